// Optics of sea water, shared by the ocean surface and the underwater pass.
//
// Extinction per metre for R, G, B (680, 550, 440 nm): pure water's absorption (Pope &
// Fry 1997: 0.45, 0.057, 0.0066 1/m) plus a little scattering by particles, so clear
// coastal water: red is gone after a few metres, blue reaches tens of metres.
const vec3 WATER_EXTINCTION_PER_M = vec3(0.46, 0.075, 0.035);
// Radiance leaving deep water per unit irradiance over pi: the light scattered back up
// from the water body, dark blue (open-ocean remote-sensing reflectance of a few per cent
// in blue, under one in red).
const vec3 DEEP_WATER_ALBEDO = vec3(0.002, 0.012, 0.03);
const float WATER_F0 = 0.02;                    // normal-incidence reflectance, n = 1.333
// Ground this far below the sea surface is dark: the light that reaches it has crossed at least
// this much water (straight down; the sun's and the sky's paths are longer), which leaves under
// a millionth of it in every channel (exp(-0.035 x 400) = 8e-7, blue), and seen from above the
// sea the way back up takes as much again. The surface light and the terrain's shadow do no work
// there (most of the sea floor seen from orbit).
const float SEA_FLOOR_DARK_DEPTH_M = 400.0;

vec3 waterTransmittanceAlong(float pathM) { return exp(-WATER_EXTINCTION_PER_M * pathM); }

// The light that reaches a point depthM below the sea surface, from the sun's and the sky's
// irradiance just above it: the sun's beam along its refracted path (Snell, n = 1.333), the
// sky's diffuse light along depth / 0.85 (the mean cosine of light refracted into water from a
// uniform sky). The sea floor and anything else under water is lit by this, not by the light
// in air: 10 km down it is dark.
void lightUnderWater(float depthM, float cosSunZenith, inout vec3 sunIrradiance, inout vec3 skyIrradiance) {
    if (depthM <= 0.0) return;
    float sinRefracted = sqrt(max(0.0, 1.0 - cosSunZenith * cosSunZenith)) / 1.333;
    float cosRefracted = sqrt(1.0 - sinRefracted * sinRefracted);  // >= 0.66
    sunIrradiance *= waterTransmittanceAlong(depthM / cosRefracted);
    skyIrradiance *= waterTransmittanceAlong(depthM / 0.85);
}

vec3 deepWaterRadiance(vec3 irradiance) { return DEEP_WATER_ALBEDO / PI * irradiance; }

// Sea foam: a diffuse white of about 0.6 (whitecaps' reflectance in the visible, 0.4-0.7:
// Whitlock, Bartlett & Gurney 1982; Koepke 1984), lit as a horizontal surface.
const float FOAM_ALBEDO = 0.6;
vec3 foamRadiance(vec3 irradiance) { return FOAM_ALBEDO / PI * irradiance; }

// Schlick's approximation of the Fresnel reflectance of water for incidence cosine c.
float waterFresnel(float c) {
    float m = 1.0 - clamp(c, 0.0, 1.0);
    return WATER_F0 + (1.0 - WATER_F0) * m * m * m * m * m;
}

// Sun glitter: radiance towards `toViewer` per unit solar irradiance at the surface, for a
// sea whose unresolved facets have isotropic Gaussian slopes of total variance
// slopeVariance around `normal` (Bruneton et al. 2010, Eq. 14:
// F p(zeta_h) / (4 cos(theta_v) cos^4(theta_h))).
float sunGlitter(vec3 normal, vec3 toViewer, vec3 toSun, float slopeVariance) {
    vec3 h = normalize(toViewer + toSun);
    float cosH = max(dot(h, normal), 1e-3);
    float cosV = max(dot(toViewer, normal), 1e-3);
    float sigma2 = 0.5 * slopeVariance;  // per axis
    float tan2 = (1.0 - cosH * cosH) / (cosH * cosH);
    float p = exp(-0.5 * tan2 / sigma2) / (2.0 * PI * sigma2);
    return waterFresnel(dot(h, toViewer)) * p / (4.0 * cosV * cosH * cosH * cosH * cosH);
}
