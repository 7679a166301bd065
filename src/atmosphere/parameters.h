// From the user's atmosphere parameters (SI, preset) to the model's
// AtmosphereParameters (km, 1/km), the struct shared by GPU and CPU code.
#pragma once

#include <string>
#include <vector>

#include "atmosphere/model.h"
#include "scene/scene.h"

namespace planet::atmosphere {

// The model's top_radius is the preset's atmosphere.top_radius_km, or lower where
// the air has ended: see airThicknessKm.
AtmosphereParameters makeAtmosphereParameters(const Scene& scene);

// The optical depth above the top of the air the model keeps (see airThicknessKm).
constexpr double kNegligibleOpticalDepth = 1e-9;

// The thickness of the atmosphere the tables cover, km: the preset's
// top_radius_km - planetRadiusKm, cut where every species has ended: above the
// altitude H ln(beta H / 1e-9) an exponential profile (scattering or extinction
// beta at the ground, scale height H) leaves a vertical optical depth under 1e-9
// (1e-6 along the grazing ray of a 1000-fold longer way), and ozone ends at the
// top of its tent. The tables parametrize altitude over the whole thickness, so
// a top far above the air (200 000 km over 8 km of scale height) would leave the
// air inside the first texel and the quadrature along rays stepping over it; the
// air that is cut off changes no transmittance by more than 1e-6.
// Never cut below minAtmosphereThicknessKm(planetRadiusKm).
double airThicknessKm(const AtmosphereParams& atmosphere, double planetRadiusKm);

// ---- Where the precomputed tables hold (docs/ATMOSPHERE_RANGES.md) ----
//
// The model runs in single precision on the GPU with positions in km, and its
// tables are read with float texture coordinates. Measured against the double
// reference (tests/test_atmosphere_edges.cpp) the tables agree within the
// atmosphere tests' tolerance inside these limits and not beyond them. They bind
// only an atmosphere that holds particles: a vacuum has nothing to get wrong.
//
// A planet radius within [300, 30000] km: floats in km are 2 m apart at 30 000 km
// (rays grazing the ground then miss it by metres: 1.6 % off at 100 000 km, 1.9 %
// at 50 000 km with 1.5 km scale heights), and a planet under 300 km is too small
// for the ground half of the view-angle axis (a 100 km planet: 2.8 % off).
constexpr double kMinAtmospherePlanetRadiusKm = 300.0;
constexpr double kMaxAtmospherePlanetRadiusKm = 30000.0;
// Scale heights at least 3e-5 of the radius (0.19 km at 6360 km, 0.9 km at 30 000
// km): the float positions of grazing rays (0.5 m at 6360 km) must be small
// against the layer (0.05 km at 6360 km: 1.7 % off; 0.2 km at 20 000 km: 2.4 %).
constexpr double kMinScaleHeightPerRadius = 3e-5;
// A thickness of at least 1 km and 1e-4 of the radius (3 km at 30 000 km): the
// table's altitude axis must span more than a few float steps (0.1 km: 3.9 % off).
constexpr double kMinAtmosphereThicknessKm = 1.0;
constexpr double kMinAtmosphereThicknessPerRadius = 1e-4;
// At most optical depth 60 along the horizontal ray from the ground to space, in
// every channel: the ray grazing the ground from the top of the atmosphere crosses
// twice that, which the table's fourth root of the transmittance still holds in a
// float (exp(-120 / 4)), and the lookups still agree with the double reference
// (ozone at 114: 100 % off in places, Rayleigh and Mie hold to 160). Earth: 9.9,
// the shipped hazy preset: 50.3.
constexpr double kMaxHorizontalOpticalDepth = 60.0;

double minAtmosphereThicknessKm(double planetRadiusKm);
double minScaleHeightKm(double planetRadiusKm);

// Optical depth of the horizontal ray from the ground to the top of the atmosphere,
// per channel, of each species (rayleigh, mie extinction, ozone) and in total.
struct HorizontalOpticalDepth {
    glm::dvec3 rayleigh{0.0}, mie{0.0}, ozone{0.0};
    glm::dvec3 total() const { return rayleigh + mie + ozone; }
};
HorizontalOpticalDepth horizontalOpticalDepth(const AtmosphereParameters& atmosphere);

// The limits above as (field, message) problems, blamed on the parameter to change;
// empty when the scene's atmosphere is within them. Expects every parameter in its
// table range and top_radius_km above radius_km (validateScene checks those first).
struct AtmosphereLimitProblem {
    std::string field;
    std::string message;
};
std::vector<AtmosphereLimitProblem> checkAtmosphereLimits(const Scene& scene);

// Exponential profile exp(-h / H) (Elek Eq. 8, Sperlhofer Eq. 2-5); H in km.
DensityProfile exponentialProfile(double scaleHeightKm);
// Tent profile: 1 at peakKm, falling linearly to 0 at peakKm +- widthKm / 2.
DensityProfile tentProfile(double peakKm, double widthKm);
// No particles at all.
DensityProfile emptyProfile();

}  // namespace planet::atmosphere
