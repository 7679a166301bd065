// The disk caches' shared entry (util/cache_entry.h), CPU only: an entry round trips
// exactly (FLOAT) or to half precision (HALF), key.txt reads as documented, every way an
// entry can be wrong is refused with a reason that says which, a left-over temporary
// folder is never taken for an entry, and loadOrMake's flow (hit, miss, forced, refused,
// not saved). The caches built on it have their own tests (test_table_cache.cpp,
// test_continents.cpp). Tier (d) of STYLE habit 9.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <glm/vec4.hpp>

#include "test_util.h"
#include "util/cache_entry.h"
#include "util/file_util.h"

namespace fs = std::filesystem;
using namespace planet;
using test::contains;

namespace {

const CacheFormat kFormat{"test entry", "planet cache entry test", "planetTestKey", CachePixel::Float, false};
const std::string kKey = "0123456789abcdef";

// An entry's data: a 4-channel image of 5 x 3 texels and a 1-channel one of 4 x 2.
struct Data {
    std::vector<glm::vec4> rgba = std::vector<glm::vec4>(15);
    std::vector<float> mono = std::vector<float>(8);

    static Data sample() {
        Data d;
        for (std::size_t i = 0; i < d.rgba.size(); ++i)
            d.rgba[i] = glm::vec4(0.1f * i, -1.0f / (1.0f + i), 1e-30f * i, 3e30f);
        for (std::size_t i = 0; i < d.mono.size(); ++i) d.mono[i] = std::sqrt(2.0f + i);
        return d;
    }
    std::vector<CacheImage> images() {
        return {{"rgba.exr", 5, 3, interleavedChannels(&rgba.data()->x, {"R", "G", "B", "A"})},
                {"mono.exr", 4, 2, {{"Y", mono.data(), sizeof(float)}}}};
    }
};

const CacheFields kFields{{"version", "3"}, {"size", "5"}, {"note", "kept, not checked"}};
const CacheFields kChecked{{"version", "3"}, {"size", "5"}};

class CacheEntry : public ::testing::Test {
protected:
    void SetUp() override {
        root = fs::path(PLANET_TEST_OUT) / "cache_entry" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(root);
        entry = root / kKey;
    }
    void write(Data data = Data::sample(), const fs::path& dir = {}) {
        writeCacheEntry(dir.empty() ? entry : dir, kFormat, kKey, kFields, data.images());
    }
    // The reason the entry is refused ("" when it is read).
    std::string refusal(const CacheFields& checked = kChecked, const std::string& key = kKey) {
        Data into;
        std::string reason;
        if (readCacheEntry(entry, kFormat, key, checked, into.images(), &reason)) return {};
        EXPECT_FALSE(reason.empty());
        return reason;
    }
    // Rewrites key.txt's checksum of `file` to match its current bytes.
    void forgeChecksum(const std::string& file) {
        std::istringstream in(readFile(entry / "key.txt"));
        std::string out, line;
        while (std::getline(in, line))
            out += (line.starts_with(file + " ") ? file + " " + checksum(readFile(entry / file)) : line) + "\n";
        writeFileAtomic(entry / "key.txt", out);
    }
    fs::path root, entry;
};

}  // namespace

TEST_F(CacheEntry, RoundTripsExactlyWithKeyFileAsDocumented) {
    const Data written = Data::sample();
    write(written);
    Data read;
    std::string reason;
    ASSERT_TRUE(readCacheEntry(entry, kFormat, kKey, kChecked, read.images(), &reason)) << reason;
    EXPECT_EQ(read.rgba, written.rgba);
    EXPECT_EQ(read.mono, written.mono);

    // key.txt: the comment, the key, the fields in order, one checksum per image.
    const std::string text = readFile(entry / "key.txt");
    EXPECT_EQ(text, "# planet cache entry test\nkey " + kKey + "\nversion 3\nsize 5\nnote kept, not checked\n" +
                        "rgba.exr " + checksum(readFile(entry / "rgba.exr")) + "\nmono.exr " +
                        checksum(readFile(entry / "mono.exr")) + "\n");
    EXPECT_EQ(parseKeyFile(text).at("note"), "kept, not checked");

    // Writing again replaces the entry and leaves nothing else beside it.
    Data other = Data::sample();
    other.mono[3] = -7.0f;
    write(other);
    ASSERT_TRUE(readCacheEntry(entry, kFormat, kKey, kChecked, read.images(), &reason)) << reason;
    EXPECT_EQ(read.mono[3], -7.0f);
    EXPECT_EQ(std::distance(fs::directory_iterator(root), fs::directory_iterator()), 1);
}

TEST_F(CacheEntry, HalfChannelsRoundTripToHalfPrecision) {
    CacheFormat half = kFormat;
    half.pixel = CachePixel::Half;
    half.compress = true;
    std::vector<float> values{0.0f, -1.0f, 0.5f, 1.0f / 3.0f, 1000.0f, 6.1035156e-05f};
    writeCacheEntry(entry, half, kKey, {}, {{"h.exr", 3, 2, {{"Y", values.data(), sizeof(float)}}}});
    std::vector<float> read(values.size(), 99.0f);
    std::string reason;
    ASSERT_TRUE(readCacheEntry(entry, half, kKey, {}, {{"h.exr", 3, 2, {{"Y", read.data(), sizeof(float)}}}}, &reason))
        << reason;
    for (std::size_t i = 0; i < values.size(); ++i) EXPECT_NEAR(read[i], values[i], std::abs(values[i]) / 1024.0f);
    EXPECT_EQ(read[0], 0.0f);
    EXPECT_EQ(read[1], -1.0f);
    // A FLOAT reader refuses HALF channels rather than converting them.
    EXPECT_FALSE(readCacheEntry(entry, kFormat, kKey, {}, {{"h.exr", 3, 2, {{"Y", read.data(), sizeof(float)}}}},
                                &reason));
    EXPECT_TRUE(contains(reason, "not FLOAT")) << reason;
}

TEST_F(CacheEntry, AChecksumMismatchIsRefusedNamingTheFile) {
    write();
    std::string bytes = readFile(entry / "mono.exr");
    bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x5a);
    writeFileAtomic(entry / "mono.exr", bytes);
    const std::string why = refusal();
    EXPECT_TRUE(contains(why, "mono.exr")) << why;
    EXPECT_TRUE(contains(why, "damaged (checksum " + checksum(bytes))) << why;
}

TEST_F(CacheEntry, MissingFolderKeyFileOrImageIsRefused) {
    EXPECT_TRUE(contains(refusal(), "no cache folder")) << refusal();
    write();
    fs::remove(entry / "rgba.exr");
    EXPECT_TRUE(contains(refusal(), "rgba.exr")) << refusal();
    write();
    fs::remove(entry / "key.txt");
    EXPECT_TRUE(contains(refusal(), "key.txt")) << refusal();
    // key.txt without the image's checksum line.
    write();
    std::string text = readFile(entry / "key.txt");
    text = text.substr(0, text.find("mono.exr "));
    writeFileAtomic(entry / "key.txt", text);
    EXPECT_TRUE(contains(refusal(), "no checksum for mono.exr")) << refusal();
}

TEST_F(CacheEntry, AnotherKeyVersionOrSizeIsRefusedNamingTheField) {
    write();
    EXPECT_TRUE(contains(refusal(kChecked, "fedcba9876543210"), "holds key " + kKey + ", expected fedcba9876543210"));
    EXPECT_TRUE(contains(refusal({{"version", "4"}}), "holds version '3', expected '4'")) << refusal({{"version", "4"}});
    EXPECT_TRUE(contains(refusal({{"size", "6"}}), "holds size '5', expected '6'")) << refusal({{"size", "6"}});
    EXPECT_TRUE(contains(refusal({{"missing", "1"}}), "holds missing '', expected '1'"));
    EXPECT_EQ(refusal(), "");  // the fields it holds: read
}

TEST_F(CacheEntry, AFileOpenExrCannotReadOrOfAnotherEntryIsRefused) {
    write();
    writeFileAtomic(entry / "rgba.exr", "not an exr");
    forgeChecksum("rgba.exr");  // the checksum matches: only the decoder can tell
    EXPECT_TRUE(contains(refusal(), "OpenEXR cannot read it")) << refusal();

    // An image copied from an entry of another key carries that key in its header.
    const fs::path other = root / "other";
    writeCacheEntry(other, kFormat, "00000000000000aa", kFields, Data::sample().images());
    write();
    fs::copy_file(other / "mono.exr", entry / "mono.exr", fs::copy_options::overwrite_existing);
    forgeChecksum("mono.exr");
    EXPECT_TRUE(contains(refusal(), "header key 00000000000000aa")) << refusal();

    // Read as another size or with a channel the file does not have.
    write();
    std::string reason;
    std::vector<float> small(4);
    EXPECT_FALSE(readCacheEntry(entry, kFormat, kKey, {}, {{"mono.exr", 2, 2, {{"Y", small.data(), 4}}}}, &reason));
    EXPECT_TRUE(contains(reason, "size 4x2, expected 2x2")) << reason;
    std::vector<float> mono(8);
    EXPECT_FALSE(readCacheEntry(entry, kFormat, kKey, {}, {{"mono.exr", 4, 2, {{"Z", mono.data(), 4}}}}, &reason));
    EXPECT_TRUE(contains(reason, "no channel Z")) << reason;
}

TEST_F(CacheEntry, NanOrInfIsRefused) {
    for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        Data data = Data::sample();
        data.rgba[7].z = bad;
        write(data);
        const std::string why = refusal();
        EXPECT_TRUE(contains(why, "rgba.exr")) << why;
        EXPECT_TRUE(contains(why, "texel 7 channel B is not finite")) << why;
    }
}

TEST_F(CacheEntry, AStaleTemporaryFolderIsNotTakenForAnEntry) {
    // A writer that died after writing everything but before the rename leaves <key>.tmp<pid>.
    const fs::path stale = root / (kKey + ".tmp999999");
    write(Data::sample(), stale);  // a complete entry, under the temporary name
    ASSERT_TRUE(fs::exists(stale / "key.txt"));
    EXPECT_TRUE(contains(refusal(), "no cache folder")) << refusal();
    // Our own temporary folder from an earlier run of this process id is cleared, not reused.
    const fs::path own = root / (kKey + ".tmp" + std::to_string(::getpid()));
    fs::create_directories(own);
    writeFileAtomic(own / "junk.exr", "junk");
    write();
    EXPECT_EQ(refusal(), "");
    EXPECT_FALSE(fs::exists(own));
    EXPECT_FALSE(fs::exists(entry / "junk.exr"));
}

TEST_F(CacheEntry, AFolderWhereAFileShouldBeIsRefusedAndHealedByTheNextWrite) {
    // A folder opens as a stream on Linux with a size of 2^63: this was std::bad_alloc, and
    // every later run stopped on it.
    for (const std::string file : {"key.txt", "rgba.exr"}) {
        write();
        fs::remove(entry / file);
        fs::create_directories(entry / file / "inside");
        EXPECT_TRUE(contains(refusal(), file) && contains(refusal(), "folder")) << refusal();
        write();  // what loadOrMake does after a refusal
        EXPECT_EQ(refusal(), "") << file;
        EXPECT_TRUE(fs::is_regular_file(entry / file));
    }
}

TEST_F(CacheEntry, WritingAnEntryClearsWhatDeadWritersLeft) {
    fs::create_directories(root);
    // A process id that is not running (beyond Linux's pid_max), another that is (ours, as a
    // neighbour writer would be), and a running one's folder older than a day.
    const fs::path dead = root / "aaaa.tmp99999999", deadOld = root / "bbbb.old99999999";
    const fs::path live = root / ("cccc.tmp" + std::to_string(::getppid()));
    const fs::path ancient = root / ("dddd.tmp" + std::to_string(::getppid()));
    for (const fs::path& p : {dead, deadOld, live, ancient}) fs::create_directories(p / "x");
    writeFileAtomic(dead / "half.exr", "half");
    fs::last_write_time(ancient, fs::file_time_type::clock::now() - std::chrono::hours(25));
    write();
    EXPECT_FALSE(fs::exists(dead));
    EXPECT_FALSE(fs::exists(deadOld));
    EXPECT_TRUE(fs::exists(live));  // it may be writing now
    EXPECT_FALSE(fs::exists(ancient));  // its process id came back for another program
    EXPECT_EQ(refusal(), "");
}

TEST_F(CacheEntry, AFailedWriteLeavesNothingBehind) {
    Data data = Data::sample();
    std::vector<CacheImage> images = data.images();
    images[1].width = 0;  // OpenEXR refuses an empty data window
    EXPECT_THROW(writeCacheEntry(entry, kFormat, kKey, kFields, images), FileError);
    EXPECT_FALSE(fs::exists(entry));
    EXPECT_TRUE(!fs::exists(root) || fs::is_empty(root));
}

// ---------------------------------------------------------------- loadOrMake

TEST(CacheLoadOrMake, LoadsOrMakesAndSavesAndSaysWhat) {
    const fs::path dir = fs::path(PLANET_TEST_OUT) / "cache_load_or_make";
    fs::remove_all(dir);
    std::optional<int> stored;  // the "entry"
    int made = 0, toldBeforeMaking = 0;
    auto load = [&](std::string* reason) -> std::optional<int> {
        if (!stored) *reason = "nothing stored";
        return stored;
    };
    auto make = [&] { return 40 + ++made; };
    auto save = [&](int v) {
        if (v == 43) throw FileError("disk full");
        stored = v;
        fs::create_directories(dir);
    };
    auto onMake = [&](const CacheOutcome& o) {
        ++toldBeforeMaking;
        EXPECT_FALSE(o.hit);
        EXPECT_EQ(made, toldBeforeMaking - 1);  // before make()
    };
    CacheOutcome o;

    EXPECT_EQ(loadOrMake(dir, false, load, make, save, onMake, &o), 41);  // nothing there: made, saved
    EXPECT_FALSE(o.hit);
    EXPECT_EQ(o.rejected, "");  // no folder: nothing refused
    EXPECT_EQ(o.dir, dir);
    EXPECT_GE(o.seconds, 0.0);
    EXPECT_EQ(o.notSaved, "");

    EXPECT_EQ(loadOrMake(dir, false, load, make, save, onMake, &o), 41);  // a hit: not made again
    EXPECT_TRUE(o.hit);
    EXPECT_EQ(made, 1);
    EXPECT_EQ(toldBeforeMaking, 1);

    EXPECT_EQ(loadOrMake(dir, true, load, make, save, onMake, &o), 42);  // forced
    EXPECT_TRUE(o.forced);
    EXPECT_EQ(o.rejected, "");

    stored.reset();  // the folder is there, the entry refused
    EXPECT_EQ(loadOrMake(dir, false, load, make, save, onMake, &o), 43);
    EXPECT_EQ(o.rejected, "nothing stored");
    EXPECT_EQ(o.notSaved, "disk full");  // returned anyway; the caller decides
    EXPECT_FALSE(stored);
    EXPECT_EQ(toldBeforeMaking, 3);
}
