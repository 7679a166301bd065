#include "clouds/cloud_resources.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "render/bindings.h"
#include "util/log.h"

namespace planet::clouds {

noise::CloudVolumeParams volumeParamsOf(const CloudParams& c) {
    noise::CloudVolumeParams p;
    p.seed = c.volume_seed;
    p.size = c.volume_size;
    p.shapeFrequency = c.shape_frequency;
    p.detailFrequency = c.detail_frequency;
    p.erosion = c.erosion;
    p.cloudFraction = c.cloud_fraction;
    p.borderVoxels = c.border_voxels;
    return p;
}

noise::WeatherParams weatherParamsOf(const CloudParams& c) {
    noise::WeatherParams p;
    p.seed = c.weather_seed;
    p.coverage = 0.5;  // the layer's coverage scales it live (CloudLocalCoverage): no rebake
    p.frequency = c.weather_frequency;
    p.latitudeBands = c.latitude_bands;
    return p;
}

namespace {

void setFilters(const gl::Texture& t, GLenum wrap) {
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum axis : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) glTextureParameteri(t.id(), axis, wrap);
}

// The volume as a GL texture: R16F (the cache's half floats as they are), GL_REPEAT on
// every axis (Eq. 12's fract), trilinear between noise::kCloudVolumeMipLevels mip levels (read
// where a pixel spans voxels: cloud_density.glsl, CloudVolumeLod).
gl::Texture makeVolumeTexture(const noise::CloudVolume& volume) {
    gl::Texture t(GL_TEXTURE_3D);
    const int n = volume.size;
    int levels = 1;
    while (levels < noise::kCloudVolumeMipLevels && (n >> levels) >= 1) ++levels;
    glTextureStorage3D(t.id(), levels, GL_R16F, n, n, n);
    const std::vector<std::uint16_t> half = noise::cloudVolumeHalf(volume);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    glTextureSubImage3D(t.id(), 0, 0, 0, 0, n, n, n, GL_RED, GL_HALF_FLOAT, half.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    setFilters(t, GL_REPEAT);
    glGenerateTextureMipmap(t.id());
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    t.label("cloud volume " + std::to_string(n) + "^3");
    return t;
}

// The weather map as a seamless cube map, RG16F (coverage, type).
gl::Texture makeWeatherTexture(const noise::WeatherMap& map) {
    gl::Texture t(GL_TEXTURE_CUBE_MAP);
    const int n = map.size;
    glTextureStorage2D(t.id(), 1, GL_RG16F, n, n);
    glTextureSubImage3D(t.id(), 0, 0, 0, 0, n, n, 6, GL_RG, GL_FLOAT, map.texels.data());  // the faces in GL's order
    setFilters(t, GL_CLAMP_TO_EDGE);
    t.label("weather map " + std::to_string(n) + "^2 x 6");
    return t;
}

bool drawn(const CloudParams& c) { return c.enabled && !c.constant_density; }

}  // namespace

CloudResources::CloudResources(std::filesystem::path cacheRoot) : cacheRoot_(std::move(cacheRoot)) {
    glNamedBufferStorage(buffer_.id(), sizeof(CloudBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    buffer_.label("CloudBlock");
    glNamedBufferStorage(statisticsBuffer_.id(), 3 * sizeof(std::uint32_t), nullptr,
                         GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
    statisticsBuffer_.label("cloud march statistics");
    // Placeholders until a bake: one empty voxel, no coverage (shaders always have a texture bound).
    glTextureStorage3D(volume_.id(), 1, GL_R16F, 1, 1, 1);
    const float empty = -1.0f;
    glTextureSubImage3D(volume_.id(), 0, 0, 0, 0, 1, 1, 1, GL_RED, GL_FLOAT, &empty);
    setFilters(volume_, GL_REPEAT);
    volume_.label("cloud volume (none)");
    glTextureStorage2D(weather_.id(), 1, GL_RG16F, 1, 1);
    const float clear[2] = {0.0f, 0.5f};
    for (int face = 0; face < 6; ++face) glTextureSubImage3D(weather_.id(), 0, 0, 0, face, 1, 1, 1, GL_RG, GL_FLOAT, clear);
    setFilters(weather_, GL_CLAMP_TO_EDGE);
    weather_.label("weather map (none)");
}

CloudResources::~CloudResources() {
    if (pending_.valid()) pending_.wait();  // the worker reads nothing of ours, but must not outlive the process' GL
}

double CloudResources::largeStepKm(double tileWidthKm) const {
    if (volumeSize_ == 0) return 0.0;
    // A trilinear sample < 0 guarantees no cloud voxel within border - 1 voxels of it (cloud_volume.h).
    return tileWidthKm * double(std::max(borderVoxels_ - 1, 0)) / double(volumeSize_);
}

double CloudResources::bakeProgress() const {
    return pending_.valid() && pendingProgress_ ? std::min(pendingProgress_->load(), 0.999) : 1.0;
}

bool CloudResources::needsBake(const CloudParams& c) const {
    return drawn(c) && (volumeParams_ != volumeParamsOf(c) ||
                        weatherParams_ != std::make_pair(weatherParamsOf(c), c.weather_map_size));
}

CloudResources::Baked CloudResources::bake(const CloudParams& c, const std::shared_ptr<std::atomic<double>>& progress) const {
    Baked b;
    b.volumeParams = volumeParamsOf(c);
    b.weatherParams = weatherParamsOf(c);
    b.weatherSize = c.weather_map_size;
    const bool volume = volumeParams_ != b.volumeParams;
    const bool weather = weatherParams_ != std::make_pair(b.weatherParams, b.weatherSize);
    // Each its share of the progress by its expected time: on 2 cores the 256³ volume took 11 s and
    // the 1024² x 6 weather map 13.6 s (docs/PERFORMANCE.md, 2026-12-04), each in proportion to
    // its voxels or texels.
    const double volumeSeconds = 11.0 * std::pow(b.volumeParams.size / 256.0, 3.0);
    const double weatherSeconds = 13.6 * std::pow(b.weatherSize / 1024.0, 2.0);
    const double split = volume && weather ? volumeSeconds / (volumeSeconds + weatherSeconds) : volume ? 1.0 : 0.0;
    auto report = [progress](double from, double to) -> noise::BakeProgress {
        return [progress, from, to](double f) { progress->store(from + (to - from) * f); };
    };
    if (volume) b.volume = noise::loadOrBakeCloudVolume(b.volumeParams, cacheRoot_, report(0.0, split));
    if (weather) {
        b.weather = noise::loadOrBakeWeatherMap(b.weatherParams, b.weatherSize, cacheRoot_, report(split, 1.0));
        const auto start = std::chrono::steady_clock::now();
        b.clearSky = buildClearSkyMap(*b.weather);
        logInfo("clear sky map " + std::to_string(b.clearSky->size) + "^2 x 6 in " +
                std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start).count()) +
                " ms");
    }
    progress->store(1.0);
    return b;
}

void CloudResources::upload(Baked&& b) {
    if (b.volume) {
        volume_ = makeVolumeTexture(*b.volume);
        volumeSize_ = b.volume->size;
        borderVoxels_ = b.volumeParams.borderVoxels;
        volumeParams_ = b.volumeParams;
    }
    if (b.weather) {
        weather_ = makeWeatherTexture(*b.weather);
        clearSky_ = makeClearSkyTexture(b.clearSky ? *b.clearSky : ClearSkyMap{});
        clearSkyMap_ = b.clearSky ? *b.clearSky : ClearSkyMap{};
        weatherParams_ = std::make_pair(b.weatherParams, b.weatherSize);
    }
}

bool CloudResources::update(const Scene& scene, const Camera& camera, int viewportHeight) {
    bool made = false;
    // A finished background bake comes in first (it may be for older parameters; the check
    // below then starts the next).
    if (pending_.valid() && pending_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
        try {
            upload(pending_.get());
            made = true;
        } catch (const std::exception& e) {
            logError(std::string("cloud bake failed: ") + e.what());
            volumeParams_ = volumeParamsOf(pendingFor_);  // do not retry the same parameters every frame
            weatherParams_ = std::make_pair(weatherParamsOf(pendingFor_), pendingFor_.weather_map_size);
        }
    }
    const CloudParams& c = scene.clouds;
    if (needsBake(c) && !pending_.valid()) {
        pendingProgress_ = std::make_shared<std::atomic<double>>(0.0);
        if (background_ && volumeSize_ > 0) {  // the first bake is waited for, as the first tables are
            pendingFor_ = c;
            pending_ = std::async(std::launch::async, [this, c, progress = pendingProgress_] { return bake(c, progress); });
        } else {
            upload(bake(c, pendingProgress_));
            made = true;
        }
    }
    block_ = makeCloudBlock(scene, camera, largeStepKm(c.tile_width_km), volumeSize_,
                            camera.fovY_rad / std::max(viewportHeight, 1));
    // Until the first volume is there, the layer is drawn without clouds rather than from
    // the placeholder.
    if (drawn(c) && volumeSize_ == 0) block_.enabled = 0;
    block_.statistics = statistics_ ? 1 : 0;
    glNamedBufferSubData(buffer_.id(), 0, sizeof block_, &block_);
    if (statistics_) {
        const std::uint32_t zero[3] = {0, 0, 0};
        glNamedBufferSubData(statisticsBuffer_.id(), 0, sizeof zero, zero);
    }
    return made;
}

void CloudResources::bind() const {
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_CLOUDS, buffer_.id());
    glBindTextureUnit(binding::UNIT_CLOUD_VOLUME, volume_.id());
    glBindTextureUnit(binding::UNIT_WEATHER_MAP, weather_.id());
    glBindTextureUnit(binding::UNIT_CLEAR_SKY, clearSky_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_CLOUD_STATISTICS, statisticsBuffer_.id());
}

MarchStatistics CloudResources::marchStatistics() const {
    std::uint32_t counts[3] = {0, 0, 0};
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(statisticsBuffer_.id(), 0, sizeof counts, counts);
    return {counts[0], counts[1], counts[2]};
}

double CloudResources::clearAngleAt(const glm::dvec3& direction) const {
    // CloudClearDistance's conditions (clouds/cloud_density.glsl): the map says nothing for a layer of
    // constant density or coverage over 1/2 (CloudLocalCoverage then lifts a 0).
    if (block_.enabled == 0 || block_.coverage > 0.5f || block_.constantDensity != 0) return 0.0;
    return clearSkyAngleAt(clearSkyMap_, direction);
}

}  // namespace planet::clouds
