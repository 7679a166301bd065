// Wave-set generation from a sea spectrum (wave_spectrum.h): Pierson-Moskowitz or JONSWAP
// wavelengths and amplitudes, directions spread about the wind, origins upwind.
#include "ocean/wave_spectrum.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <sstream>

#include "scene/scene.h"

namespace planet::ocean {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;

// splitmix64 (Steele, Lea & Flood 2014): small, fast, and the same on every platform.
class Random {
public:
    explicit Random(uint64_t seed) : state_(seed) {}

    uint64_t next() {
        uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    // Uniform in [0, 1), 53 random bits.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    // Standard normal (Box-Muller); 1 - uniform() is in (0, 1], so the log is finite.
    double normal() { return std::sqrt(-2.0 * std::log(1.0 - uniform())) * std::cos(2.0 * kPi * uniform()); }

private:
    uint64_t state_;
};

// The inputs generation relies on, clamped to their documented ranges (ocean_params.h).
struct Inputs {
    double windSpeed;      // m/s
    double fetch;          // m, 0: fully developed
    double spreadRad;      // std. deviation of the direction about the wind, rad
    double minWavelength;  // m
    double choppiness;     // sum Q A k
    double latitudeDeg;    // of the wind point
    double longitudeDeg;
    double bearingDeg;     // of the wind, clockwise from north
};

Inputs clampedInputs(const OceanParams& p) {
    // x >= lo fails for NaN too, which then takes the lower bound.
    const auto atLeast = [](double x, double lo) { return x >= lo ? x : lo; };
    Inputs in;
    in.windSpeed = atLeast(p.wind_speed_mps, 0.1);
    in.fetch = atLeast(p.fetch_km, 0.0) * 1000.0;
    in.spreadRad = std::min(atLeast(p.directional_spread_deg, 0.0), 180.0) * kDegree;
    in.minWavelength = atLeast(p.min_wavelength_m, 1e-3);
    in.choppiness = std::min(atLeast(p.choppiness, 0.0), 1.0);
    in.latitudeDeg = std::min(atLeast(p.wind_latitude_deg, -90.0), 90.0);
    in.longitudeDeg = std::isfinite(p.wind_longitude_deg) ? p.wind_longitude_deg : 0.0;
    in.bearingDeg = std::isfinite(p.wind_bearing_deg) ? p.wind_bearing_deg : 0.0;
    return in;
}

struct Spectrum {
    double alpha;   // Phillips constant
    double omegaP;  // peak angular frequency, rad/s
    double gamma;   // JONSWAP peak enhancement; 1: Pierson-Moskowitz

    double operator()(double omega) const {
        const double g2 = kGravity * kGravity;
        const double ratio4 = std::pow(omegaP / omega, 4.0);
        double s = alpha * g2 / std::pow(omega, 5.0) * std::exp(-1.25 * ratio4);
        if (gamma != 1.0) {
            // Hasselmann et al. 1973: peak width sigma 0.07 below the peak, 0.09 above.
            const double sigma = omega <= omegaP ? 0.07 : 0.09;
            const double x = (omega - omegaP) / (sigma * omegaP);
            s *= std::pow(gamma, std::exp(-0.5 * x * x));
        }
        return s;
    }
};

Spectrum spectrumFor(const Inputs& in) {
    const double U = in.windSpeed;
    const double g = kGravity;
    // Pierson & Moskowitz 1964: fully developed sea.
    const Spectrum pm{8.1e-3, 0.855 * g / U, 1.0};
    if (in.fetch <= 0.0) return pm;
    // Hasselmann et al. 1973 (JONSWAP), with the fetch capped where w_p falls to PM's: beyond that
    // dimensionless fetch (about 17000) the sea is fully developed and the fits no longer apply.
    const double maxFetch = std::pow(22.0 / 0.855, 3.0) * U * U / g;
    const double F = std::min(in.fetch, maxFetch);
    const double alpha = 0.076 * std::pow(U * U / (F * g), 0.22);
    const double omegaP = 22.0 * std::cbrt(g * g / (U * F));
    return {alpha, omegaP, 3.3};
}

// Local north and east at a latitude/longitude: the derivatives of directionFromLatLon, so
// that they are defined at the poles too (as the limit along the given meridian).
glm::dvec3 northAt(double latDeg, double lonDeg) {
    const double lat = latDeg * kDegree;
    const double lon = lonDeg * kDegree;
    return {-std::sin(lat) * std::cos(lon), -std::sin(lat) * std::sin(lon), std::cos(lat)};
}

glm::dvec3 eastAt(double lonDeg) {
    const double lon = lonDeg * kDegree;
    return {-std::sin(lon), std::cos(lon), 0.0};
}

// One wave's share of the spectrum: the energy of the log-frequency stratum [logA, logB]
// and a frequency drawn from the spectrum restricted to it, at u in [0, 1).
struct StratumSample {
    double omega;   // rad/s
    double energy;  // integral of S over the stratum, m^2 (= A^2 / 2)
};

StratumSample sampleStratum(const Spectrum& spectrum, double logA, double logB, int steps, double u,
                            std::vector<double>& cumulative) {
    // Trapezoid rule in x = log w: integral of S dw = integral of S(e^x) e^x dx.
    const double dx = (logB - logA) / steps;
    const auto density = [&](int j) {
        const double omega = std::exp(logA + j * dx);
        return spectrum(omega) * omega;
    };
    cumulative.assign(static_cast<size_t>(steps) + 1, 0.0);
    double previous = density(0);
    for (int j = 1; j <= steps; ++j) {
        const double next = density(j);
        cumulative[static_cast<size_t>(j)] = cumulative[static_cast<size_t>(j) - 1] + 0.5 * (previous + next) * dx;
        previous = next;
    }
    const double energy = cumulative.back();
    if (!(energy > 0.0)) return {std::exp(logA + u * (logB - logA)), 0.0};  // nothing there (far tail)
    // Invert the cumulative energy, linearly within a sub-interval.
    const double target = u * energy;
    const auto above = std::upper_bound(cumulative.begin(), cumulative.end(), target);
    const size_t j = static_cast<size_t>(above - cumulative.begin());
    const size_t hi = std::min(j, static_cast<size_t>(steps));
    const size_t lo = hi - 1;
    const double width = cumulative[hi] - cumulative[lo];
    const double t = width > 0.0 ? (target - cumulative[lo]) / width : 0.5;
    return {std::exp(logA + (static_cast<double>(lo) + t) * dx), energy};
}

}  // namespace

double waveSpectrum(const OceanParams& params, double omega) { return spectrumFor(clampedInputs(params))(omega); }

double spectrumPeakFrequency(const OceanParams& params) { return spectrumFor(clampedInputs(params)).omegaP; }

double significantWaveHeight(const std::vector<GerstnerWave>& waves) {
    double variance = 0.0;  // of the height: sum A^2 / 2
    for (const GerstnerWave& w : waves) variance += 0.5 * w.amplitude_m * w.amplitude_m;
    return 4.0 * std::sqrt(variance);
}

std::vector<GerstnerWave> generateWaves(const OceanParams& params) {
    const int count = params.wave_count;
    if (count <= 0) return {};
    const Inputs in = clampedInputs(params);
    const Spectrum spectrum = spectrumFor(in);

    // Frequency range: from half the peak frequency (the spectrum's energy below is under
    // exp(-20) of the total) to the deep-water frequency of the shortest wave, w = sqrt(g k).
    const double omegaHi = std::sqrt(kGravity * 2.0 * kPi / in.minWavelength);
    const double omegaLo = std::min(0.5 * spectrum.omegaP, 0.5 * omegaHi);
    const double logLo = std::log(omegaLo);
    const double logStep = (std::log(omegaHi) - logLo) / count;
    // Quadrature sub-intervals per stratum: at least 2048 over the whole range, so that one
    // wave alone still carries the right energy.
    const int subSteps = std::max(8, (2048 + count - 1) / count);
    std::vector<double> cumulative;

    const glm::dvec3 windPoint = directionFromLatLon(in.latitudeDeg, in.longitudeDeg);
    const glm::dvec3 north = northAt(in.latitudeDeg, in.longitudeDeg);
    const glm::dvec3 east = eastAt(in.longitudeDeg);
    const double bearing = in.bearingDeg * kDegree;
    const double qakEach = in.choppiness / count;  // each wave's share of sum Q A k

    // The seed picks the stream; the constant only keeps seed 0 from starting at state 0.
    Random random(static_cast<uint64_t>(static_cast<uint32_t>(params.seed)) ^ 0x6F6365616E5F7761ull);
    std::vector<GerstnerWave> waves(static_cast<size_t>(count));
    double pairAngle = 0.0;
    for (int i = 0; i < count; ++i) {
        GerstnerWave& w = waves[static_cast<size_t>(i)];
        // Frequency: one per log stratum, drawn from S within it; amplitude A = sqrt(2 S dw) with
        // S dw the stratum's whole energy, so that sum A^2 / 2 is the spectrum's m0 for any count.
        const StratumSample sample = sampleStratum(spectrum, logLo + i * logStep, logLo + (i + 1) * logStep, subSteps,
                                                   random.uniform(), cumulative);
        const double omega = sample.omega;
        w.amplitude_m = std::sqrt(2.0 * sample.energy);
        const double k = omega * omega / kGravity;  // deep-water dispersion w^2 = g k
        w.wavelength_m = 2.0 * kPi / k;
        w.speed_mps = deepWaterSpeed(w.wavelength_m);

        // Direction at the wind point: bearing + a truncated-normal angle; antithetic pairs (2j, 2j + 1).
        if (i % 2 == 0) {
            do {
                pairAngle = in.spreadRad * random.normal();
            } while (std::abs(pairAngle) > 0.5 * kPi);
        } else {
            pairAngle = -pairAngle;
        }
        const double heading = bearing + pairAngle;  // clockwise from north
        const glm::dvec3 travel = std::cos(heading) * north + std::sin(heading) * east;
        // Origin upwind along the great circle through the wind point with that heading.
        const double upwind = random.uniform(20.0, 60.0) * kDegree;
        w.origin = glm::normalize(std::cos(upwind) * windPoint - std::sin(upwind) * travel);
        w.phase_rad = random.uniform(0.0, 2.0 * kPi);

        // Finch (GPU Gems 1 ch. 1): Q_i = choppiness / (k_i A_i N) clamped to [0, 1], so Q_i A_i k_i <= choppiness / N.
        const double ak = w.amplitude_m * k;
        w.steepness = qakEach >= ak ? 1.0 : qakEach / ak;
    }
    return waves;
}

std::string validateOceanParams(const OceanParams& params) {
    if (!(params.fade_end > params.fade_start)) {
        std::ostringstream message;
        message << "ocean.fade_end (" << params.fade_end << ") must be greater than ocean.fade_start ("
                << params.fade_start << "): Michelic Eq. 11 needs e1 > e0";
        return message.str();
    }
    return "";
}

}  // namespace planet::ocean
