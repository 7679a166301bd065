#!/usr/bin/env bash
# Our frame side by side with Eric Bruneton's own demo (issue 15, "What must hold"), on
# this machine, in one run:
#
#   bash scripts/bruneton_demo_bench.sh DEMO_REPO
#
# DEMO_REPO is a local copy of github.com/ebruneton/precomputed_atmospheric_scattering:
# a clone or extract (a folder holding atmosphere/demo/), or a bare git mirror (its HEAD is
# exported with `git archive`). Nothing is downloaded.
#
# 1. The demo (atmosphere/demo/*.cc, atmosphere/model.cc, text/*.cc,
#    external/glad/src/glad.cc; the Makefile's `demo` target, with its .glsl -> .glsl.inc
#    step) is built into $OUT/demo after a small patch (below, as a here-doc) that makes it
#    time its frames: for each view of DEMO_VIEWS, DEMO_WARMUP frames, then DEMO_FRAMES
#    frames each ended by glFinish() and timed with steady_clock from the start of the
#    display callback (the swap to the X server after it is not timed: our bench renders
#    off screen), the median printed, then the next view, then exit. The patch also prints
#    glGetString(GL_RENDERER), hides the help text (not part of the scene), takes the
#    window size from DEMO_WIDTH x DEMO_HEIGHT and the vertical field of view per view (the
#    demo's is fixed at 50 deg), and writes each view's last frame as $OUT/round1/<view>.ppm
#    (round 1 only) for a look at what was timed. The demo precomputes its tables (about
#    2.5 minutes on two llvmpipe cores) before the first frame: outside the timed frames, but
#    once per round, hence one demo process for all three views.
# 2. It runs under `xvfb-run -s "-screen 0 WxHx24"` with LIBGL_ALWAYS_SOFTWARE=1 (Mesa's
#    llvmpipe, checked: the script stops if GL_RENDERER does not name llvmpipe, unless
#    ALLOW_ANY_RENDERER=1).
# 3. Our side: `planet bench --views assets/views/{ground,orbit,space}.toml --size SIZE
#    --tables full --frames FRAMES --warmup WARMUP`, with the earth preset as it ships
#    (clouds on, the temporal march: passes `sky march` + `sky temporal` + `sky refine`) and with a copy of
#    it without clouds ($OUT/earth_no_clouds.toml: `[clouds] enabled = false`, every other
#    key the earth preset's default; written here rather than under assets/presets/, whose
#    list of presets the tests pin): there the air alone is marched in every pixel every
#    frame by one full-rate `sky` pass, what the demo does per pixel.
# 4. ROUNDS rounds (default 3), interleaved: demo, ours, ours without clouds, demo, ...;
#    the figures are medians over the rounds (each round's figure a median over its frames).
#
# The views. The demo's scene is a 1 km sphere standing on the ground of a 6360 km planet
# (the same radius and atmosphere height as our earth preset); its camera sits at distance
# l from the sphere's foot (the world origin on the ground) at zenith angle z and always
# looks at that foot; the sun is given by its zenith and azimuth angles in the frame of
# the foot. For each of our views this script picks l and z so that the camera is at our
# view's altitude above the ground and looks down by our view's pitch (the ray through
# the centre of the image hits the ground at the foot), puts the sun at our view's sun
# elevation and at its azimuth relative to our heading, in the camera's own local frame
# (the camera is up to 17 deg of arc away from the foot), and uses our field of view:
#   ground: 2 m up, pitch 0, fov 60, sun 40 deg up and 80 deg right. A level view never
#           meets the ground, so the demo's own distance, l = 9 km, is kept: the camera at
#           2 m looks down by 0.05 deg, the sphere (13 deg across) in the middle of the
#           image. Our camera stands on terrain 430 m above sea level, the demo's on the sea
#           level ground; there is no terrain, no sea and no cloud in the demo.
#   orbit:  400 km up, pitch -20 (just below the 19.8 deg dip of the horizon), fov 60, sun
#           60 deg up and 90 deg right: l = 2000 km, z = 87.2 deg. The sphere is sub-pixel.
#   space:  30 000 km up, looking straight down, fov 30, sun 30 deg up and 90 deg right
#           (north up): l = 30 000 km, z = 0.
# What cannot match: the demo shades every pixel with the same branches whatever it sees
# (sphere, ground, sky: it has no geometry but a full-screen quad), with its tables in half
# floats (ours are 32-bit floats, the same sizes: scattering 256x128x32, transmittance
# 256x64, irradiance 64x16); its ground is a sphere of one albedo, ours a tessellated
# terrain, an ocean and clouds; its exposure and tone mapping are its own.
#
# Our passes on llvmpipe: the bench is run with --finish-each-pass on (its default on a
# software renderer), which waits for the GPU before and after each pass, so a pass's CPU +
# wait is its own work: its submitting (the vertex and tessellation stages run there, in the
# draw call) and its fragments, rasterized by llvmpipe's threads. (Before that option existed
# a pass's fragments were waited for by the next pass, and this script attributed them so;
# its summaries of 2026-12-03 were made that way.) The passes sum to the bench's frame row, the
# sum over the passes of CPU + wait, which leaves out the history copies after the last pass.
# GPU timestamps are coarse on llvmpipe in general and are shown beside them.
#
# Options (environment): ROUNDS (3), SIZE (1280x720), TABLES (full), FRAMES (5) and
# WARMUP (2) for ours (a 1280x720 frame takes seconds on two cores; WARMUP must be at
# least 2 with the temporal march: its first frame after a view change is a full-rate one
# and the second compiles the sparse passes' shaders), DEMO_FRAMES (5), DEMO_WARMUP (2),
# VIEWS ("ground orbit space"; others are not matched), OUT (out/bruneton_demo_bench),
# PLANET (./build/planet), ROOT (planet --root: shaders and assets from elsewhere; with
# PLANET, a snapshot that edits in the checkout cannot reach during the run), SUMMARY_ONLY=1
# (print the tables again from $OUT's rounds, with the same settings; nothing is run).
# Needs g++, freeglut (freeglut3-dev), libGL, xvfb-run.
# Prints per-round figures and the tables; results and logs under $OUT. Whole run at the
# defaults: about 15-25 minutes on two llvmpipe cores. Recorded in docs/PERFORMANCE.md.
set -euo pipefail
[ $# -eq 1 ] || { sed -n '2,10p' "$0" >&2; exit 2; }
demo_repo=$(cd "$1" 2>/dev/null && pwd) || { echo "bruneton_demo_bench.sh: no folder $1" >&2; exit 2; }
cd "$(dirname "$0")/.."
planet=${PLANET:-./build/planet}
rounds=${ROUNDS:-3}
size=${SIZE:-1280x720}
width=${size%x*}
height=${size#*x}
tables=${TABLES:-full}
frames=${FRAMES:-5}
warmup=${WARMUP:-2}
demo_frames=${DEMO_FRAMES:-5}
demo_warmup=${DEMO_WARMUP:-2}
views=${VIEWS:-"ground orbit space"}
out=${OUT:-out/bruneton_demo_bench}
root_option=()
[ -z "${ROOT:-}" ] || root_option=(--root "$ROOT")
[ -x "$planet" ] || { echo "bruneton_demo_bench.sh: no $planet (build first: cmake --build build)" >&2; exit 1; }
mkdir -p "$out"
out=$(cd "$out" && pwd)

# The bench CSV's rows without the header and the first column (the renderer, quoted: it
# holds commas): width,height,view,pass,frames,gpu_median_ms,gpu_p95_ms,cpu_median_ms,
# cpu_p95_ms,cloud_steps_per_pixel,cloud_skipped_share,wait_median_ms,wait_p95_ms
bench_rows() { sed -E -e '1d' -e 's/^("[^"]*"|[^,]*),//' "$1"; }

# --- the tables --------------------------------------------------------------------------
summarize() {
    {
        for round in $(seq 1 "$rounds"); do
            awk -v r="$round" '$1 == "DEMO_MEDIAN_MS" { print r ",demo," $2 ",frame,0,0,0," $3 }' "$out/round$round/demo.log"
            for variant in ours clear; do  # round,variant,view,pass,cpu,wait,gpu
                bench_rows "$out/round$round/$variant.csv" |
                    awk -F, -v r="$round" -v v="$variant" '{ print r "," v "," $3 "," $4 "," $8 "," $12 "," $6 }'
            done
        done
    } > "$out/all.csv"
    awk -F, -v views="$views" -v rounds="$rounds" -v renderer="$renderer" -v size="$size" -v frames="$frames" \
        -v warmup="$warmup" -v dframes="$demo_frames" -v dwarmup="$demo_warmup" '
    function median(key,    n, i, j, t, a) {  # median over the rounds of v[key, round]
        n = 0
        for (i = 1; i <= rounds; ++i) if ((key SUBSEP i) in v) a[++n] = v[key, i]
        if (n == 0) return -1
        for (i = 2; i <= n; ++i) { t = a[i]; for (j = i - 1; j >= 1 && a[j] > t; --j) a[j + 1] = a[j]; a[j + 1] = t }
        return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
    }
    function ms(x) { return x < 0 ? "-" : sprintf("%.0f", x) }
    function ratio(a, b) { return a < 0 || b <= 0 ? "-" : sprintf("%.2f", a / b) }
    function verdict(a, b, bar) { return bar == "" ? "no bar" : (a / b <= bar ? "met" : "NOT met") }
    {
        round = $1; variant = $2; view = $3; pass = $4
        if (variant == "demo") { v["demo", view, round] = $8; next }
        cpu[variant, view, pass, round] = $5; wait[variant, view, pass, round] = $6
        v[variant, view, pass, "gpu", round] = $7
        present[variant, view, pass] = 1
        if (pass == "frame") v[variant, view, "frame", round] = $5 + $6
    }
    END {
        n_order = split("prepare,terrain,terrain shadow,surface light,ocean,terrain reflection,sea reflection,sky,sky march,sky temporal,sky refine,antialias,tonemap", order, ",")
        n_views = split(views, vs, " ")
        # attributed: the pass own CPU time + its own wait (--finish-each-pass on: each pass
        # waits for the work before it first, so its wait is its own fragments); the sum is
        # the frame cpu + wait
        for (i = 1; i <= n_views; ++i) for (var = 1; var <= 2; ++var) {
            variant = var == 1 ? "ours" : "clear"; view = vs[i]
            for (r = 1; r <= rounds; ++r) {
                for (p = 1; p <= n_order; ++p) {
                    pass = order[p]
                    if (!((variant SUBSEP view SUBSEP pass SUBSEP r) in cpu)) continue
                    v[variant, view, pass, "attr", r] = cpu[variant, view, pass, r] + wait[variant, view, pass, r]
                }
                if ((variant SUBSEP view SUBSEP "sky march" SUBSEP r) in cpu)
                    v[variant, view, "air", r] = v[variant, view, "sky march", "attr", r] + v[variant, view, "sky temporal", "attr", r] + \
                                                 v[variant, view, "sky refine", "attr", r]
                else if ((variant SUBSEP view SUBSEP "sky" SUBSEP r) in cpu)
                    v[variant, view, "air", r] = v[variant, view, "sky", "attr", r]
            }
        }
        printf "\nBruneton demo against planet bench, %s, %s; medians of %d interleaved rounds (demo: %d frames after %d warm-up; ours: %d after %d)\n", \
            renderer, size, rounds, dframes, dwarmup, frames, warmup
        printf "ms. ours: the earth preset (clouds, temporal march); clear: the same without clouds (the air marched at full rate).\n"
        printf "Our frame = cpu + wait summed over the passes; a pass = its own cpu + wait (--finish-each-pass on; see the script).\n"
        printf "Bars (issue 15): frame <= 1.5x the demo frame for orbit and space, <= 2x for ground; atmosphere pass <= 0.7x (orbit, space).\n\n"
        printf "| view | demo frame | our frame | / demo | bar | | clear frame | / demo | our sky passes (air + clouds) | / demo | clear sky pass (air alone) | / demo | bar | |\n"
        printf "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n"
        for (i = 1; i <= n_views; ++i) {
            view = vs[i]
            d = median("demo" SUBSEP view); f = median("ours" SUBSEP view SUBSEP "frame")
            air = median("ours" SUBSEP view SUBSEP "air"); cf = median("clear" SUBSEP view SUBSEP "frame")
            cair = median("clear" SUBSEP view SUBSEP "air")
            fbar = view == "ground" ? 2 : 1.5; abar = view == "ground" ? "" : 0.7
            printf "| %s | %s | %s | %s | <= %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", view, ms(d), ms(f), ratio(f, d), \
                fbar, verdict(f, d, fbar), ms(cf), ratio(cf, d), ms(air), ratio(air, d), ms(cair), ratio(cair, d), \
                abar == "" ? "-" : "<= " abar, abar == "" ? "no bar" : verdict(air, d, abar) " / " verdict(cair, d, abar)
        }
        printf "\nWhere our frame goes (ms, attributed, medians over the rounds; sky: sky march + sky temporal + sky refine, or the full-rate sky)\n\n"
        printf "| view | variant | terrain | terrain shadow | surface light | ocean | terrain reflection | sea reflection | sky | tonemap | frame | demo frame |\n"
        printf "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n"
        for (i = 1; i <= n_views; ++i) for (var = 1; var <= 2; ++var) {
            variant = var == 1 ? "ours" : "clear"; view = vs[i]; k = variant SUBSEP view SUBSEP
            printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", view, variant, ms(median(k "terrain" SUBSEP "attr")), \
                ms(median(k "terrain shadow" SUBSEP "attr")), ms(median(k "surface light" SUBSEP "attr")), ms(median(k "ocean" SUBSEP "attr")), \
                ms(median(k "terrain reflection" SUBSEP "attr")), ms(median(k "sea reflection" SUBSEP "attr")), ms(median(k "air")), \
                ms(median(k "tonemap" SUBSEP "attr")), ms(median(k "frame")), ms(median("demo" SUBSEP view))
        }
        printf "\nPer pass (ms, medians over the rounds): cpu / wait / attributed / gpu timestamps\n\n"
        printf "| view | variant | pass | cpu | wait | attributed | gpu |\n| --- | --- | --- | --- | --- | --- | --- |\n"
        for (i = 1; i <= n_views; ++i) for (var = 1; var <= 2; ++var) {
            variant = var == 1 ? "ours" : "clear"; view = vs[i]
            for (p = 1; p <= n_order + 1; ++p) {
                pass = p <= n_order ? order[p] : "frame"
                if (!((variant SUBSEP view SUBSEP pass) in present)) continue
                for (r = 1; r <= rounds; ++r) {
                    delete v["c", r]; delete v["w", r]
                    if ((variant SUBSEP view SUBSEP pass SUBSEP r) in cpu) {
                        v["c", r] = cpu[variant, view, pass, r]; v["w", r] = wait[variant, view, pass, r]
                    }
                }
                printf "| %s | %s | %s | %.1f | %.1f | %s | %s |\n", view, variant, pass, median("c"), median("w"), \
                    pass == "frame" ? ms(median(variant SUBSEP view SUBSEP "frame")) : ms(median(variant SUBSEP view SUBSEP pass SUBSEP "attr")), \
                    ms(median(variant SUBSEP view SUBSEP pass SUBSEP "gpu"))
            }
        }
        printf "\nPer round (ms): demo frame / our frame / clear frame\n"
        for (i = 1; i <= n_views; ++i) {
            view = vs[i]; printf "  %-7s", view
            for (r = 1; r <= rounds; ++r) printf "  round %d: %s / %s / %s", r, ms(v["demo", view, r]), ms(v["ours", view, "frame", r]), ms(v["clear", view, "frame", r])
            printf "\n"
        }
    }' "$out/all.csv" | tee "$out/summary.md"
    echo "results in $out/ (summary.md, all.csv, round*/: logs, CSVs, round1/*.ppm: the demo's frames)" >&2
}

# --- the views, matched (see the top) ----------------------------------------------------
# match NAME ALTITUDE_KM PITCH_DEG SUN_ELEVATION_DEG SUN_AZIMUTH_FROM_HEADING_DEG FOV_DEG [DISTANCE_KM]
# prints "NAME:distance_m,view_zenith,view_azimuth,sun_zenith,sun_azimuth,fov_deg" and,
# on stderr, what it matched.
match() {
    awk -v name="$1" -v h="$2" -v pitch="$3" -v e="$4" -v phi="$5" -v fov="$6" -v l="${7:-}" 'BEGIN {
        R = 6360; d = atan2(0, -1) / 180; P = R + h
        if (l == "") {  # the near root of |camera + t v| = R with the view ray v pitched down
            s = sin(-pitch * d)
            l = s * P - sqrt(s * s * P * P - (P * P - R * R))
        }
        c = (P * P - R * R - l * l) / (2 * l * R); if (c > 1) c = 1; if (c < -1) c = -1
        z = atan2(sqrt(1 - c * c), c)
        theta = atan2(l * sin(z), R + l * c)   # arc between the camera and the foot
        # the camera frame (view azimuth 0): forward (-cos theta, 0, sin theta), right
        # (0, 1, 0), up (sin theta, 0, cos theta)
        sx = cos(e * d) * cos(phi * d) * -cos(theta) + sin(e * d) * sin(theta)
        sy = cos(e * d) * sin(phi * d)
        sz = cos(e * d) * cos(phi * d) * sin(theta) + sin(e * d) * cos(theta)
        sun_zenith = atan2(sqrt(sx * sx + sy * sy), sz); sun_azimuth = atan2(sy, sx)
        got_pitch = atan2(-(l + R * c) / P, sqrt(1 - ((l + R * c) / P) ^ 2)) / d
        printf "%s:%.6g,%.6f,0,%.6f,%.6f,%g", name, l * 1000, z, sun_zenith, sun_azimuth, fov
        printf "demo view %-7s camera %.4g km up, distance %.6g km, view zenith %.4f rad (%.2f deg), pitch %.3f deg, sun zenith %.4f rad, azimuth %.4f rad, fov %g deg\n", \
            name, h, l, z, z / d, got_pitch, sun_zenith, sun_azimuth, fov > "/dev/stderr"
    }'
}
demo_views=""
bench_views=()
for view in $views; do
    case $view in
        ground) m=$(match ground 0.002 0 40 80 60 9) ;;      # heading 60, sun azimuth 140
        orbit) m=$(match orbit 400 -20 60 90 60) ;;          # heading 90, sun azimuth 180
        space) m=$(match space 30000 -90 30 90 30) ;;        # heading 0, sun azimuth 90
        *) echo "bruneton_demo_bench.sh: no demo match for the view $view" >&2; exit 2 ;;
    esac
    demo_views="${demo_views:+$demo_views;}$m"
    bench_views+=("${ROOT:-.}/assets/views/$view.toml")
done
printf 'name = "Earth without clouds"\ndescription = "The earth preset with [clouds] off (bruneton_demo_bench.sh)"\n[clouds]\nenabled = false\n' \
    > "$out/earth_no_clouds.toml"

if [ "${SUMMARY_ONLY:-0}" = 1 ]; then  # the tables again from $OUT's rounds, nothing run
    renderer=$(sed -n 's/^GL_RENDERER: //p' "$out/round1/demo.log")
    summarize
    exit 0
fi

# --- 1. the demo's sources, patched, built ---------------------------------------------
src="$out/demo"
rm -rf "$src"
mkdir -p "$src"
if [ -d "$demo_repo/atmosphere/demo" ]; then
    cp -r "$demo_repo/atmosphere" "$demo_repo/text" "$demo_repo/external" "$src/"
    revision=$(git -C "$demo_repo" rev-parse HEAD 2>/dev/null || echo "unknown revision")
elif git --git-dir="$demo_repo" rev-parse --verify -q HEAD >/dev/null; then
    git --git-dir="$demo_repo" archive HEAD atmosphere text external | tar -x -C "$src"
    revision=$(git --git-dir="$demo_repo" rev-parse HEAD)
else
    echo "bruneton_demo_bench.sh: $demo_repo holds neither atmosphere/demo/ nor a git repository" >&2
    exit 1
fi
echo "== the demo: $demo_repo ($revision), built in $src" >&2
# The patch: timing, views and window size from the environment, renderer string, no help
# text, a PPM of each view's last frame (see the top of this script).
patch -s -p1 -d "$src" <<'PATCH'
--- a/atmosphere/demo/demo.cc
+++ b/atmosphere/demo/demo.cc
@@ -50,6 +50,36 @@
 #include <string>
 #include <vector>
 
+// Timing patch (planet's scripts/bruneton_demo_bench.sh): DEMO_VIEWS =
+// "name:distance_m,view_zenith,view_azimuth,sun_zenith,sun_azimuth,fov_deg;..."
+// (radians but the fov); each view gets DEMO_WARMUP frames, then DEMO_FRAMES
+// frames each ended by glFinish(), timed with steady_clock; prints the median.
+#include <chrono>
+#include <cstdio>
+#include <cstdlib>
+struct BenchView { std::string name; double v[6]; };
+static std::vector<BenchView> BenchViews() {
+  std::vector<BenchView> views;
+  const char* env = std::getenv("DEMO_VIEWS");
+  std::stringstream list(env ? env : "");
+  std::string item, number;
+  while (std::getline(list, item, ';')) {
+    BenchView view = {item.substr(0, item.find(':')),
+                      {9000.0, 1.47, -0.1, 1.3, 2.9, 50.0}};
+    std::stringstream numbers(item.substr(item.find(':') + 1));
+    for (int i = 0; i < 6 && std::getline(numbers, number, ','); ++i)
+      view.v[i] = std::atof(number.c_str());
+    views.push_back(view);
+  }
+  if (views.empty()) views.push_back({"default", {9000.0, 1.47, -0.1, 1.3, 2.9, 50.0}});
+  return views;
+}
+static int EnvInt(const char* name, int fallback) {
+  const char* v = std::getenv(name);
+  return v && *v ? std::atoi(v) : fallback;
+}
+static double g_fov_deg = 50.0;
+
 namespace atmosphere {
 namespace demo {
 
@@ -106,7 +136,7 @@
     use_half_precision_(true),
     use_luminance_(NONE),
     do_white_balance_(false),
-    show_help_(true),
+    show_help_(false),
     program_(0),
     view_distance_meters_(9000.0),
     view_zenith_angle_radians_(1.47),
@@ -120,6 +150,10 @@
   if (!gladLoadGL()) {
     throw std::runtime_error("GLAD initialization failed");
   }
+  std::printf("GL_RENDERER: %s\nGL_VERSION: %s\n",
+      reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
+      reinterpret_cast<const char*>(glGetString(GL_VERSION)));
+  std::fflush(stdout);
   if (!GLAD_GL_VERSION_3_3) {
     throw std::runtime_error("OpenGL 3.3 or higher is required");
   }
@@ -355,6 +389,20 @@
 */
 
 void Demo::HandleRedisplayEvent() const {
+  static const std::vector<BenchView> views = BenchViews();
+  static size_t view_index = 0;
+  static int frame = 0;
+  static std::vector<double> times_ms;
+  const BenchView& view = views[view_index];
+  if (frame == 0) {
+    Demo* self = const_cast<Demo*>(this);
+    self->SetView(view.v[0], view.v[1], view.v[2], view.v[3], view.v[4],
+        exposure_);
+    g_fov_deg = view.v[5];
+    self->HandleReshapeEvent(
+        glutGet(GLUT_WINDOW_WIDTH), glutGet(GLUT_WINDOW_HEIGHT));
+  }
+  const auto frame_start = std::chrono::steady_clock::now();
   // Unit vectors of the camera frame, expressed in world space.
   float cos_z = cos(view_zenith_angle_radians_);
   float sin_z = sin(view_zenith_angle_radians_);
@@ -415,6 +463,37 @@
     text_renderer_->DrawText(help.str(), 5, 4);
   }
 
+  glFinish();
+  const double ms = std::chrono::duration<double, std::milli>(
+      std::chrono::steady_clock::now() - frame_start).count();
+  const int warmup = EnvInt("DEMO_WARMUP", 2);
+  std::printf("%s frame %d: %.1f ms (%dx%d)%s\n", view.name.c_str(), frame,
+      ms, glutGet(GLUT_WINDOW_WIDTH), glutGet(GLUT_WINDOW_HEIGHT),
+      frame < warmup ? " warm-up" : "");
+  if (++frame > warmup) times_ms.push_back(ms);
+  if (static_cast<int>(times_ms.size()) >= EnvInt("DEMO_FRAMES", 5)) {
+    std::sort(times_ms.begin(), times_ms.end());
+    const size_t n = times_ms.size();
+    std::printf("DEMO_MEDIAN_MS %s %.2f (%zu frames after %d warm-up)\n",
+        view.name.c_str(), n % 2 ? times_ms[n / 2]
+            : 0.5 * (times_ms[n / 2 - 1] + times_ms[n / 2]), n, warmup);
+    if (const char* dir = std::getenv("DEMO_SHOT_DIR")) {  // last frame, PPM
+      const int w = glutGet(GLUT_WINDOW_WIDTH), h = glutGet(GLUT_WINDOW_HEIGHT);
+      std::vector<unsigned char> rgb(3 * w * h);
+      glPixelStorei(GL_PACK_ALIGNMENT, 1);
+      glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
+      FILE* f = std::fopen((std::string(dir) + "/" + view.name + ".ppm").c_str(), "wb");
+      if (f) {
+        std::fprintf(f, "P6\n%d %d\n255\n", w, h);
+        for (int y = h - 1; y >= 0; --y) std::fwrite(&rgb[3 * w * y], 1, 3 * w, f);
+        std::fclose(f);
+      }
+    }
+    times_ms.clear();
+    frame = 0;
+    if (++view_index == views.size()) std::exit(0);
+  }
+  std::fflush(stdout);
   glutSwapBuffers();
   glutPostRedisplay();
 }
@@ -427,7 +506,7 @@
 void Demo::HandleReshapeEvent(int viewport_width, int viewport_height) {
   glViewport(0, 0, viewport_width, viewport_height);
 
-  const float kFovY = 50.0 / 180.0 * kPi;
+  const float kFovY = g_fov_deg / 180.0 * kPi;
   const float kTanFovY = tan(kFovY / 2.0);
   float aspect_ratio = static_cast<float>(viewport_width) / viewport_height;
 
--- a/atmosphere/demo/demo_main.cc
+++ b/atmosphere/demo/demo_main.cc
@@ -38,6 +38,7 @@
 #include <glad/glad.h>
 #include <GL/freeglut.h>
 
+#include <cstdlib>
 #include <memory>
 
 using atmosphere::demo::Demo;
@@ -49,7 +50,9 @@
   glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE);
   glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_CONTINUE_EXECUTION);
 
-  std::unique_ptr<Demo> demo(new Demo(1024, 576));
+  std::unique_ptr<Demo> demo(new Demo(
+      std::getenv("DEMO_WIDTH") ? std::atoi(std::getenv("DEMO_WIDTH")) : 1024,
+      std::getenv("DEMO_HEIGHT") ? std::atoi(std::getenv("DEMO_HEIGHT")) : 576));
   glutMainLoop();
   return 0;
 }
PATCH
# The Makefile's %.glsl.inc rule: the GLSL as a raw string literal, comments and blank
# lines dropped.
for glsl in atmosphere/definitions.glsl atmosphere/functions.glsl atmosphere/demo/demo.glsl; do
    name=$(basename "$glsl" .glsl)
    sed -e "1i const char ${name}_glsl[] = R\"***(" -e '$a )***";' \
        -e '/^\/\*/,/\*\/$/d' -e '/^ *\/\//d' -e '/^$/d' "$src/$glsl" > "$src/$glsl.inc"
done
objects=()
for cc in atmosphere/demo/demo.cc atmosphere/demo/demo_main.cc atmosphere/model.cc text/text_renderer.cc \
          external/glad/src/glad.cc; do
    object="$src/$(basename "$cc" .cc).o"
    g++ -std=c++11 -O2 -DNDEBUG -I"$src" -I"$src/external" -I"$src/external/glad/include" -c "$src/$cc" -o "$object"
    objects+=("$object")
done
g++ "${objects[@]}" -pthread -ldl -lglut -lGL -o "$src/atmosphere_demo"

# --- the rounds --------------------------------------------------------------------------
for round in $(seq 1 "$rounds"); do
    dir="$out/round$round"
    mkdir -p "$dir"
    shot=()
    [ "$round" != 1 ] || shot=(DEMO_SHOT_DIR="$dir")
    echo "== round $round/$rounds: the demo ($size, its tables first); load $(cut -d' ' -f1-3 /proc/loadavg)" >&2
    xvfb-run -a -s "-screen 0 ${width}x${height}x24" env LIBGL_ALWAYS_SOFTWARE=1 DEMO_WIDTH="$width" \
        DEMO_HEIGHT="$height" DEMO_VIEWS="$demo_views" DEMO_FRAMES="$demo_frames" DEMO_WARMUP="$demo_warmup" \
        "${shot[@]}" "$src/atmosphere_demo" > "$dir/demo.log" 2>&1 || { cat "$dir/demo.log" >&2; exit 1; }
    renderer=$(sed -n 's/^GL_RENDERER: //p' "$dir/demo.log")
    echo "   demo GL_RENDERER: $renderer" >&2
    case $renderer in
        *llvmpipe*) ;;
        *) [ "${ALLOW_ANY_RENDERER:-0}" = 1 ] || { echo "bruneton_demo_bench.sh: not llvmpipe: $renderer" >&2; exit 1; } ;;
    esac
    grep '^DEMO_MEDIAN_MS' "$dir/demo.log" | sed 's/^/   /' >&2
    for variant in ours clear; do
        preset=()
        [ "$variant" = ours ] || preset=(--preset "$out/earth_no_clouds.toml")
        echo "== round $round/$rounds: planet bench, $variant; load $(cut -d' ' -f1-3 /proc/loadavg)" >&2
        "$planet" bench "${root_option[@]}" "${preset[@]}" --views "${bench_views[@]}" --size "$size" --tables "$tables" \
            --frames "$frames" --warmup "$warmup" --finish-each-pass on --csv "$dir/$variant.csv" --plot '' \
            > "$dir/$variant.log" 2>&1 ||
            { cat "$dir/$variant.log" >&2; exit 1; }
        grep -m1 '^planet bench on' "$dir/$variant.log" | sed 's/^/   /' >&2
        bench_rows "$dir/$variant.csv" | awk -F, '$4 == "frame" { printf "   %-8s frame cpu + wait %.0f ms\n", $3, $8 + $12 }' >&2
    done
done

summarize
