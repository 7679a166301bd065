// From the user's atmosphere parameters (SI, preset) to the model's
// AtmosphereParameters (km, 1/km), the struct shared by GPU and CPU code.
#pragma once

#include "atmosphere/model.h"
#include "scene/scene.h"

namespace planet::atmosphere {

AtmosphereParameters makeAtmosphereParameters(const Scene& scene);

// Exponential profile exp(-h / H) (Elek Eq. 8, Sperlhofer Eq. 2-5); H in km.
DensityProfile exponentialProfile(double scaleHeightKm);
// Tent profile: 1 at peakKm, falling linearly to 0 at peakKm +- widthKm / 2.
DensityProfile tentProfile(double peakKm, double widthKm);
// No particles at all.
DensityProfile emptyProfile();

}  // namespace planet::atmosphere
