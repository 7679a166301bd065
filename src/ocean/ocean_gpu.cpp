// Packing the waves for the GPU, and gerstner.glsl compiled as C++ (ocean_gpu.h).
#include "ocean/ocean_gpu.h"
#include "ocean/ocean_block.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace planet::ocean {
namespace glsl {
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using glm::abs;
using glm::cross;
using glm::dot;
using std::floor;
using glm::max;
using glm::smoothstep;
using glm::step;
using std::sqrt;
inline float atan(float y, float x) { return std::atan2(y, x); }
#define OUT(x) x&
#include "shaders/ocean/gerstner.glsl"
#undef OUT
}  // namespace glsl

static_assert(sizeof(OceanWaveGpu) == 64 && sizeof(glsl::OceanWave) == 64, "std430 size of OceanWave");

namespace {

constexpr double kTwoPi = 6.283185307179586;

// x reduced to [-pi, pi).
double wrapPhase(double x) { return x - kTwoPi * std::floor(x / kTwoPi + 0.5); }

// Any unit vector perpendicular to the unit vector a.
glm::dvec3 anyPerpendicular(const glm::dvec3& a) {
    const glm::dvec3 helper = std::abs(a.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    return glm::normalize(glm::cross(a, helper));
}

glm::dvec3 cameraDirection(const glm::dvec3& cameraPosition) {
    const double length = glm::length(cameraPosition);
    return length > 0.0 ? cameraPosition / length : glm::dvec3(0, 0, 1);
}

}  // namespace

std::vector<OceanWaveGpu> packWaves(const std::vector<GerstnerWave>& waves, const glm::dvec3& cameraPosition,
                                    double seaRadius, double time) {
    const glm::dvec3 vc = cameraDirection(cameraPosition);
    // Longest first, so that the shaders can stop at the first wave too short for the
    // sampling and take the rest's slope variance from scale.z in one step.
    std::vector<const GerstnerWave*> order;
    for (const GerstnerWave& w : waves) order.push_back(&w);
    std::stable_sort(order.begin(), order.end(),
                     [](const GerstnerWave* a, const GerstnerWave* b) { return a->wavelength_m > b->wavelength_m; });
    std::vector<OceanWaveGpu> records;
    records.reserve(waves.size());
    for (const GerstnerWave* wave : order) {
        const GerstnerWave& w = *wave;
        const glm::dvec3 o = glm::normalize(w.origin);
        const double cosC = glm::dot(vc, o);
        const glm::dvec3 tangent = vc - cosC * o;
        const double sinC = glm::length(tangent);
        const glm::dvec3 e = sinC > 1e-12 ? tangent / sinC : anyPerpendicular(o);
        const double thetaC = std::atan2(sinC, cosC);
        const double k = kTwoPi / w.wavelength_m;
        // Michelic Eq. 8's phase k l - w t + phase0 at the camera's direction (l = r theta, Eq. 7).
        const double phase = wrapPhase(wrapPhase(k * seaRadius * thetaC) - wrapPhase(k * w.speed_mps * time) + w.phase_rad);
        records.push_back(OceanWaveGpu{glm::vec4(glm::vec3(o), static_cast<float>(k * seaRadius)),
                                       glm::vec4(glm::vec3(e), static_cast<float>(sinC)),
                                       glm::vec4(static_cast<float>(w.amplitude_m), static_cast<float>(w.steepness),
                                                 static_cast<float>(cosC), static_cast<float>(phase)),
                                       glm::vec4(static_cast<float>(k), static_cast<float>(w.wavelength_m), 0.0f, 0.0f)});
    }
    double tail = 0.0;  // slope variance (A k)^2 / 2 of this wave and every shorter one
    for (auto r = records.rbegin(); r != records.rend(); ++r) {
        const double slope = double(r->shape.x) * double(r->scale.x);
        tail += 0.5 * slope * slope;
        r->scale.z = static_cast<float>(tail);
    }
    return records;
}

glm::vec3 gpuPathDisplacement(const std::vector<OceanWaveGpu>& records, const glm::dvec3& direction,
                              const glm::dvec3& cameraPosition, const WaveFade& fade) {
    const glm::dvec3 v = glm::normalize(direction);
    const glm::vec3 dv(v - cameraDirection(cameraPosition));
    const glm::vec3 vf(v);
    glm::vec3 displacement(0.0f);
    for (const OceanWaveGpu& r : records) {
        const glsl::OceanWave w{r.originKr, r.frameE, r.shape, r.scale};
        glm::vec3 travel;
        float oneMinusAbsCos;
        const float phase = glsl::gerstnerPhase(w, dv, travel, oneMinusAbsCos);
        const float q = glsl::gerstnerSteepness(w, oneMinusAbsCos, static_cast<float>(fade.e0), static_cast<float>(fade.e1));
        const float a = r.shape.x;
        displacement += vf * (a * std::sin(phase)) + travel * (q * a * std::cos(phase));  // Michelic Eq. 8
    }
    return displacement;
}

double coxMunkSlopeVariance(double windSpeedMps) { return 0.003 + 5.12e-3 * windSpeedMps; }

double subgridSlopeVariance(const std::vector<GerstnerWave>& waves, double windSpeedMps) {
    double resolved = 0.0;
    for (const GerstnerWave& w : waves) {
        const double slope = w.amplitude_m * kTwoPi / w.wavelength_m;
        resolved += 0.5 * slope * slope;
    }
    const double total = coxMunkSlopeVariance(windSpeedMps);
    return std::max(total - resolved, 0.1 * total);
}

double maxWaveHeight(const std::vector<GerstnerWave>& waves) {
    double sum = 0.0;
    for (const GerstnerWave& w : waves) sum += w.amplitude_m;
    return sum;
}

}  // namespace planet::ocean

namespace planet::ocean {

OceanBlock makeOceanBlock(const Scene& scene) {
    OceanBlock b{};
    b.seaLevel = static_cast<float>(scene.ocean.sea_level_m);
    b.maxWaveHeight = static_cast<float>(maxWaveHeight(scene.waves));
    b.targetEdgePixels = static_cast<float>(scene.ocean.target_edge_px);
    b.coarsestEdgePixels = static_cast<float>(std::max(scene.terrain.target_edge_px, scene.ocean.target_edge_px));
    b.fadeStart = static_cast<float>(scene.ocean.fade_start);
    b.fadeEnd = static_cast<float>(scene.ocean.fade_end);
    b.subgridSlopeVariance = static_cast<float>(subgridSlopeVariance(scene.waves, scene.ocean.wind_speed_mps));
    b.waveCount = static_cast<int>(scene.waves.size());
    return b;
}

}  // namespace planet::ocean
