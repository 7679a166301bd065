// `planet sky-probe`: sky radiance and transmittance for a list of rays given
// as a CSV, to compare the model with measurements or other implementations.
//
// Each row gives the camera altitude, the sun's zenith angle, and the view's
// zenith angle and azimuth relative to the sun. The frame is local: camera at
// (0, 0, bottom_radius + altitude), sun (sin sz, 0, cos sz), view
// (sin vz cos az, sin vz sin az, cos vz). Output per row: the light scattered
// towards the camera divided by the solar irradiance, per channel, in 1/sr (no
// ground reflection, no sun disc), and the view ray's transmittance.
//
// Clear sky (the preset's clouds.enabled false): GetSkyRadiance()
// (shaders/atmosphere/rendering.glsl) and the transmittance to the ground or
// the top of the atmosphere (GetViewRayTransmittance).
//
// With clouds (clouds.enabled true): the unified march of clouds and atmosphere
// (shaders/clouds/cloud_march.glsl, MarchView, Michelic Eq. 15-20), exactly what
// the sky pass runs, without the per-pixel jitter (1/2) and the far field (no
// pixel footprint): in-scattering of air and clouds and the transmittance of
// both, up to the ground where the ray hits it (at least 1 mm, so that a ray
// from the ground is not read as one to space), to space otherwise. The local
// frame is then the planet's own: the camera sits above the north pole (+z, the
// frame of the weather map), the sun's azimuth is along the meridian of
// longitude 0 (+x). The clouds are at the scene's clock (--time: they drift
// with the wind); each camera position gets its own CloudBlock, its tile offset
// formed in double (cloud_block.h). The preset's clouds.constant_density = true
// replaces the baked volume by a uniform layer (density clouds.density_scale)
// for checks against closed forms.
//
// By default the GPU evaluates it (shaders/atmosphere/sky_probe.comp, or with
// clouds clouds/cloud_probe.comp with the baked volume and weather map of
// CloudResources) with the tables from the cache, precomputed there if missing;
// --reference runs the same functions compiled as C++ (Model, double; with
// clouds clouds/cloud_reference.h, with the same volume and weather map loaded
// or baked through the cloud cache) on freshly computed CPU reference tables.
// The whole input is checked before any work: a malformed row stops the command
// naming its line, and nothing is written.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>

#include "app/commands.h"
#include "app/session.h"
#include "app/sky_accuracy.h"
#include "app/sky_probe_cases.h"
#include "atmosphere/parameters.h"
#include "atmosphere/precompute_gpu.h"
#include "atmosphere/reference_tables.h"
#include "atmosphere/uniforms.h"
#include "clouds/cloud_block.h"
#include "clouds/cloud_probe.h"
#include "clouds/cloud_reference.h"
#include "clouds/cloud_resources.h"
#include "render/bindings.h"
#include "gl/context.h"
#include "gl/debug.h"
#include "gl/program.h"
#include "noise/cloud_volume.h"
#include "noise/weather_map.h"
#include "scene/toml_error.h"
#include "util/file_util.h"
#include "util/log.h"

namespace planet {

namespace fs = std::filesystem;
using namespace atmosphere;

namespace {

constexpr int kRowsPerDispatch = 1 << 16;  // GPU rows per chunk (progress and watchdog granularity)
constexpr std::size_t kProgressRows = 100000;  // report progress for inputs at least this long

struct ProbeResult {
    glm::dvec3 radiance;       // W m^-2 sr^-1 nm^-1
    glm::dvec3 transmittance;
};

// The row's geometry in the local frame (see the file header), km and unit vectors.
struct Rays {
    glm::dvec3 camera, view, sun;
};

Rays raysFor(const ProbeRow& row, const AtmosphereParameters& atmosphere) {
    const double sz = glm::radians(row.sunZenithDeg), vz = glm::radians(row.viewZenithDeg),
                 az = glm::radians(row.viewAzimuthDeg);
    return {glm::dvec3(0.0, 0.0, atmosphere.bottom_radius + row.altitudeM / 1000.0),
            glm::dvec3(std::sin(vz) * std::cos(az), std::sin(vz) * std::sin(az), std::cos(vz)),
            glm::dvec3(std::sin(sz), 0.0, std::cos(sz))};
}

void reportProgress(std::size_t done, std::size_t total) {
    if (total >= kProgressRows)
        logInfo("sky-probe: " + std::to_string(done) + " / " + std::to_string(total) + " rows (" +
                std::to_string(static_cast<int>(100.0 * static_cast<double>(done) / static_cast<double>(total))) +
                "%)");
}

// ------------------------------------------------------------------ with clouds

// The row's ray for the cloud march (km, from the planet centre): raysFor's, ending at the
// ground where it hits it (at least 1 mm: a distance <= 0 means "to space"), else to space.
clouds::CloudProbeRay cloudRayFor(const ProbeRow& row, const AtmosphereParameters& atmosphere) {
    const Rays r = raysFor(row, atmosphere);
    clouds::CloudProbeRay ray;
    ray.origin = r.camera;
    ray.direction = r.view;
    ray.sun = r.sun;
    const double radius = glm::length(r.camera), rmu = glm::dot(r.camera, r.view);
    const double discriminant = rmu * rmu - (radius - atmosphere.bottom_radius) * (radius + atmosphere.bottom_radius);
    if (rmu < 0.0 && discriminant >= 0.0) ray.distanceKm = std::max(-rmu - std::sqrt(discriminant), 1e-6);
    return ray;
}

// The CloudBlock for a camera at `originKm`: makeCloudBlock forms the tile offset of the
// camera in double (Michelic Eq. 12); no pixel footprint, hence no far field.
clouds::CloudBlock cloudBlockAt(const Scene& scene, const glm::dvec3& originKm, double largeStepKm) {
    Camera camera;
    camera.position = originKm * 1000.0;
    return clouds::makeCloudBlock(scene, camera, largeStepKm, scene.clouds.volume_size, 0.0);
}

// Row indices by camera altitude: one camera position, one block.
std::map<double, std::vector<std::size_t>> rowsByAltitude(const std::vector<ProbeRow>& rows) {
    std::map<double, std::vector<std::size_t>> groups;
    for (std::size_t i = 0; i < rows.size(); ++i) groups[rows[i].altitudeM].push_back(i);
    return groups;
}

ProbeResult fromMarch(const clouds::CloudProbeResult& m) { return {m.inscatter, m.transmittance}; }

// clouds/cloud_probe.comp for every row, a dispatch per camera position, i.e. per distinct
// altitude (and per kRowsPerDispatch rows), with the volume and the weather map loaded or
// baked by CloudResources as for the renderer.
std::vector<ProbeResult> probeCloudsOnGpu(const std::vector<ProbeRow>& rows, const Scene& scene,
                                          const AtmosphereParameters& params, const GpuTables& tables,
                                          const fs::path& shaderRoot) {
    clouds::CloudResources resources;
    resources.update(scene, Camera{}, 1);  // the volume and the weather map (nothing for a constant layer)
    const double largeStepKm = resources.largeStepKm(scene.clouds.tile_width_km);
    const clouds::CloudProbe probe(shaderRoot, tables.sizes);
    const AtmosphereUniforms uniforms = makeAtmosphereUniforms(params);
    std::vector<ProbeResult> results(rows.size());
    std::size_t done = 0;
    for (const auto& [altitude, indices] : rowsByAltitude(rows)) {
        for (std::size_t first = 0; first < indices.size(); first += kRowsPerDispatch) {
            const std::size_t last = std::min<std::size_t>(indices.size(), first + kRowsPerDispatch);
            std::vector<clouds::CloudProbeRay> rays;
            for (std::size_t k = first; k < last; ++k) rays.push_back(cloudRayFor(rows[indices[k]], params));
            const clouds::CloudBlock block = cloudBlockAt(scene, rays[0].origin, largeStepKm);
            const std::vector<clouds::CloudProbeResult> got = probe.run(tables, uniforms, block, &resources, rays);
            for (std::size_t k = first; k < last; ++k) results[indices[k]] = fromMarch(got[k - first]);
            const std::size_t before = done;
            done += last - first;
            if (done / kRowsPerDispatch != before / kRowsPerDispatch || done == rows.size())
                reportProgress(done, rows.size());
        }
    }
    return results;
}

// The same march on the CPU in double (clouds/cloud_reference.h), on all cores, with the
// volume and the weather map from the same cache entries (baked there if missing).
std::vector<ProbeResult> probeCloudsOnCpu(const std::vector<ProbeRow>& rows, const Scene& scene,
                                          const AtmosphereParameters& params, const AtmosphereTables& tables) {
    const CloudParams& c = scene.clouds;
    std::optional<noise::CloudVolume> volume;
    std::optional<noise::WeatherMap> weather;
    if (!c.constant_density) {
        const fs::path root = noise::defaultCloudCacheRoot();
        volume = noise::loadOrBakeCloudVolume(clouds::volumeParamsOf(c), root);
        weather = noise::loadOrBakeWeatherMap(clouds::weatherParamsOf(c), c.weather_map_size, root);
    }
    const clouds::CloudReference reference(params, tables, volume ? &*volume : nullptr, weather ? &*weather : nullptr);
    const double largeStepKm = clouds::largeStepKmOf(c);
    std::vector<ProbeResult> results(rows.size());
    for (std::size_t first = 0; first < rows.size(); first += kRowsPerDispatch) {
        const std::size_t last = std::min<std::size_t>(rows.size(), first + kRowsPerDispatch);
        std::vector<clouds::CloudProbeRay> rays;
        std::vector<clouds::CloudBlock> blocks;
        for (std::size_t i = first; i < last; ++i) {
            rays.push_back(cloudRayFor(rows[i], params));
            blocks.push_back(cloudBlockAt(scene, rays.back().origin, largeStepKm));
        }
        const std::vector<clouds::CloudProbeResult> got = reference.march(blocks, rays);
        for (std::size_t i = first; i < last; ++i) results[i] = fromMarch(got[i - first]);
        reportProgress(last, rows.size());
    }
    return results;
}

// ------------------------------------------------------------------ the probes

std::vector<ProbeResult> probeOnGpu(const std::vector<ProbeRow>& rows, const Scene& scene,
                                    const SkyProbeOptions& options, const DataPaths& paths) {
    gl::DebugMessages messages;  // outlives the context that reports into it
    gl::HeadlessContext context(options.common.glDebug);
    gl::installDebugOutput(&messages, options.common.glDebug);
    const TableSizes sizes = commandTableSizes(options.common.tables, true);
    const AtmosphereParameters params = makeAtmosphereParameters(scene);

    std::ostringstream log;
    const AtmosphereTables cpuTables =
        loadOrPrecomputeTables(scene, sizes, options.cache, paths.shaders(), false, false, log);
    std::istringstream lines(log.str());
    for (std::string line; std::getline(lines, line);) logInfo("sky-probe: " + line);
    const GpuTables tables = upload(cpuTables);
    if (scene.clouds.enabled) {
        std::vector<ProbeResult> results = probeCloudsOnGpu(rows, scene, params, tables, paths.shaders());
        if (messages.errors > 0) throw std::runtime_error("GL errors were reported while probing the sky");
        return results;
    }

    const gl::Program program = gl::buildProgram(
        gl::ShaderSources{paths.shaders(), gl::shaderPreamble() + atmosphereShaderDefines(sizes)},
        gl::ProgramDesc{"atmosphere sky probe", {"atmosphere/sky_probe.comp"}});

    std::vector<glm::vec4> rayData(rows.size() * 3 + 3, glm::vec4(0.0f));  // +3: never an empty buffer
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const Rays r = raysFor(rows[i], params);
        // w: the altitude (km) formed in double, apart from the radius (sky_probe.comp).
        rayData[3 * i] = glm::vec4(glm::vec3(r.camera), static_cast<float>(rows[i].altitudeM / 1000.0));
        rayData[3 * i + 1] = glm::vec4(glm::vec3(r.view), 0.0f);
        rayData[3 * i + 2] = glm::vec4(glm::vec3(r.sun), 0.0f);
    }
    gl::Buffer rayBuffer, resultBuffer, uniformBuffer;
    glNamedBufferStorage(rayBuffer.id(), static_cast<GLsizeiptr>(rayData.size() * sizeof(glm::vec4)), rayData.data(), 0);
    const std::size_t resultCount = rows.size() * 2 + 2;
    glNamedBufferStorage(resultBuffer.id(), static_cast<GLsizeiptr>(resultCount * sizeof(glm::vec4)), nullptr, 0);
    const AtmosphereUniforms u = makeAtmosphereUniforms(params);
    glNamedBufferStorage(uniformBuffer.id(), sizeof u, &u, 0);
    const clouds::CloudBlock clearSky{};  // enabled 0
    gl::Buffer noClouds;
    glNamedBufferStorage(noClouds.id(), sizeof clearSky, &clearSky, 0);
    rayBuffer.label("sky probe rays");
    resultBuffer.label("sky probe results");
    uniformBuffer.label("sky probe atmosphere parameters");

    {
        gl::DebugGroup group("sky probe");
        glUseProgram(program.id());
        glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_ATMOSPHERE, uniformBuffer.id());
        glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_CLOUDS, noClouds.id());  // the clear sky
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_PROBE_INPUT, rayBuffer.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_PROBE_OUTPUT, resultBuffer.id());
        glBindTextureUnit(binding::UNIT_TRANSMITTANCE, tables.transmittance.id());
        glBindTextureUnit(binding::UNIT_SCATTERING, tables.scattering.id());
        glBindTextureUnit(binding::UNIT_SINGLE_MIE, tables.singleMie.id());
        for (std::size_t first = 0; first < rows.size(); first += kRowsPerDispatch) {
            const int count = static_cast<int>(std::min<std::size_t>(kRowsPerDispatch, rows.size() - first));
            glProgramUniform1i(program.id(), 0, static_cast<GLint>(first));
            glProgramUniform1i(program.id(), 1, count);
            glDispatchCompute(static_cast<GLuint>((count + 63) / 64), 1, 1);
            glFinish();
            reportProgress(first + static_cast<std::size_t>(count), rows.size());
        }
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    }
    std::vector<glm::vec4> resultData(resultCount);
    glGetNamedBufferSubData(resultBuffer.id(), 0, static_cast<GLsizeiptr>(resultCount * sizeof(glm::vec4)),
                            resultData.data());
    if (messages.errors > 0) throw std::runtime_error("GL errors were reported while probing the sky");

    std::vector<ProbeResult> results(rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i)
        results[i] = {glm::dvec3(resultData[2 * i]), glm::dvec3(resultData[2 * i + 1])};
    return results;
}

std::vector<ProbeResult> probeOnCpu(const std::vector<ProbeRow>& rows, const Scene& scene,
                                    const SkyProbeOptions& options) {
    const TableSizes sizes = commandTableSizes(options.common.tables, false);
    const AtmosphereParameters params = makeAtmosphereParameters(scene);
    logInfo("sky-probe: computing the CPU reference tables (double precision)");
    const ReferenceResult reference =
        computeReferenceTables(params, sizes, scene.atmosphere.scattering_orders,
                               [](const PrecomputeStep& step) {
                                   char text[96];
                                   std::snprintf(text, sizeof text, "sky-probe: reference %s: %.3f s",
                                                 step.name.c_str(), step.seconds);
                                   logInfo(text);
                               });
    const AtmosphereTables& t = reference.tables;
    if (scene.clouds.enabled) return probeCloudsOnCpu(rows, scene, params, t);
    Model model(sizes);
    std::vector<ProbeResult> results(rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const Rays r = raysFor(rows[i], params);
        glm::dvec3 transmittance(0.0);
        const glm::dvec3 radiance = model.GetSkyRadiance(params, t.transmittance, t.scattering, t.singleMie,
                                                         r.camera, r.view, r.sun, transmittance);
        transmittance = model.GetViewRayTransmittance(params, t.transmittance, r.camera, r.view);  // to the ground too
        results[i] = {radiance, transmittance};
        if ((i + 1) % kRowsPerDispatch == 0 || i + 1 == rows.size()) reportProgress(i + 1, rows.size());
    }
    return results;
}

std::string csvNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

}  // namespace

int runSkyProbe(const SkyProbeOptions& options) {
    if (options.in.empty()) throw InputError("--in: give the input CSV");
    if (options.out.empty()) throw InputError("--out: give the output CSV");
    const std::vector<ProbeRow> rows = readProbeCases(options.in);
    std::vector<ProbeResultRow> against;
    if (!options.against.empty()) {
        against = readProbeResults(options.against);  // checked before any work
        if (against.size() != rows.size())
            throw InputError("--against " + options.against + " has " + std::to_string(against.size()) +
                             " rays, --in " + std::to_string(rows.size()) + ": not the same rays");
    }
    checkOutputsWritable({options.out});
    const DataPaths paths = findDataPaths(options.common.root);
    const NamedPreset preset = loadNamedPreset(paths, options.common.preset);  // rays in a local frame: no view
    const glm::dvec3 irradiance = preset.scene.sun.irradiance;
    if (!(irradiance.r > 0.0 && irradiance.g > 0.0 && irradiance.b > 0.0))
        throw InputError("sky-probe divides by the solar irradiance: the preset's sun.irradiance must be > 0 in "
                         "every channel");

    Scene scene = preset.scene;
    scene.time_s = options.common.time;  // the clouds' wind drift

    const auto start = std::chrono::steady_clock::now();
    const std::vector<ProbeResult> results =
        options.reference ? probeOnCpu(rows, scene, options) : probeOnGpu(rows, scene, options, paths);

    std::vector<ProbeResultRow> got;
    for (std::size_t i = 0; i < rows.size(); ++i)
        got.push_back({rows[i], results[i].radiance / irradiance, results[i].transmittance});
    std::string csv;
    for (const char* c : kProbeInputColumns) csv += std::string(c) + ",";
    for (const char* c : kProbeOutputColumns) csv += std::string(c) + (c == kProbeOutputColumns[5] ? "\n" : ",");
    for (std::size_t i = 0; i < rows.size(); ++i) {
        for (const std::string& field : rows[i].text) csv += field + ",";
        for (int c = 0; c < 3; ++c) csv += csvNumber(got[i].radiance[c]) + ",";
        for (int c = 0; c < 3; ++c) csv += csvNumber(got[i].transmittance[c]) + (c < 2 ? "," : "\n");
    }
    writeFileAtomic(options.out, csv);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("probed %zu rows%s on %s in %.3f s\nwrote %s\n", rows.size(),
                scene.clouds.enabled ? " through the clouds" : "", options.reference ? "the CPU (reference)" : "the GPU",
                seconds,
                fs::absolute(options.out).lexically_normal().c_str());
    if (!against.empty()) {
        // The csv's own rounding (9 digits), as a later comparison of the two files would see it.
        const std::vector<ProbeResultRow> written = parseProbeResults(csv, options.out);
        const double radiusM = makeAtmosphereParameters(scene).bottom_radius * 1000.0;
        std::printf("against %s:\n%s\n", options.against.c_str(),
                    describe(compareSkyProbes(written, against, radiusM), written).c_str());
    }
    return 0;
}

}  // namespace planet
