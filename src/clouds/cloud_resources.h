// The cloud layer's baked data on the GPU: the tiling density volume (a 3D texture, R16F,
// GL_REPEAT, trilinear) and the weather map (a cube map: coverage, cloud type), made or
// loaded in the renderer's prepare step when their parameters change, and the CloudBlock.
#pragma once

#include <vector>

#include "clouds/cloud_block.h"
#include "gl/handle.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace planet::clouds {

// A tiling density volume: size^3 values, x fastest; > 0 cloud density, 0 empty within
// `borderVoxels` of a cloud, < 0 empty farther away (Michelic fig. 9).
struct DensityVolume {
    int size = 0;
    int borderVoxels = 0;
    std::vector<float> values;
};

class CloudResources {
public:
    CloudResources();

    // Makes the volume and the weather map when there are none yet (or their parameters
    // changed) and uploads the block for this frame. Returns true when it made textures.
    bool update(const Scene& scene, const Camera& camera);
    // Binds the block at BLOCK_CLOUDS and the textures at UNIT_CLOUD_VOLUME, UNIT_WEATHER_MAP.
    void bind() const;
    // The largest step through empty space the volume's border allows for a tile width, km.
    double largeStepKm(double tileWidthKm) const;
    const CloudBlock& block() const { return block_; }

private:
    gl::Texture volume_{GL_TEXTURE_3D};
    gl::Texture weather_{GL_TEXTURE_CUBE_MAP};
    gl::Buffer buffer_;
    CloudBlock block_{};
    int volumeSize_ = 0;
    int borderVoxels_ = 0;
};

// The volume as a GL texture: R16F, GL_REPEAT on every axis (Eq. 12's fract), linear.
gl::Texture makeVolumeTexture(const DensityVolume& volume);

// An interim volume until the baked Perlin-Worley volume lands (noise/cloud_volume.h):
// inverted tiled Worley noise, three octaves, thresholded, with its zero-density border.
DensityVolume interimDensityVolume(int size, int borderVoxels);

}  // namespace planet::clouds
