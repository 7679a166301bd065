// The cloud layer's baked data on the GPU: the tiling density volume (noise/cloud_volume.h;
// a 3D texture, R16F, GL_REPEAT, trilinear) and the weather map (noise/weather_map.h; a
// cube map, RG16F: coverage, cloud type), loaded from the cache or baked in the renderer's
// prepare step when their parameters change, and the CloudBlock of each frame.
//
// A bake takes seconds (a 256^3 volume 11-27 s on two cores, once; the cache makes it a
// load). A still waits for it, and so does the first frame of the explorer. The explorer asks
// for background rebakes: a rebake runs on a worker thread, the frame keeps the textures it
// had, and bakeProgress() tells the Scene panel how far it got; the textures are swapped in
// at the first prepare after it finished.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <future>
#include <memory>
#include <optional>

#include "clouds/cloud_block.h"
#include "gl/handle.h"
#include "noise/cloud_volume.h"
#include "clouds/clear_sky.h"
#include "noise/weather_map.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace planet::clouds {

// The bake parameters of a scene's clouds.
noise::CloudVolumeParams volumeParamsOf(const CloudParams& clouds);
noise::WeatherParams weatherParamsOf(const CloudParams& clouds);

// The sky pass's cloud march over one frame (the sea's reflections not included).
struct MarchStatistics {
    std::uint64_t marchSteps = 0;    // small steps, in or near clouds
    std::uint64_t skippedSteps = 0;  // large steps through empty space (the zero-density border's)
    std::uint64_t pixels = 0;        // pixels marched through air
    double stepsPerPixel(std::uint64_t allPixels) const {
        return allPixels ? double(marchSteps + skippedSteps) / double(allPixels) : 0.0;
    }
    double skippedShare() const {
        return marchSteps + skippedSteps ? double(skippedSteps) / double(marchSteps + skippedSteps) : 0.0;
    }
};

class CloudResources {
public:
    // `cacheRoot`: where the volume and the weather map are cached (noise::defaultCloudCacheRoot()).
    explicit CloudResources(std::filesystem::path cacheRoot = noise::defaultCloudCacheRoot());
    ~CloudResources();
    CloudResources(const CloudResources&) = delete;
    CloudResources& operator=(const CloudResources&) = delete;

    // Makes the volume and the weather map when the clouds are on and their bake parameters
    // changed (nothing while they are off, or for a constant-density layer), and uploads
    // the block for this frame. Returns true when it uploaded new textures.
    // `viewportHeight` (pixels) sets the footprints of the far field.
    bool update(const Scene& scene, const Camera& camera, int viewportHeight);
    // Bind the block at BLOCK_CLOUDS and the textures at UNIT_CLOUD_VOLUME, UNIT_WEATHER_MAP, UNIT_CLEAR_SKY.
    void bind() const;
    // The largest step through empty space the volume's border allows for a tile width, km.
    double largeStepKm(double tileWidthKm) const;
    const CloudBlock& block() const { return block_; }
    // The clear sky's angle at `direction` (rad; clouds/clear_sky.h), where the march's clear sky
    // check would read it: 0 where the map says nothing (no weather yet, coverage over 1/2, a layer
    // of constant density, the clouds off).
    double clearAngleAt(const glm::dvec3& direction) const;

    // Bake on a worker thread and keep drawing meanwhile (the explorer); off: update waits.
    void setBackgroundBakes(bool on) { background_ = on; }
    // In [0, 1) while a background bake runs, 1 otherwise.
    double bakeProgress() const;
    // Count the sky pass's march steps (planet bench): the counters are cleared at each
    // update and read after the frame with marchStatistics().
    void setStatistics(bool on) { statistics_ = on; }
    MarchStatistics marchStatistics() const;

private:
    struct Baked {
        noise::CloudVolumeParams volumeParams;
        noise::WeatherParams weatherParams;
        int weatherSize = 0;
        std::optional<noise::CloudVolume> volume;  // absent when only the weather changed
        std::optional<noise::WeatherMap> weather;
        std::optional<ClearSkyMap> clearSky;  // with the weather
    };
    Baked bake(const CloudParams& clouds, const std::shared_ptr<std::atomic<double>>& progress) const;
    void upload(Baked&& baked);
    bool needsBake(const CloudParams& clouds) const;

    std::filesystem::path cacheRoot_;
    gl::Texture volume_{GL_TEXTURE_3D};
    gl::Texture weather_{GL_TEXTURE_CUBE_MAP};
    gl::Texture clearSky_ = makeClearSkyTexture({});
    ClearSkyMap clearSkyMap_;  // what clearSky_ holds (empty: the placeholder's 0)
    gl::Buffer buffer_;
    gl::Buffer statisticsBuffer_;
    bool statistics_ = false;
    CloudBlock block_{};
    bool background_ = false;

    // What the textures hold (nullopt: the 1-texel placeholders).
    std::optional<noise::CloudVolumeParams> volumeParams_;
    std::optional<std::pair<noise::WeatherParams, int>> weatherParams_;
    int volumeSize_ = 0;
    int borderVoxels_ = 0;

    // A background bake in flight and what it is for.
    std::future<Baked> pending_;
    CloudParams pendingFor_{};
    std::shared_ptr<std::atomic<double>> pendingProgress_;
};

}  // namespace planet::clouds
