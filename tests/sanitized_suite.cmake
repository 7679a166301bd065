# The sanitizer build's checks, run by this build's CTest (included from CMakeLists.txt when
# PLANET_SANITIZED_BUILD names a PLANET_FUZZ build folder; scripts/test.sh builds
# build-sanitize/ with scripts/build_sanitize.sh and sets it):
#   sanitized.unit_tests.N   planet_tests under ASan + UBSan, the suites that need no GL, in shards
#   fuzz.NAME                each libFuzzer target for PLANET_FUZZ_SECONDS from fuzz/corpus/NAME
# Each fails naming the missing binary when that folder has not been built. A high COST makes
# CTest start them first, so that they run beside the main suite rather than after it.
set(PLANET_SANITIZED_SHARDS 2 CACHE STRING "Shards of the sanitized unit tests (CTest runs them in parallel)")
set(PLANET_FUZZ_SECONDS 25 CACHE STRING "Seconds each fuzz target runs in CTest")
get_filename_component(PLANET_SANITIZED_DIR "${PLANET_SANITIZED_BUILD}" ABSOLUTE BASE_DIR "${CMAKE_SOURCE_DIR}")

math(EXPR last_shard "${PLANET_SANITIZED_SHARDS} - 1")
foreach(shard RANGE ${last_shard})
  add_test(NAME sanitized.unit_tests.${shard}
           COMMAND bash ${CMAKE_SOURCE_DIR}/tests/run_sanitized.sh ${PLANET_SANITIZED_DIR} ${shard} ${PLANET_SANITIZED_SHARDS})
  set_tests_properties(sanitized.unit_tests.${shard} PROPERTIES COST 100000 TIMEOUT 1200)
endforeach()

foreach(name ${PLANET_FUZZ_TARGETS})
  add_test(NAME fuzz.${name}
           COMMAND bash ${CMAKE_SOURCE_DIR}/fuzz/run_fuzzer.sh ${PLANET_SANITIZED_DIR} ${name} ${PLANET_FUZZ_SECONDS})
  math(EXPR fuzz_timeout "${PLANET_FUZZ_SECONDS} * 3 + 60")  # loading the corpus, a slow machine
  set_tests_properties(fuzz.${name} PROPERTIES COST 50000 TIMEOUT ${fuzz_timeout})
endforeach()
