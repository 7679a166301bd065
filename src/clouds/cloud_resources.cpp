#include "clouds/cloud_resources.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "noise/noise.h"
#include "render/bindings.h"

namespace planet::clouds {

namespace {

// Marks every voxel within `border` voxels (Chebyshev distance, wrapping) of a cloud voxel:
// separable running maxima along x, y and z.
std::vector<unsigned char> nearCloud(const DensityVolume& v, int border) {
    const int n = v.size;
    std::vector<unsigned char> near(v.values.size());
    for (std::size_t i = 0; i < near.size(); ++i) near[i] = v.values[i] > 0.0f;
    std::vector<unsigned char> line(n), out(n);
    const int strides[3] = {1, n, n * n};
    for (int axis = 0; axis < 3; ++axis) {
        const int stride = strides[axis];
        for (int a = 0; a < n; ++a) {
            for (int b = 0; b < n; ++b) {
                // The start of a line along `axis`: the other two coordinates are a and b.
                const int base = axis == 0 ? (a * n + b) * n : axis == 1 ? a * n * n + b : a * n + b;
                for (int i = 0; i < n; ++i) line[i] = near[base + i * stride];
                for (int i = 0; i < n; ++i) {
                    unsigned char any = 0;
                    for (int d = -border; d <= border && !any; ++d) any = line[((i + d) % n + n) % n];
                    out[i] = any;
                }
                for (int i = 0; i < n; ++i) near[base + i * stride] = out[i];
            }
        }
    }
    return near;
}

}  // namespace

DensityVolume interimDensityVolume(int size, int borderVoxels) {
    DensityVolume v;
    v.size = size;
    v.borderVoxels = borderVoxels;
    v.values.resize(static_cast<std::size_t>(size) * size * size);
    for (int z = 0; z < size; ++z)
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const glm::vec3 p = (glm::vec3(x, y, z) + 0.5f) / float(size);
                float shape = 0.0f, amplitude = 0.5f, total = 0.0f;
                for (int octave = 0; octave < 3; ++octave) {
                    const float cells = 4.0f * float(1 << octave);
                    shape += amplitude * (1.0f - noise::worley(p * cells, cells));
                    total += amplitude;
                    amplitude *= 0.5f;
                }
                shape /= total;
                v.values[(static_cast<std::size_t>(z) * size + y) * size + x] =
                    std::clamp((shape - 0.55f) / 0.3f, 0.0f, 1.0f);
            }
    const std::vector<unsigned char> near = nearCloud(v, borderVoxels);
    for (std::size_t i = 0; i < v.values.size(); ++i)
        if (v.values[i] <= 0.0f) v.values[i] = near[i] ? 0.0f : -1.0f;
    return v;
}

gl::Texture makeVolumeTexture(const DensityVolume& volume) {
    gl::Texture t(GL_TEXTURE_3D);
    glTextureStorage3D(t.id(), 1, GL_R16F, volume.size, volume.size, volume.size);
    glTextureSubImage3D(t.id(), 0, 0, 0, 0, volume.size, volume.size, volume.size, GL_RED, GL_FLOAT,
                        volume.values.data());
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTextureParameteri(t.id(), wrap, GL_REPEAT);
    t.label("cloud volume " + std::to_string(volume.size) + "^3");
    return t;
}

CloudResources::CloudResources() {
    glNamedBufferStorage(buffer_.id(), sizeof(CloudBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    buffer_.label("CloudBlock");
    // The weather map until the baked one lands: full coverage everywhere (the layer's
    // coverage parameter alone decides).
    glTextureStorage2D(weather_.id(), 1, GL_RG16F, 1, 1);
    const float full[2] = {1.0f, 0.5f};
    for (int face = 0; face < 6; ++face) glTextureSubImage3D(weather_.id(), 0, 0, 0, face, 1, 1, 1, GL_RG, GL_FLOAT, full);
    glTextureParameteri(weather_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(weather_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    weather_.label("weather map (uniform)");
}

double CloudResources::largeStepKm(double tileWidthKm) const {
    if (volumeSize_ == 0) return 0.0;
    // A trilinear sample < 0 guarantees no cloud voxel within border - 1 voxels of it.
    return tileWidthKm * double(std::max(borderVoxels_ - 1, 0)) / double(volumeSize_);
}

bool CloudResources::update(const Scene& scene, const Camera& camera) {
    bool made = false;
    if (volumeSize_ == 0) {
        const DensityVolume v = interimDensityVolume(64, 3);
        volume_ = makeVolumeTexture(v);
        volumeSize_ = v.size;
        borderVoxels_ = v.borderVoxels;
        made = true;
    }
    block_ = makeCloudBlock(scene, camera, largeStepKm(scene.clouds.tile_width_km));
    glNamedBufferSubData(buffer_.id(), 0, sizeof block_, &block_);
    return made;
}

void CloudResources::bind() const {
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_CLOUDS, buffer_.id());
    glBindTextureUnit(binding::UNIT_CLOUD_VOLUME, volume_.id());
    glBindTextureUnit(binding::UNIT_WEATHER_MAP, weather_.id());
}

}  // namespace planet::clouds
