#include "atmosphere/atmosphere.h"

#include <cstring>

#include "atmosphere/parameters.h"
#include "util/log.h"

namespace planet::atmosphere {

bool Atmosphere::Target::operator==(const Target& o) const {
    return orders == o.orders && std::memcmp(&uniforms, &o.uniforms, sizeof uniforms) == 0;
}

Atmosphere::Target Atmosphere::targetFor(const Scene& scene) {
    return {makeAtmosphereUniforms(makeAtmosphereParameters(scene)), scene.atmosphere.scattering_orders};
}

Atmosphere::Atmosphere(const std::filesystem::path& shaderRoot, const TableSizes& sizes)
    : precompute_(shaderRoot, sizes) {
    glNamedBufferStorage(uniforms_.id(), sizeof(AtmosphereUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
    uniforms_.label("AtmosphereUniforms");
}

void Atmosphere::update(const Scene& scene) {
    const Target wanted = targetFor(scene);
    if (!tables_) {  // first use: tables now
        logInfo("precomputing atmosphere tables (" + std::to_string(sizes().bytes() >> 20) + " MiB)...");
        tables_ = precompute_.compute(makeAtmosphereParameters(scene), wanted.orders, [](const PrecomputeStep& s) {
            logInfo("  " + s.name + ": " + std::to_string(s.seconds) + " s");
        });
        current_ = wanted;
        glNamedBufferSubData(uniforms_.id(), 0, sizeof current_.uniforms, &current_.uniforms);
        return;
    }
    if (job_ && !(pending_ == wanted)) job_.reset();  // parameters moved on: restart with the newest
    if (!job_ && !(current_ == wanted)) {
        job_ = precompute_.start(makeAtmosphereParameters(scene), wanted.orders);
        pending_ = wanted;
    }
    if (job_ && job_->step()) finishJob();
}

void Atmosphere::finishJob() {
    tables_ = job_->takeResult();
    current_ = pending_;
    glNamedBufferSubData(uniforms_.id(), 0, sizeof current_.uniforms, &current_.uniforms);
    job_.reset();
}

void Atmosphere::bind() const {
    const GLuint textures[] = {tables_->transmittance.id(), tables_->scattering.id(), tables_->singleMie.id(),
                               tables_->irradiance.id()};
    glBindTextures(kFirstTableUnit, 4, textures);
    glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereUniformBinding, uniforms_.id());
}

}  // namespace planet::atmosphere
