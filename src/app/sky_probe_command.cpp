// `planet sky-probe`: sky radiance and transmittance for a list of rays given
// as a CSV, to compare the model with measurements or other implementations.
//
// Each row gives the camera altitude, the sun's zenith angle, and the view's
// zenith angle and azimuth relative to the sun. The frame is local: camera at
// (0, 0, bottom_radius + altitude), sun (sin sz, 0, cos sz), view
// (sin vz cos az, sin vz sin az, cos vz). Output per row: GetSkyRadiance()
// (shaders/atmosphere/rendering.glsl) divided by the solar irradiance, per
// channel, in 1/sr (scattered light only: no ground reflection, no sun disc),
// and the whole view ray's transmittance (0 when it hits the ground).
//
// By default the GPU evaluates it (shaders/atmosphere/sky_probe.comp) with the
// tables from the cache, precomputed there if missing; --reference runs the
// same function compiled as C++ (Model, double) on freshly computed CPU
// reference tables. The whole input is checked before any work: a malformed
// row stops the command naming its line, and nothing is written.
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>
#include <string_view>

#include "app/commands.h"
#include "app/session.h"
#include "atmosphere/parameters.h"
#include "atmosphere/precompute_gpu.h"
#include "atmosphere/reference_tables.h"
#include "atmosphere/uniforms.h"
#include "clouds/cloud_block.h"
#include "render/bindings.h"
#include "gl/context.h"
#include "gl/debug.h"
#include "gl/program.h"
#include "scene/toml_error.h"
#include "util/file_util.h"
#include "util/log.h"

namespace planet {

namespace fs = std::filesystem;
using namespace atmosphere;

namespace {

constexpr const char* kInputColumns[4] = {"altitude_m", "sun_zenith_deg", "view_zenith_deg", "view_azimuth_deg"};
constexpr const char* kOutputColumns = "radiance_r,radiance_g,radiance_b,transmittance_r,transmittance_g,transmittance_b";
constexpr int kRowsPerDispatch = 1 << 16;  // GPU rows per chunk (progress and watchdog granularity)
constexpr std::size_t kProgressRows = 100000;  // report progress for inputs at least this long

struct ProbeRow {
    std::string text[4];   // the input fields as written, echoed to the output
    double altitudeM, sunZenithDeg, viewZenithDeg, viewAzimuthDeg;
};

struct ProbeResult {
    glm::dvec3 radiance;       // W m^-2 sr^-1 nm^-1
    glm::dvec3 transmittance;
};

std::string trim(std::string_view s) {
    const std::size_t a = s.find_first_not_of(" \t\r");
    if (a == std::string_view::npos) return {};
    const std::size_t b = s.find_last_not_of(" \t\r");
    return std::string(s.substr(a, b - a + 1));
}

std::vector<std::string> splitFields(const std::string& line) {
    std::vector<std::string> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        fields.push_back(trim(std::string_view(line).substr(start, comma == std::string::npos ? std::string::npos
                                                                                              : comma - start)));
        if (comma == std::string::npos) return fields;
        start = comma + 1;
    }
}

// The CSV, checked row by row; throws InputError naming file, line and column.
std::vector<ProbeRow> readCases(const std::string& file) {
    const std::string text = readFile(file);
    std::istringstream in(text);
    std::string line;
    int lineNo = 0;
    std::string expectedHeader;
    for (const char* c : kInputColumns) expectedHeader += std::string(expectedHeader.empty() ? "" : ",") + c;

    bool sawHeader = false;
    std::vector<ProbeRow> rows;
    struct Range {
        double lo, hi;
        const char* unit;
    };
    const Range ranges[4] = {{0.0, 1e9, "m"}, {0.0, 180.0, "deg"}, {0.0, 180.0, "deg"}, {-360.0, 360.0, "deg"}};
    while (std::getline(in, line)) {
        ++lineNo;
        if (trim(line).empty()) continue;
        const std::vector<std::string> fields = splitFields(line);
        if (!sawHeader) {
            std::string header;
            for (const std::string& f : fields) header += (header.empty() ? "" : ",") + f;
            if (header != expectedHeader)
                throw InputError(file, lineNo, "", "expected the header '" + expectedHeader + "', found '" + trim(line) + "'");
            sawHeader = true;
            continue;
        }
        if (fields.size() != 4)
            throw InputError(file, lineNo, "",
                             "expected 4 columns (" + expectedHeader + "), found " + std::to_string(fields.size()));
        ProbeRow row{};
        double* values[4] = {&row.altitudeM, &row.sunZenithDeg, &row.viewZenithDeg, &row.viewAzimuthDeg};
        for (int c = 0; c < 4; ++c) {
            const std::string& f = fields[static_cast<std::size_t>(c)];
            double v = 0.0;
            const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
            if (f.empty() || ec != std::errc() || end != f.data() + f.size() || !std::isfinite(v))
                throw InputError(file, lineNo, kInputColumns[c], "'" + f + "' is not a number");
            if (!(v >= ranges[c].lo && v <= ranges[c].hi)) {
                char message[160];
                std::snprintf(message, sizeof message, "value %s is out of range [%g, %g] %s", f.c_str(), ranges[c].lo,
                              ranges[c].hi, ranges[c].unit);
                throw InputError(file, lineNo, kInputColumns[c], message);
            }
            *values[c] = v;
            row.text[c] = f;
        }
        rows.push_back(std::move(row));
    }
    if (!sawHeader) throw InputError(file, 0, "", "empty file: expected the header '" + expectedHeader + "'");
    return rows;
}

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

std::vector<ProbeResult> probeOnGpu(const std::vector<ProbeRow>& rows, const Session& session,
                                    const SkyProbeOptions& options, const DataPaths& paths) {
    gl::DebugMessages messages;  // outlives the context that reports into it
    gl::HeadlessContext context(options.common.glDebug);
    gl::installDebugOutput(&messages, options.common.glDebug);
    const TableSizes sizes = commandTableSizes(options.common.tables, true);
    const AtmosphereParameters params = makeAtmosphereParameters(session.scene);

    std::ostringstream log;
    const AtmosphereTables cpuTables =
        loadOrPrecomputeTables(session.scene, sizes, options.cache, paths.shaders(), false, false, log);
    std::istringstream lines(log.str());
    for (std::string line; std::getline(lines, line);) logInfo("sky-probe: " + line);
    const GpuTables tables = upload(cpuTables);

    const gl::Program program = gl::buildProgram(
        gl::ShaderSources{paths.shaders(), gl::shaderPreamble() + atmosphereShaderDefines(sizes)},
        gl::ProgramDesc{"atmosphere sky probe", {"atmosphere/sky_probe.comp"}});

    std::vector<glm::vec4> rayData(rows.size() * 3 + 3, glm::vec4(0.0f));  // +3: never an empty buffer
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const Rays r = raysFor(rows[i], params);
        rayData[3 * i] = glm::vec4(glm::vec3(r.camera), 0.0f);
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

std::vector<ProbeResult> probeOnCpu(const std::vector<ProbeRow>& rows, const Session& session,
                                    const SkyProbeOptions& options) {
    const TableSizes sizes = commandTableSizes(options.common.tables, false);
    const AtmosphereParameters params = makeAtmosphereParameters(session.scene);
    logInfo("sky-probe: computing the CPU reference tables (double precision)");
    const ReferenceResult reference =
        computeReferenceTables(params, sizes, session.scene.atmosphere.scattering_orders,
                               [](const PrecomputeStep& step) {
                                   char text[96];
                                   std::snprintf(text, sizeof text, "sky-probe: reference %s: %.3f s",
                                                 step.name.c_str(), step.seconds);
                                   logInfo(text);
                               });
    const AtmosphereTables& t = reference.tables;
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
    const std::vector<ProbeRow> rows = readCases(options.in);
    checkOutputsWritable({options.out});
    const DataPaths paths = findDataPaths(options.common.root);
    const Session session = loadSession(paths, options.common.preset, options.common.view);
    const glm::dvec3 irradiance = session.scene.sun.irradiance;
    if (!(irradiance.r > 0.0 && irradiance.g > 0.0 && irradiance.b > 0.0))
        throw InputError("sky-probe divides by the solar irradiance: the preset's sun.irradiance must be > 0 in "
                         "every channel");

    const auto start = std::chrono::steady_clock::now();
    const std::vector<ProbeResult> results =
        options.reference ? probeOnCpu(rows, session, options) : probeOnGpu(rows, session, options, paths);

    std::string csv;
    for (const char* c : kInputColumns) csv += std::string(c) + ",";
    csv += std::string(kOutputColumns) + "\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
        for (const std::string& field : rows[i].text) csv += field + ",";
        const glm::dvec3 perSr = results[i].radiance / irradiance;
        for (int c = 0; c < 3; ++c) csv += csvNumber(perSr[c]) + ",";
        for (int c = 0; c < 3; ++c) csv += csvNumber(results[i].transmittance[c]) + (c < 2 ? "," : "\n");
    }
    writeFileAtomic(options.out, csv);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("probed %zu rows on %s in %.3f s\nwrote %s\n", rows.size(),
                options.reference ? "the CPU (reference)" : "the GPU", seconds,
                fs::absolute(options.out).lexically_normal().c_str());
    return 0;
}

}  // namespace planet
