// Spherical Gerstner waves, the CPU reference in double (waves.h; Michelic §4, Eq. 7-11).
//
// Every function goes through waveTerm, which evaluates one wave at one direction: the
// phase, the unit direction of travel d_i and the faded steepness Q'_i. Positions and
// normals are then the plain sums of Eq. 8 and Eq. 10.
#include "ocean/waves.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace planet::ocean {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

struct WaveTerm {
    glm::dvec3 travel{0.0};  // d_i: unit tangent away from o_i; zero at v = +-o_i where it is undefined
    double phase = 0.0;      // theta_i = k_i l_i - w_i t + phase_i
    double steepness = 0.0;  // Q'_i (Eq. 11)
};

// GLSL's smoothstep, extended to e1 <= e0 as a step at e0 (so e0 = e1 = 0 turns the fade off).
double smoothstep(double e0, double e1, double x) {
    if (!(e1 > e0)) return x < e0 ? 0.0 : 1.0;
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

WaveTerm waveTerm(const GerstnerWave& w, const glm::dvec3& v, double seaRadius, double time, const WaveFade& fade) {
    WaveTerm term;
    const double c = glm::dot(v, w.origin);
    const double s = glm::length(glm::cross(v, w.origin));
    // Eq. 7: l = r * angle(v, o); atan2 keeps the angle accurate near 0 and pi, where acos loses half the digits.
    const double l = seaRadius * std::atan2(s, c);
    term.phase = w.wavenumber() * l - w.angularFrequency() * time + w.phase_rad;
    // Eq. 7's d = v x ((v - o) x v) = v (v.o) - o has length sin(angle) = s; normalised (see waves.h).
    const glm::dvec3 d = v * c - w.origin;
    const double len = glm::length(d);
    if (len > 0.0) term.travel = d / len;
    // Eq. 11's argument 1 - |v.o|, written s^2 / (1 + |c|) to keep its digits near the origin and antipode
    // (as shaders/ocean/gerstner.glsl does).
    term.steepness = w.steepness * smoothstep(fade.e0, fade.e1, s * s / (1.0 + std::abs(c)));
    return term;
}

}  // namespace

double GerstnerWave::wavenumber() const { return kTwoPi / wavelength_m; }

double GerstnerWave::angularFrequency() const { return wavenumber() * speed_mps; }

double deepWaterSpeed(double wavelength_m) { return std::sqrt(kGravity * wavelength_m / kTwoPi); }

glm::dvec3 gerstnerPosition(const std::vector<GerstnerWave>& waves, glm::dvec3 unitDirection, double seaRadius,
                            double time, const WaveFade& fade) {
    const glm::dvec3 v = glm::normalize(unitDirection);
    double vertical = 0.0;
    glm::dvec3 horizontal(0.0);
    for (const GerstnerWave& w : waves) {
        const WaveTerm term = waveTerm(w, v, seaRadius, time, fade);
        vertical += w.amplitude_m * std::sin(term.phase);
        horizontal += term.steepness * w.amplitude_m * std::cos(term.phase) * term.travel;
    }
    return v * (seaRadius + vertical) + horizontal;  // Eq. 8
}

glm::dvec3 gerstnerNormal(const std::vector<GerstnerWave>& waves, glm::dvec3 unitDirection, double seaRadius,
                          double time, const WaveFade& fade) {
    const glm::dvec3 v = glm::normalize(unitDirection);
    double vertical = 1.0;
    glm::dvec3 horizontal(0.0);
    for (const GerstnerWave& w : waves) {
        const WaveTerm term = waveTerm(w, v, seaRadius, time, fade);
        const double ak = w.amplitude_m * w.wavenumber();
        vertical -= term.steepness * ak * std::sin(term.phase);
        horizontal -= ak * std::cos(term.phase) * term.travel;
    }
    return glm::normalize(v * vertical + horizontal);  // Eq. 10
}

double gerstnerHeight(const std::vector<GerstnerWave>& waves, glm::dvec3 unitDirection, double seaRadius,
                      double time, const WaveFade& fade) {
    return glm::length(gerstnerPosition(waves, unitDirection, seaRadius, time, fade)) - seaRadius;
}

std::string validateWaves(const std::vector<GerstnerWave>& waves) {
    for (size_t i = 0; i < waves.size(); ++i) {
        const GerstnerWave& w = waves[i];
        std::ostringstream bad;
        bad << "wave " << i << ": ";
        const double originLength = glm::length(w.origin);
        if (!(std::abs(originLength - 1.0) <= 1e-6)) {
            bad << "origin must be a unit vector (length " << originLength << ")";
        } else if (!(std::isfinite(w.amplitude_m) && w.amplitude_m >= 0.0)) {
            bad << "amplitude_m must be finite and >= 0 (" << w.amplitude_m << ")";
        } else if (!(std::isfinite(w.wavelength_m) && w.wavelength_m > 0.0)) {
            bad << "wavelength_m must be finite and > 0 (" << w.wavelength_m << ")";
        } else if (!(w.steepness >= 0.0 && w.steepness <= 1.0)) {
            bad << "steepness must be in [0, 1] (" << w.steepness << ")";
        } else if (!std::isfinite(w.speed_mps)) {
            bad << "speed_mps must be finite (" << w.speed_mps << ")";
        } else if (!std::isfinite(w.phase_rad)) {
            bad << "phase_rad must be finite (" << w.phase_rad << ")";
        } else {
            continue;
        }
        return bad.str();
    }
    // Crests loop where the horizontal Jacobian of Eq. 8 reaches 0: for the sum of the waves
    // that cannot happen while sum Q_i A_i k_i <= 1 (Michelic Fig. 8d for one wave).
    double sharpness = 0.0;
    for (const GerstnerWave& w : waves) sharpness += w.steepness * w.amplitude_m * w.wavenumber();
    if (!(sharpness <= 1.0)) {
        std::ostringstream bad;
        bad << "the sum of steepness x amplitude x wavenumber over the waves is " << sharpness
            << ", above 1: the crests would loop (lower steepness or amplitude, or lengthen the waves)";
        return bad.str();
    }
    return "";
}

double shoalingKept(double amplitude_m, double waterDepth_m) {
    return std::clamp(0.39 * waterDepth_m / std::max(amplitude_m, 1e-6), 0.0, 1.0);
}

double foamCover(const std::vector<GerstnerWave>& waves, double waterDepth_m) {
    double energy = 0.0, foam = 0.0;
    for (const GerstnerWave& w : waves) {
        const double a2 = w.amplitude_m * w.amplitude_m;
        const double kept = shoalingKept(w.amplitude_m, waterDepth_m);
        energy += a2;
        if (kept < 1.0) foam += a2 * kept * kFoamCrestMean;
    }
    return energy > 0.0 ? foam / energy : 0.0;
}

}  // namespace planet::ocean
