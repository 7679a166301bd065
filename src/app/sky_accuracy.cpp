#include "app/sky_accuracy.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scene/toml_error.h"

namespace planet {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDaylightMaxSunZenithDeg = 80.0;
constexpr double kHorizonBandDeg = 2.0;

SkyErrorSummary summarize(std::vector<std::pair<double, std::size_t>> errors) {
    SkyErrorSummary s;
    s.rays = errors.size();
    if (errors.empty()) return s;
    std::sort(errors.begin(), errors.end());
    const std::size_t n = errors.size();
    s.median = n % 2 ? errors[n / 2].first : 0.5 * (errors[n / 2 - 1].first + errors[n / 2].first);
    s.worst = errors.back().first;
    s.worstRow = errors.back().second;
    return s;
}

std::string describeClass(const char* name, const SkyErrorSummary& s, const std::vector<ProbeResultRow>& rays) {
    char text[256];
    if (s.rays == 0) {
        std::snprintf(text, sizeof text, "%s: no rays", name);
        return text;
    }
    const ProbeRow& w = rays[s.worstRow].ray;
    std::snprintf(text, sizeof text,
                  "%s: %zu rays, median %.4g %%, worst %.4g %% (row %zu: altitude %s m, sun zenith %s, view zenith %s, "
                  "azimuth %s deg)",
                  name, s.rays, 100.0 * s.median, 100.0 * s.worst, s.worstRow + 1, w.text[0].c_str(),
                  w.text[1].c_str(), w.text[2].c_str(), w.text[3].c_str());
    return text;
}

}  // namespace

SkyRayClass classifySkyRay(const ProbeRow& ray, double planetRadiusM) {
    // The horizon's dip below the horizontal from altitude h: acos(R / (R + h)).
    const double dipDeg = std::acos(planetRadiusM / (planetRadiusM + ray.altitudeM)) * 180.0 / kPi;
    const bool aboveHorizon = ray.viewZenithDeg < 90.0 + dipDeg - kHorizonBandDeg;
    return ray.sunZenithDeg <= kDaylightMaxSunZenithDeg && aboveHorizon ? SkyRayClass::Daylight
                                                                        : SkyRayClass::TwilightOrHorizon;
}

double skyRadianceError(const ProbeResultRow& got, const ProbeResultRow& reference) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(got.radiance[c] - reference.radiance[c]) /
                                    std::max(reference.radiance[c], kSkyAccuracyFloorPerSr));
    return worst;
}

SkyAccuracy compareSkyProbes(const std::vector<ProbeResultRow>& got, const std::vector<ProbeResultRow>& reference,
                             double planetRadiusM) {
    if (got.size() != reference.size())
        throw InputError("the probe has " + std::to_string(got.size()) + " rays and the reference " +
                         std::to_string(reference.size()) + ": not the same rays");
    std::vector<std::pair<double, std::size_t>> daylight, twilight;
    std::size_t dark = 0;
    for (std::size_t i = 0; i < got.size(); ++i) {
        const ProbeRow &a = got[i].ray, &b = reference[i].ray;
        if (a.altitudeM != b.altitudeM || a.sunZenithDeg != b.sunZenithDeg || a.viewZenithDeg != b.viewZenithDeg ||
            a.viewAzimuthDeg != b.viewAzimuthDeg)
            throw InputError("row " + std::to_string(i + 1) + " is not the same ray in the probe and the reference");
        const glm::dvec3& ref = reference[i].radiance;
        if (std::max({ref.r, ref.g, ref.b}) < kSkyAccuracyFloorPerSr) {
            ++dark;
            continue;
        }
        const double error = skyRadianceError(got[i], reference[i]);
        (classifySkyRay(a, planetRadiusM) == SkyRayClass::Daylight ? daylight : twilight).emplace_back(error, i);
    }
    return {summarize(std::move(daylight)), summarize(std::move(twilight)), dark};
}

std::string describe(const SkyAccuracy& accuracy, const std::vector<ProbeResultRow>& rays) {
    return describeClass("daylight", accuracy.daylight, rays) + "\n" +
           describeClass("twilight or horizon", accuracy.twilightOrHorizon, rays) + "\n" +
           std::to_string(accuracy.darkRays) + " rays with no light in the reference (not compared)";
}

}  // namespace planet
