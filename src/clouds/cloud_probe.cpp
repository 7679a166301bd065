#include "clouds/cloud_probe.h"

#include "gl/debug.h"
#include "gl/program.h"
#include "render/bindings.h"

namespace planet::clouds {

CloudProbe::CloudProbe(const std::filesystem::path& shaderRoot, const atmosphere::TableSizes& sizes)
    : program_(gl::buildProgram(
          gl::ShaderSources{shaderRoot, gl::shaderPreamble() + atmosphere::atmosphereShaderDefines(sizes)},
          gl::ProgramDesc{"cloud probe", {"clouds/cloud_probe.comp"}})) {}

std::vector<CloudProbeResult> probeClouds(const std::filesystem::path& shaderRoot,
                                          const atmosphere::GpuTables& tables,
                                          const atmosphere::AtmosphereUniforms& atmosphere, const CloudBlock& block,
                                          const CloudResources* textures, const std::vector<CloudProbeRay>& rays) {
    if (rays.empty()) return {};
    return CloudProbe(shaderRoot, tables.sizes).run(tables, atmosphere, block, textures, rays);
}

std::vector<CloudProbeResult> CloudProbe::run(const atmosphere::GpuTables& tables,
                                              const atmosphere::AtmosphereUniforms& atmosphere,
                                              const CloudBlock& block, const CloudResources* textures,
                                              const std::vector<CloudProbeRay>& rays) const {
    if (rays.empty()) return {};
    std::vector<glm::vec4> input;
    for (const CloudProbeRay& r : rays) {
        input.emplace_back(glm::vec3(r.origin), static_cast<float>(r.distanceKm));
        input.emplace_back(glm::vec3(r.direction), 0.0f);
        input.emplace_back(glm::vec3(r.sun), 0.0f);
    }
    gl::Buffer inputBuffer, outputBuffer, atmosphereBuffer, cloudBuffer;
    glNamedBufferStorage(inputBuffer.id(), static_cast<GLsizeiptr>(input.size() * sizeof(glm::vec4)), input.data(), 0);
    const GLsizeiptr outputBytes = static_cast<GLsizeiptr>(rays.size() * 2 * sizeof(glm::vec4));
    glNamedBufferStorage(outputBuffer.id(), outputBytes, nullptr, 0);
    glNamedBufferStorage(atmosphereBuffer.id(), sizeof atmosphere, &atmosphere, 0);
    glNamedBufferStorage(cloudBuffer.id(), sizeof block, &block, 0);

    gl::DebugGroup group("cloud probe");
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_ATMOSPHERE, atmosphereBuffer.id());
    if (textures) textures->bind();  // the volume, the weather map (and its own block, replaced below)
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_CLOUDS, cloudBuffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_PROBE_INPUT, inputBuffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_PROBE_OUTPUT, outputBuffer.id());
    glBindTextureUnit(binding::UNIT_TRANSMITTANCE, tables.transmittance.id());
    glBindTextureUnit(binding::UNIT_SCATTERING, tables.scattering.id());
    glBindTextureUnit(binding::UNIT_SINGLE_MIE, tables.singleMie.id());
    glBindTextureUnit(binding::UNIT_IRRADIANCE, tables.irradiance.id());
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // the weather map, as the renderer samples it
    glUseProgram(program_.id());
    glProgramUniform1i(program_.id(), 0, static_cast<GLint>(rays.size()));
    glDispatchCompute(static_cast<GLuint>((rays.size() + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> output(rays.size() * 2);
    glGetNamedBufferSubData(outputBuffer.id(), 0, outputBytes, output.data());
    glUseProgram(0);

    std::vector<CloudProbeResult> results(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
        results[i].transmittance = glm::dvec3(glm::vec3(output[2 * i]));
        results[i].inscatter = glm::dvec3(glm::vec3(output[2 * i + 1]));
        results[i].steps = static_cast<int>(output[2 * i].w);
        results[i].skipped = static_cast<int>(output[2 * i + 1].w);
    }
    return results;
}

}  // namespace planet::clouds
