#include "atmosphere/energy_balance.h"

#include <algorithm>
#include <cmath>

namespace planet::atmosphere {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The smallest scale height of the exponential profiles that hold any particles (km);
// the limb quadrature must resolve it.
double smallestScaleHeight(const AtmosphereParameters& a) {
    double smallest = a.top_radius - a.bottom_radius;
    auto consider = [&](const DensityProfile& p, const glm::dvec3& coefficient) {
        if (glm::max(coefficient.x, glm::max(coefficient.y, coefficient.z)) <= 0.0) return;
        for (const DensityProfileLayer& l : p.layers)
            if (l.exp_term != 0.0 && l.exp_scale < 0.0) smallest = std::min(smallest, -1.0 / l.exp_scale);
    };
    consider(a.rayleigh_density, a.rayleigh_scattering);
    consider(a.mie_density, a.mie_extinction);
    return smallest;
}

// Midpoint rule over t in [0, 1] of a map t -> b with derivative db/dt: the b of
// each sample and its weight db.
struct Node {
    double b, db;
};

}  // namespace

EnergyBalance measureEnergyBalance(const AtmosphereParameters& atmosphere, const AtmosphereTables& tables,
                                   const EnergyQuadrature& q) {
    Model model(tables.sizes);
    const double R = atmosphere.bottom_radius, Rt = atmosphere.top_radius, thickness = Rt - R;

    // Impact parameters. Ground rays: b = R (1 - (1 - t)^2), denser towards the limb.
    // Limb rays: altitude b - R geometric from h0 to the thickness, plus one node in [0, h0].
    std::vector<Node> ground, limb;
    for (int i = 0; i < q.groundRays; ++i) {
        const double t = (i + 0.5) / q.groundRays, s = 1.0 - t;
        ground.push_back({R * (1.0 - s * s), 2.0 * R * s / q.groundRays});
    }
    const double h0 = std::min(1e-4 * thickness, 0.05 * smallestScaleHeight(atmosphere));
    limb.push_back({R + 0.5 * h0, h0});
    const double logRatio = std::log(thickness / h0);
    for (int i = 0; i < q.limbRays; ++i) {
        const double h = h0 * std::exp(logRatio * (i + 0.5) / q.limbRays);
        limb.push_back({R + h, h * logRatio / q.limbRays});
    }

    const glm::dvec3 sun(0.0, 0.0, 1.0);
    const glm::dvec3 E = atmosphere.solar_irradiance;
    auto safeDivide = [](const glm::dvec3& a, const glm::dvec3& b) {
        return glm::dvec3(b.x > 0 ? a.x / b.x : 0.0, b.y > 0 ? a.y / b.y : 0.0, b.z > 0 ? a.z / b.z : 0.0);
    };

    // Scattered and ground-reflected light leaving the top sphere: sum of L b db dphi d(mu_s).
    glm::dvec3 scattered(0.0), reflected(0.0);
    const double dMuS = 2.0 / q.sunCosines, dPhi = kPi / q.azimuths;
    for (int k = 0; k < q.sunCosines; ++k) {
        const double muS = -1.0 + (k + 0.5) * dMuS;
        const double sinS = std::sqrt(std::max(0.0, 1.0 - muS * muS));
        const glm::dvec3 n(sinS, 0.0, muS);      // the point's zenith
        const glm::dvec3 t1(muS, 0.0, -sinS);    // tangent in the sun's plane
        const glm::dvec3 t2(0.0, 1.0, 0.0);
        const glm::dvec3 camera = Rt * n;
        for (int j = 0; j < q.azimuths; ++j) {
            const double phi = (j + 0.5) * dPhi;
            const glm::dvec3 tangent = std::cos(phi) * t1 + std::sin(phi) * t2;
            for (const std::vector<Node>* nodes : {&ground, &limb}) {
                for (const Node& node : *nodes) {
                    const double sinT = node.b / Rt, cosT = std::sqrt(std::max(0.0, 1.0 - sinT * sinT));
                    const glm::dvec3 view = -(sinT * tangent + cosT * n);  // looking in, light going out
                    glm::dvec3 transmittance;
                    const glm::dvec3 L = model.GetSkyRadiance(atmosphere, tables.transmittance, tables.scattering,
                                                              tables.singleMie, camera, view, sun, transmittance);
                    const double w = node.b * node.db * dPhi * dMuS;
                    scattered += L * w;
                    if (nodes == &ground && model.RayIntersectsGround(atmosphere, Rt, -cosT)) {
                        const double d = model.DistanceToBottomAtmosphereBoundary(atmosphere, Rt, -cosT);
                        const glm::dvec3 p = camera + view * d;
                        glm::dvec3 sky;
                        const glm::dvec3 sunIrradiance = model.GetSunAndSkyIrradiance(
                            atmosphere, tables.transmittance, tables.irradiance, p, glm::normalize(p), sun, sky);
                        const glm::dvec3 T =
                            model.GetTransmittance(atmosphere, tables.transmittance, Rt, -cosT, d, true);
                        reflected += atmosphere.ground_albedo / kPi * (sunIrradiance + sky) * T * w;
                    }
                }
            }
        }
    }
    // 2 pi from the sphere's area, 2 from the azimuth's mirror half; over E pi Rt^2.
    const double toFraction = 2.0 * kPi * 2.0 / (kPi * Rt * Rt);
    EnergyBalance balance;
    balance.scattered = safeDivide(scattered * toFraction, E);
    balance.ground = safeDivide(reflected * toFraction, E);

    // Direct light: the chord at impact b is twice the way from its lowest point (r = b,
    // mu = 0) to the top, so its transmittance is that table value squared.
    glm::dvec3 direct(0.0);
    for (const Node& node : limb) {
        const glm::dvec3 T = model.GetTransmittanceToTopAtmosphereBoundary(atmosphere, tables.transmittance, node.b, 0.0);
        direct += T * T * 2.0 * kPi * node.b * node.db;
    }
    balance.direct = direct / (kPi * Rt * Rt);

    // Absorbed by the ground: 2 pi R^2 int (1 - albedo) (direct + sky) d(mu_s).
    glm::dvec3 absorbed(0.0);
    for (int k = 0; k < q.groundCosines; ++k) {
        const double muS = -1.0 + (k + 0.5) * 2.0 / q.groundCosines;
        const glm::dvec3 p = R * glm::dvec3(std::sqrt(std::max(0.0, 1.0 - muS * muS)), 0.0, muS);
        glm::dvec3 sky;
        const glm::dvec3 sunIrradiance =
            model.GetSunAndSkyIrradiance(atmosphere, tables.transmittance, tables.irradiance, p, p / R, sun, sky);
        absorbed += (glm::dvec3(1.0) - atmosphere.ground_albedo) * (sunIrradiance + sky) * (2.0 / q.groundCosines);
    }
    balance.absorbed = safeDivide(absorbed * 2.0 * kPi * R * R, E * (kPi * Rt * Rt));
    return balance;
}

}  // namespace planet::atmosphere
