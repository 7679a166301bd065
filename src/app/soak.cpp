#include "app/soak.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <unistd.h>

#include "app/camera_path.h"
#include "gl/live_objects.h"
#include "ocean/wave_spectrum.h"
#include "scene/toml_error.h"
#include "util/file_util.h"
#include "util/log.h"

namespace planet {

namespace fs = std::filesystem;

namespace {

constexpr int kEvery = 100;  // frames between edits, and between samples

double residentMiB() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return static_cast<double>(resident) * static_cast<double>(::sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// A path with a keyframe at every view, in the order the views were loaded, kEvery frames
// apart at its natural rate, and back to the first (so at least two keyframes).
CameraPath tourOfViews(const Session& session) {
    if (session.views.empty()) throw InputError("--suite soak: no views to fly through");
    CameraPathFile file;
    file.name = "tour of the views";
    file.fps = 10.0;
    std::vector<View> stops = session.views;
    stops.push_back(stops.front());
    for (std::size_t i = 0; i < stops.size(); ++i) {
        const View& v = stops[i];
        PathKeyframe k;
        k.time_s = static_cast<double>(i) * kEvery / file.fps;
        k.latitude_deg = v.latitude_deg;
        k.longitude_deg = v.longitude_deg;
        k.altitude_m = v.altitude_m;
        k.heading_deg = v.heading_deg;
        k.pitch_deg = v.pitch_deg;
        k.fov_deg = v.fov_deg;
        file.keyframes.push_back(k);
    }
    return CameraPath(file, session.scene.planetRadiusM(), [&session](const glm::dvec3& direction) {
        return terrain::surfaceHeightM(session.ground, direction);
    });
}

// One edit a user tuning the scene would make; each comes back to its start on its next turn.
struct Edit {
    std::string name;
    std::function<void(Session&, glm::ivec2&, Renderer&)> apply;
};

std::vector<Edit> edits(glm::ivec2 size) {
    auto toggle = [](double& value, double a, double b) { value = value == a ? b : a; };
    return {
        {"render.exposure", [=](Session& s, glm::ivec2&, Renderer&) { toggle(s.scene.render.exposure, 10.0, 20.0); }},
        {"clouds.coverage", [=](Session& s, glm::ivec2&, Renderer&) { toggle(s.scene.clouds.coverage, 0.5, 0.8); }},
        {"atmosphere.mie_g (tables)",
         [=](Session& s, glm::ivec2&, Renderer&) { toggle(s.scene.atmosphere.mie_g, 0.8, 0.7); }},
        {"ocean.wind_speed_mps (waves)",
         [=](Session& s, glm::ivec2&, Renderer&) {
             toggle(s.scene.ocean.wind_speed_mps, 8.0, 14.0);
             s.scene.waves = ocean::generateWaves(s.scene.ocean);
         }},
        {"render.temporal", [=](Session& s, glm::ivec2&, Renderer&) { s.scene.render.temporal = !s.scene.render.temporal; }},
        {"terrain.max_height_m",
         [=](Session& s, glm::ivec2&, Renderer&) { toggle(s.scene.terrain.max_height_m, 8000.0, 6000.0); }},
        {"resize", [=](Session&, glm::ivec2& current, Renderer&) {
             current = current == size ? glm::max(size * 3 / 4, glm::ivec2(1)) : size;
         }},
        {"atmosphere.rayleigh_scattering_per_m (tables)",
         [=](Session& s, glm::ivec2&, Renderer&) {
             glm::dvec3& r = s.scene.atmosphere.rayleigh_scattering_per_m;
             r = r.x == 5.802e-6 ? r * 1.5 : glm::dvec3(5.802e-6, 13.558e-6, 33.1e-6);
         }},
        {"shader reload (all)", [=](Session&, glm::ivec2&, Renderer& r) { r.reloadShaders(true); }},
    };
}

struct Sample {
    int frame = 0;
    double seconds = 0.0;
    double residentMiB = 0.0;
    gl::LiveObjects objects;
    std::string edit;
};

// Least-squares slope of resident memory against frames, MiB per 1000 frames.
double slopePer1000(const std::vector<Sample>& samples) {
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const Sample& s : samples) {
        n += 1;
        sx += s.frame;
        sy += s.residentMiB;
        sxx += static_cast<double>(s.frame) * s.frame;
        sxy += s.frame * s.residentMiB;
    }
    const double d = n * sxx - sx * sx;
    return d > 0.0 ? 1000.0 * (n * sxy - sx * sy) / d : 0.0;
}

}  // namespace

int benchSoak(Renderer& renderer, Session& session, glm::ivec2 size, int frames, const BenchOptions& o) {
    const CameraPath path = tourOfViews(session);
    const std::vector<Edit> edit = edits(size);
    std::printf("soak: %d frames along a path through %zu views, an edit every %d frames\n", frames,
                session.views.size(), kEvery);
    std::printf("%8s %9s %12s %8s  %s\n", "frame", "time s", "resident MiB", "GL objs", "edit after the sample");
    const double clockStart = session.scene.time_s;
    const double pathFrames = (path.file().keyframes.size() - 1) * kEvery;
    glm::ivec2 current = size;
    std::vector<Sample> samples;
    const auto start = std::chrono::steady_clock::now();
    for (int frame = 0; frame < frames; ++frame) {
        const double t = std::fmod(frame, pathFrames) / path.file().fps;
        applyPathSample(path, t, clockStart, session);
        renderer.render(session.scene, session.camera, current);
        if ((frame + 1) % kEvery != 0) continue;
        glFinish();
        Sample s;
        s.frame = frame + 1;
        s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        s.residentMiB = residentMiB();
        s.objects = gl::countLiveObjects();
        s.edit = edit[samples.size() % edit.size()].name;
        std::printf("%8d %9.1f %12.1f %8d  %s\n", s.frame, s.seconds, s.residentMiB, s.objects.total(), s.edit.c_str());
        std::fflush(stdout);
        edit[samples.size() % edit.size()].apply(session, current, renderer);
        samples.push_back(s);
    }
    if (samples.size() < 4) throw InputError("--suite soak: --frames must give at least 4 samples (400 frames)");

    // Warm-up: the first full round of edits (every kind of table, target and program has been
    // made once). Flat after it: the same GL objects at every sample of the same point in the
    // round, and the memory's slope over the second half under 1 MiB per 1000 frames.
    const std::size_t warm = std::min(edit.size(), samples.size() / 2);
    bool objectsFlat = true;
    int fewest = samples[warm].objects.total(), most = fewest;
    for (std::size_t i = warm; i < samples.size(); ++i) {
        fewest = std::min(fewest, samples[i].objects.total());
        most = std::max(most, samples[i].objects.total());
        if (i >= warm + edit.size() && !(samples[i].objects == samples[i - edit.size()].objects)) objectsFlat = false;
    }
    const std::vector<Sample> secondHalf(samples.begin() + static_cast<long>(samples.size() / 2), samples.end());
    const double slope = slopePer1000(secondHalf);
    const bool memoryFlat = slope < 1.0;
    std::printf("resident memory: %.1f MiB after the warm-up (frame %d), %.1f MiB at the end, slope over the second "
                "half %+.3f MiB per 1000 frames (%s)\n",
                samples[warm].residentMiB, samples[warm].frame, samples.back().residentMiB, slope,
                memoryFlat ? "flat" : "GROWING");
    std::printf("live GL objects after the warm-up: %d to %d (%s); at the end: %s\n", fewest, most,
                objectsFlat ? "the same at each point of the round of edits" : "GROWING",
                gl::describe(samples.back().objects).c_str());
    if (!o.csv.empty()) {
        std::ostringstream csv;
        csv << "frame,seconds,resident_mib,gl_buffers,gl_textures,gl_framebuffers,gl_vertex_arrays,gl_queries,"
               "gl_programs,gl_shaders,gl_total,edit_after\n";
        for (const Sample& s : samples) {
            const gl::LiveObjects& g = s.objects;
            csv << s.frame << "," << s.seconds << "," << s.residentMiB << "," << g.buffers << "," << g.textures << ","
                << g.framebuffers << "," << g.vertexArrays << "," << g.queries << "," << g.programs << "," << g.shaders
                << "," << g.total() << "," << s.edit << "\n";
        }
        writeFileAtomic(o.csv, csv.str());
        std::printf("wrote %s\n", fs::absolute(o.csv).lexically_normal().c_str());
    }
    return objectsFlat && memoryFlat ? 0 : 1;
}

}  // namespace planet
