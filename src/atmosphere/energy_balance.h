// The planet's energy balance read from a set of atmosphere tables: where the
// sunlight that reaches the atmosphere goes (tests/test_atmosphere_edges.cpp).
//
// Sun along +z, parallel light of irradiance E (atmosphere.solar_irradiance).
// The power that crosses the top of the atmosphere inwards is E pi R_top^2
// (R_top = atmosphere.top_radius). Of it, at most all can leave again:
//
//   scattered  the sky radiance the tables give for a camera on the top sphere
//              looking down (GetSkyRadiance: light scattered out of the
//              atmosphere, every order the tables hold, ground bounces between
//              orders included), integrated over the whole top sphere and over
//              each point's outward hemisphere with the cosine:
//                P = int_sphere dA int_hemisphere L cos(theta) dw.
//              By the symmetry about the sun axis dA = 2 pi R_top^2 d(mu_s), and
//              with the impact parameter b = R_top sin(theta) (the ray's distance
//              from the planet's centre) cos(theta) dw = b db dphi / R_top^2, so
//                P = 2 pi int d(mu_s) int dphi int L b db.
//   ground     the ground's own reflection (Lambertian, atmosphere.ground_albedo,
//              lit by sun and sky through GetSunAndSkyIrradiance) seen through
//              the air from the same cameras: what GetSkyRadiance leaves out;
//   direct     sunlight crossing the atmosphere without scattering: the rays at
//              impact b > R_ground through the transmittance of their chord,
//                P = E int T(b) 2 pi b db;
//   absorbed   what the ground absorbs of the sun and sky light reaching it,
//              (1 - ground albedo) (E T mu_s + sky irradiance) over the ground
//              sphere, 2 pi R_ground^2 int d(mu_s).
//
// Each is returned as a fraction of E pi R_top^2 per channel. Energy
// conservation demands scattered + ground + direct + absorbed <= 1 (the rest is
// absorbed in the air by ozone and aerosols, or lost to orders the tables do not
// hold), and so the planetary (Bond) albedo, scattered + ground, is at most 1;
// the first is the tighter bound: with the ground's share counted, a pure
// scattering atmosphere over Earth's ground sums to about 0.9. A model that
// overestimates scattering (a quadrature that steps over the air, a table that
// smears it) breaks the bound; a correct one meets it for any parameters.
//
// The tables end at the lowest sun they cover (mu_s_min) and the lookups fade
// to night below it, so light leaving the night side beyond that is not
// counted: the figures are lower bounds there, which keeps the bound a bound.
#pragma once

#include <glm/glm.hpp>

#include "atmosphere/model.h"
#include "atmosphere/tables.h"

namespace planet::atmosphere {

struct EnergyBalance {
    glm::dvec3 scattered{0.0};
    glm::dvec3 ground{0.0};
    glm::dvec3 direct{0.0};
    glm::dvec3 absorbed{0.0};
    glm::dvec3 albedo() const { return scattered + ground; }
    glm::dvec3 total() const { return scattered + ground + direct + absorbed; }
};

struct EnergyQuadrature {
    int sunCosines = 48;  // points of the top sphere, uniform in mu_s (equal areas)
    int azimuths = 24;    // phi over [0, pi] (mirror symmetry doubles it)
    int groundRays = 32;  // impact parameters b in [0, R_ground], denser towards the limb
    int limbRays = 96;    // b in [R_ground, R_top], geometric in altitude from 1e-4 of the thickness
    int groundCosines = 256;  // points of the ground sphere for `absorbed`, uniform in mu_s
};

EnergyBalance measureEnergyBalance(const AtmosphereParameters& atmosphere, const AtmosphereTables& tables,
                                   const EnergyQuadrature& quadrature = {});

}  // namespace planet::atmosphere
