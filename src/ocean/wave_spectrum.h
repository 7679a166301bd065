// A set of spherical Gerstner waves generated from wind, fetch and a seed (OceanParams).
//
// Wavelengths and amplitudes sample a standard sea spectrum S(omega) (m^2 s):
//  - fully developed (fetch_km == 0): Pierson-Moskowitz (Pierson & Moskowitz 1964),
//      S = alpha g^2 w^-5 exp(-5/4 (w_p / w)^4),  alpha = 8.1e-3,  w_p = 0.855 g / U;
//  - fetch limited: JONSWAP (Hasselmann et al. 1973), the same times gamma^r with
//      r = exp(-(w - w_p)^2 / (2 sigma^2 w_p^2)), gamma = 3.3, sigma = 0.07 (w <= w_p) or 0.09,
//      alpha = 0.076 (U^2 / (F g))^0.22,  w_p = 22 (g^2 / (U F))^(1/3),
//    with F capped where w_p reaches Pierson-Moskowitz's (g F / U^2 = (22 / 0.855)^3, about
//    17000): the fits are for growing seas, and a longer fetch does not grow the sea further.
// The range from 0.5 w_p (below which the spectrum holds under exp(-20) of its energy) to
// the deep-water frequency of min_wavelength_m is cut into wave_count strata of equal width in
// log(omega), one wave each. A wave's amplitude is A = sqrt(2 S dw) with S dw the stratum's
// whole energy (trapezoid rule, >= 2048 sub-intervals over the range), and its frequency is
// drawn from S within the stratum. So sum A^2 / 2 is the spectrum's variance m0 for any
// wave_count (even 1), and short waves keep their share of slope (they are as many per octave
// as long ones). Wavelength and speed follow deep-water dispersion, w^2 = g k.
//
// Directions: at the wind point each wave travels along the wind bearing plus a random angle
// drawn from a normal of std. deviation directional_spread_deg truncated to +-90 deg (drawing
// the direction from the spreading function D(theta) gives each wave its whole S(w) dw: the
// spreading's share is 1). Neighbouring frequencies get opposite angles (antithetic pairs),
// so that even a few waves are centred on the wind. Each wave's origin o_i lies upwind of the
// wind point on the great circle along its direction, 20 to 60 deg of arc away, so that near
// the wind point the waves run downwind and far from it their directions differ, as swell's do
// (most among their antipodes, 120 to 160 deg downwind, where they converge from all sides).
// Phases are uniform in [0, 2 pi).
//
// Steepness: Q_i = choppiness / (k_i A_i N) clamped to [0, 1] (Finch, GPU Gems 1 ch. 1), so
// that sum Q_i A_i k_i <= choppiness <= 1: the horizontal Jacobian of Eq. 8 stays >= 0 (no
// loops at the crests; at a sum of exactly 1, a cusp at most).
//
// Deterministic: the same OceanParams give bit-identical waves (splitmix64, our own uniform and
// normal draws: std:: distributions differ between standard libraries). Another libm may round
// exp, log and pow differently in the last bit, nothing more.
#pragma once

#include <string>
#include <vector>

#include "ocean/ocean_params.h"
#include "ocean/waves.h"

namespace planet::ocean {

// The waves for these parameters, in order of increasing frequency; empty when
// wave_count <= 0. Inputs outside their documented ranges are clamped (choppiness to
// [0, 1], spread to [0, 180] deg, ...) so that the result always passes validateWaves;
// validateOceanParams and the preset table report them.
std::vector<GerstnerWave> generateWaves(const OceanParams& params);

// One-sided spectral density of the sea the parameters describe (Pierson-Moskowitz or
// JONSWAP as above), m^2 s, at angular frequency omega (rad/s, > 0).
double waveSpectrum(const OceanParams& params, double omega);

// Peak angular frequency w_p of that spectrum, rad/s.
double spectrumPeakFrequency(const OceanParams& params);

// Significant wave height of a wave set, 4 sqrt(sum A_i^2 / 2), m.
double significantWaveHeight(const std::vector<GerstnerWave>& waves);

// The cross-field rules a single parameter's range cannot express, "" when they hold,
// else a message naming the parameters:
//   - ocean.fade_end > ocean.fade_start (Michelic Eq. 11 needs e1 > e0).
// Each field's own range is the preset table's job.
std::string validateOceanParams(const OceanParams& params);

}  // namespace planet::ocean
