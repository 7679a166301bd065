// The unified march of clouds and atmosphere along a view ray (Michelic §5, Eq. 15-20):
// the one function that decides what lies between a viewpoint and a surface point, or
// space. Include after atmosphere/interface.glsl.
//
// Outside the cloud layer a slice of the ray is one atmosphere lookup (T_A, I_A); each
// crossing of the layer (a ray crosses it at most twice: fig. 12) is cut into
// clouds.atmosphereSlices slices, and in each the clouds are marched in small steps (large
// ones where the volume says there is no cloud near, fig. 9, and past the whole clear sky where
// the weather map has no coverage: CloudClearDistance) for T_C and I_C (Eq. 15-16);
// slices are combined front to back by Eq. 19-20, so air in front of a cloud reddens and
// veils it and a cloud hides the air behind it. Without clouds (clouds.enabled 0) it is the
// clear-sky lookup, exactly.
//
// Light at a cloud sample: the sun's irradiance through the atmosphere to that point (red
// at sunset, none at night) times the clouds' transmittance towards the sun
// (clouds.sunSamples samples, Michelic's T_sun) times the phase function, plus the sky's
// irradiance at the sample's altitude from the upper hemisphere (radiance E / (2 pi) per
// unit scattering: an isotropic phase over the half sphere the sky fills). Options:
// Wrenninge's multiple-scattering octaves (octave i: a^i of the light, phase g c^i,
// optical depth to the sun b^i, a = b = c = 1/2) and the "powder" darkening of sunlit edges;
// with both off the march is Eq. 15-16 (with energyConservingStep 0, Eq. 16 as written).
//
// Written in the subset of GLSL that is also C++ (as cloud_density.glsl):
// src/clouds/cloud_reference.h compiles it in double, with the interface's functions
// (AirRay, SkyRadianceOfRay, SkyRadianceToPointOfRay) bound to the atmosphere's CPU model.

// The far field's slices: a crossing whose nearest point the pixel sees in the clouds' far field
// (CloudFarBlend 1: the clouds there are their mean over a footprint of 8 voxels or more) takes one
// slice per CLOUD_FAR_FIELD_SLICE_KM of its length, at most the preset's. The slices interleave
// the air inside the crossing with the clouds (Eq. 19-20); where the clouds are a smooth mean, the
// air of a short crossing matters little where it lies among them: from orbit the rays looking
// down cross the 2.5 km layer in under 10 km (a few hundredths of optical depth of air), while the
// grazing rays near the limb, hundreds of km in the layer, keep their slices. From orbit and space
// the frames move by 0.1 % on average (tests/test_cloud_far_field.cpp); the sky march at `orbit`,
// 1280x720 on llvmpipe, 35-39 -> 26 ms (four slices, each one or two air lookups, were most of its
// cost). Near the camera, and for the far clouds seen from below (long crossings), as before.
const Length CLOUD_FAR_FIELD_SLICE_KM = 10.0;

// How finely a caller marches: the sky pass gives the preset's (MarchQualityOf), the sea's
// reflection less (ocean/sea_light.frag), the probes the preset's with jitter 1/2.
struct MarchQuality {
    int slicesPerCrossing;  // atmosphere slices per crossing of the layer (Eq. 17-18)
    int stepBudget;         // small cloud steps at most, over the whole ray
    int sunSamples;         // density samples towards the sun for T_sun
    Number jitter;          // in [0, 1): where in each step it is sampled (1/2: the midpoint)
    Length minFootprintKm;  // the smallest footprint the density is seen with (> 0: the far field)
};

// The preset's march, with the given jitter.
MarchQuality MarchQualityOf(Number jitter) {
    MarchQuality q;
    q.slicesPerCrossing = clouds.atmosphereSlices;
    q.stepBudget = clouds.maxSteps;
    q.sunSamples = clouds.sunSamples;
    q.jitter = jitter;
    q.minFootprintKm = 0.0;
    return q;
}

struct CloudSegmentResult {
    vec3 transmittance;
    vec3 inscatter;
    int steps;      // small steps taken (in or near clouds)
    int skipped;    // large steps taken through empty space
    Length depthSum;  // sum of each step's distance along the ray times the opacity it added (cloud T)
    Length reached;   // where the march stopped: past `end` where a step through empty space crossed it
};

// Radiance scattered towards the viewer per unit scattering coefficient at a cloud sample.
vec3 CloudSource(vec3 point, vec3 sun, Number cosTheta, Number density, Length footprintKm, int sunSamples) {
    AtmosphereParameters atmosphere = atmosphereParameters();
    Length r = length(point);
    Number muS = dot(point, sun) / r;
    vec3 sunlight = atmosphere.solar_irradiance * GetTransmittanceToSun(atmosphere, transmittance_texture, r, muS);
    Length opticalDepth = CloudDensityPathToSun(point, sun, Number(clouds.sunSamples) * clouds.sunStep, footprintKm,
                                                sunSamples, false);  // density x km
    vec3 light = vec3(0.0);
    Number a = 1.0;
    Number b = 1.0;
    Number c = 1.0;
    for (int octave = 0; octave < clouds.multipleScatteringOctaves; ++octave) {
        Number phase = CloudPhase(clouds.phaseGForward * c, clouds.phaseGBack * c, clouds.phaseBackWeight, cosTheta);
        light += a * phase * exp(-clouds.extinction * b * opticalDepth) * sunlight;
        a *= 0.5;
        b *= 0.5;
        c *= 0.5;
    }
    // Schneider's powder: sunlit edges, where little cloud lies towards the sun, look darker.
    light *= mix(1.0, 1.0 - exp(-2.0 * clouds.extinction * (opticalDepth + density * clouds.stepKm)), clouds.powder);
    vec3 sky = GetIrradiance(atmosphere, irradiance_texture, r, muS) * NightFade(atmosphere, muS);
    return light + sky / (2.0 * PI);
}

// Eq. 15-16 from `start` to `end` km along `dir` from `origin` (km from the planet centre),
// at most `budget` small steps; from `from` on (>= start: what lies before it is known to be
// empty, the previous segment's step through empty space having crossed it).
CloudSegmentResult MarchCloudSegment(vec3 origin, vec3 dir, Length start, Length from, Length end, vec3 sun,
                                     int budget, MarchQuality quality) {
    CloudSegmentResult result;
    result.transmittance = vec3(1.0);
    result.inscatter = vec3(0.0);
    result.steps = 0;
    result.skipped = 0;
    result.depthSum = 0.0;
    Number cosTheta = dot(dir, sun);
    // The step grows where the budget could not cross the segment at clouds.stepKm, and
    // with the pixel's footprint (half of it) where the far field smooths the clouds.
    Length step = max(clouds.stepKm, (end - start) / Number(max(budget, 1)));
    Length fromCamera = length(origin - clouds.cameraFromCentre);  // the sea's reflected rays start away from it
    // Each step [t, t + dt] is sampled a fraction `jitter` of the way in (1/2: the midpoint
    // rule): neighbouring pixels sample at different depths, which turns the steps' banding
    // into fine noise, and the steps still cover the segment.
    // Inside dense cloud the step shortens so that each step's optical depth stays about 1/2
    // (down to an eighth of the step, from the last sample's density): an opaque step would
    // put the cloud's surface at one of its ends and show the steps as bands or grain.
    Length t = from;
    Number previous = 0.0;
    bool weatherClear = true;  // the last sample's weather had no coverage (CloudDensityAndClearAt); at first,
                               // read the clear sky even in a border (a border's short step before each long one
                               // took the `ground` view's march from 40 to 59 ms)
    for (int i = 0; i < 4 * clouds.maxSteps && t < end; ++i) {
        Length footprint = max((fromCamera + t) * clouds.pixelAngle, quality.minFootprintKm);
        // Where the footprint grows the step (the far field), at least 16 samples across the
        // layer's depth still, so that a narrow vertical profile (stratus) is resolved.
        Number mu = abs(dot(dir, origin + dir * t)) / length(origin + dir * t);
        Length across = (clouds.topRadius - clouds.bottomRadius) / (16.0 * max(mu, Number(1e-3)));
        Length dt = min(min(max(step, 0.5 * footprint), max(across, step)), end - t);
        if (previous > 0.0) dt = min(dt, max(0.5 / (clouds.extinction * previous), step / 8.0));
        vec3 point = origin + dir * (t + quality.jitter * dt);
        // The sample stands for its whole step: the volume is read filtered over the step's length
        // where that is longer than the pixel's footprint (a grazing ray whose budget stretched its
        // steps, far cloud tops at the horizon), else the steps sample the volume's detail a few
        // voxels apart, the same few voxels in neighbouring pixels, and their jitter showed as a
        // regular stipple along the far tops (the `clouds` view).
        footprint = max(footprint, dt);
        Length clear;
        Number density = CloudDensityAndClearAt(point, footprint, weatherClear, clear);
        if (clear > 0.0) {  // a clear sky around (the weather's coverage 0): on past it, at least a step
            t += quality.jitter * dt + max(clear, (1.0 - quality.jitter) * dt);
            result.skipped += 1;
            previous = 0.0;
            continue;
        }
        if (density < 0.0) {  // no cloud within the zero-density border: one large step
            t += quality.jitter * dt + max(clouds.largeStepKm, step);
            result.skipped += 1;
            previous = 0.0;
            continue;
        }
        previous = density;
        if (density > 0.0) {
            vec3 source = CloudSource(point, sun, cosTheta, density, footprint, quality.sunSamples);
            Number before = result.transmittance.x;  // the clouds' extinction is grey
            CloudMarchStep(density, dt, clouds.extinction, clouds.scattering, source, clouds.energyConservingStep != 0,
                           result.transmittance, result.inscatter);
            result.depthSum += (before - result.transmittance.x) * (t + quality.jitter * dt);
        }
        t += dt;
        result.steps += 1;
        if (result.steps >= budget || max(result.transmittance.x, max(result.transmittance.y, result.transmittance.z)) < 1e-4)
            break;
    }
    result.reached = t;
    return result;
}

struct ViewMarch {
    vec3 transmittance;  // from the viewpoint to the end of the ray
    vec3 inscatter;      // light added on the way (air and clouds)
    int steps;
    int skipped;
    Number cloudOpacity;   // 1 - the clouds' own transmittance along the ray (air not counted)
    Length cloudDistance;  // where along the ray the clouds are, km: each step's distance weighted by
                           // the opacity it added (the temporal march reprojects clouds from there); 0: none
};

// The air ray from the point `t` km along the ray: from a viewpoint inside the atmosphere itself
// (t = 0, `inside`) by its up and altitude (exact from centimetres above the ground, where
// `origin`'s float length is rounded to half a metre), else by position (from space as before:
// the altitude form changed the space reference view's mean luminance by 2 %, cause not
// found). One ray either way (AirRay), so each slice is one lookup.
ViewRay AirRayFrom(vec3 up, Length altitude, bool inside, vec3 origin, vec3 dir, Length t, vec3 sun) {
    return AirRay(up, altitude, t <= 0.0 && inside, origin + dir * t, dir, sun);
}

// The air from the point `t` km along the ray to `span` km further on.
struct AirSlice {
    vec3 inscatter;
    vec3 transmittance;
};
AirSlice AirSliceFrom(vec3 up, Length altitude, bool inside, vec3 origin, vec3 dir, Length t, Length span,
                      vec3 sun) {
    AirSlice a;
    a.inscatter = SkyRadianceToPointOfRay(AirRayFrom(up, altitude, inside, origin, dir, t, sun), origin + dir * t,
                                          dir, span, sun, a.transmittance);
    return a;
}

// Everything between the viewpoint (unit `up` from the planet centre, `altitude` km above the
// bottom radius, formed apart: the sky pass's from the camera's altitude in double) and the
// point `distance` km along `dir`, or space when `distance` <= 0 (then the sky behind is in `inscatter`, and
// `transmittance` is that of the whole ray, for the sun disc), marched as finely as `quality`
// says: the sky pass gives the preset's with a per-pixel jitter; the sea's reflection one
// slice, fewer steps and sun samples and the far field (its few steps would alias the
// volume, and waves and Fresnel blur the reflection anyway).
// `inside`: the air from the viewpoint by `up` and `altitude` (see AirRayFrom), else by `origin`.
ViewMarch MarchViewFrom(vec3 origin, vec3 up, Length altitude, bool inside, vec3 dir, Length distance, vec3 sun,
                        MarchQuality quality) {
    ViewMarch m;
    m.transmittance = vec3(1.0);
    m.inscatter = vec3(0.0);
    m.steps = 0;
    m.skipped = 0;
    m.cloudOpacity = 0.0;
    m.cloudDistance = 0.0;
    Number cloudTransmittance = 1.0;
    Length depthSum = 0.0;
    bool toSpace = distance <= 0.0;
    Length t = 0.0;  // the air is combined up to here
#if !CLOUDS_OFF  // (a program built for a frame without clouds crosses no layer: see cloud_density.glsl)
    vec2 crossings[2];
    int count = 0;
    if (clouds.enabled != 0) {
        Length r = length(origin);
        count = CloudLayerIntervals(r, dot(origin, dir) / r, toSpace ? 1.0e9 : distance, clouds.bottomRadius,
                                    clouds.topRadius, crossings[0], crossings[1]);
    }
    Length fromCamera = length(origin - clouds.cameraFromCentre);  // the sea's reflected rays start away from it
    for (int k = 0; k < count; ++k) {
        vec2 crossing = crossings[k];
        int slices = max(quality.slicesPerCrossing, 1);
        if (CloudFarBlend(max((fromCamera + crossing.x) * clouds.pixelAngle, quality.minFootprintKm)) >= 1.0)
            slices = min(slices, max(int(ceil((crossing.y - crossing.x) / CLOUD_FAR_FIELD_SLICE_KM)), 1));
        Length width = (crossing.y - crossing.x) / Number(slices);
        int budget = max(quality.stepBudget / (slices * count), 1);
        Length emptyTo = crossing.x;  // the clouds are known to be empty up to here
        for (int s = 0; s < slices; ++s) {  // inside the layer: slices of air with clouds in them (Eq. 19-20)
            Length a = crossing.x + Number(s) * width;
            // A slice that a step through empty space crossed whole marches nothing: its
            // loop is not entered (a clear sky's long steps cross several slices at once).
            CloudSegmentResult c =
                MarchCloudSegment(origin, dir, a, max(a, emptyTo), a + width, sun, budget, quality);
            emptyTo = c.reached;
            m.steps += c.steps;
            m.skipped += c.skipped;
            // A slice without clouds (T_C = 1, I_C = 0) changes nothing in Eq. 19-20 but its
            // air, which joins the air before and after it: a clear ray is one lookup of the air
            // (the whole ray's, as without a layer), a cloudy one no more lookups than slices.
            // (A loop of one turn or none: on llvmpipe a group of rays that none enters skips its
            // texture reads; its arithmetic may still run, masked.)
            bool cloudy = c.transmittance != vec3(1.0) || c.inscatter != vec3(0.0);
            for (int i = 0; i < (cloudy ? 1 : 0); ++i) {
                if (a > t) {  // the clear air up to the slice: T_C = 1, I_C = 0 (Eq. 17-18)
                    AirSlice clear = AirSliceFrom(up, altitude, inside, origin, dir, t, a - t, sun);
                    CombineSlice(clear.transmittance, clear.inscatter, vec3(1.0), vec3(0.0), m.transmittance,
                                 m.inscatter);
                }
                AirSlice slice = AirSliceFrom(up, altitude, inside, origin, dir, a, width, sun);
                CombineSlice(slice.transmittance, slice.inscatter, c.transmittance, c.inscatter, m.transmittance,
                             m.inscatter);
                t = a + width;
            }
            depthSum += cloudTransmittance * c.depthSum;
            cloudTransmittance *= c.transmittance.x;
        }
    }
#endif
    // The rest: the air from the last cloudy slice (or the viewpoint) to the surface point, or
    // the sky beyond.
    AirSlice rest;
    ViewRay restRay = AirRayFrom(up, altitude, inside, origin, dir, t, sun);
    if (!toSpace)
        rest.inscatter = SkyRadianceToPointOfRay(restRay, origin + dir * t, dir, max(distance - t, 0.0), sun,
                                                 rest.transmittance);
    else
        rest.inscatter = SkyRadianceOfRay(restRay, origin + dir * t, dir, sun, rest.transmittance);
    CombineSlice(rest.transmittance, rest.inscatter, vec3(1.0), vec3(0.0), m.transmittance, m.inscatter);
    m.cloudOpacity = 1.0 - cloudTransmittance;
    if (m.cloudOpacity > 0.0) m.cloudDistance = depthSum / m.cloudOpacity;
    return m;
}

ViewMarch MarchViewAt(vec3 up, Length altitude, vec3 dir, Length distance, vec3 sun, MarchQuality quality) {
    AtmosphereParameters atmosphere = atmosphereParameters();
    return MarchViewFrom(up * (atmosphere.bottom_radius + altitude), up, altitude,
                         altitude < atmosphere.top_radius - atmosphere.bottom_radius, dir, distance, sun, quality);
}

// The same from a viewpoint given by its position `origin` (km from the planet centre): the
// sea's reflected rays, the cloud probe.
ViewMarch MarchView(vec3 origin, vec3 dir, Length distance, vec3 sun, MarchQuality quality) {
    return MarchViewFrom(origin, origin, 0.0, false, dir, distance, sun, quality);
}
