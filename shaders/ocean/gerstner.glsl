// One spherical Gerstner wave (Michelic §4) evaluated relative to the camera, shared by
// GLSL and C++ (the subset of noise/simplex.glsl's header: f-suffixed literals, single
// component swizzles, OUT(x) for out parameters; src/ocean/ocean_gpu.cpp compiles it).
//
// Why relative to the camera: the phase k l_i (Eq. 7-8) of a 1 m wave at l_i ~ 10^7 m
// needs ~10 significant digits, float has 7. So the CPU computes, per wave and per frame,
// in double, the phase at the camera's direction v_c (OceanWave.shape.w, reduced mod 2 pi)
// and the great-circle frame (o, e, f = o x e) with v_c = cos(tc) o + sin(tc) e; the GPU
// adds k r (t - tc), the phase change from v_c to the point's direction v, computed from
// the small float offset dv = v - v_c without cancellation:
//   cos t - cos tc = dv.o                                  = dc
//   sin t - sin tc = (de (2 sin tc + de) + df^2) / (sin t + sin tc)   = ds
//       (from sin^2 t = (sin tc + dv.e)^2 + (dv.f)^2 for unit v, de = dv.e, df = dv.f)
//   t - tc = atan(sin(t - tc), cos(t - tc)) = atan(ds cos tc - dc sin tc, 1 + dc cos tc + ds sin tc)
// so the phase is as precise near the camera as the offset itself, and the error grows
// only with distance (where the LOD fade has removed short waves anyway).
//
#ifndef OUT
#define OUT(x) out x
#endif

// Per-wave record, std430 (ocean/ocean_gpu.h mirrors it; 64 bytes):
struct OceanWave {
    vec4 originKr;  // xyz: origin o_i (unit); w: k_i r (rad per radian of arc)
    vec4 frameE;    // xyz: e, the unit tangent at o_i towards the camera; w: sin(tc)
    vec4 shape;     // x: amplitude A_i (m); y: steepness Q_i; z: cos(tc); w: phase at the camera (rad)
    vec4 scale;     // x: wavenumber k_i (rad/m); y: wavelength (m); z: sum of (A k)^2 / 2 over this
                    // wave and the shorter ones after it (records are sorted longest first); w: unused
};

vec3 oceanXyz(vec4 v) { return vec3(v.x, v.y, v.z); }

// atan(y, x) to float precision where it matters, near the camera (|y| small against x > 0):
// GLSL allows atan an error of 4096 ulp (GLSL 4.50 §4.7.1), which times k r ~ 10^8 would
// move a short wave by centimetres next to the camera. Taylor series of atan(t) to t^7
// (relative error below t^8 / 9 ~ 4e-12 at t = 0.05); GLSL's atan beyond, where only
// long waves remain.
float gerstnerAngle(float y, float x) {
    if (x > 0.0f && abs(y) < 0.05f * x) {
        float t = y / x;
        float t2 = t * t;
        return t * (1.0f - t2 * (1.0f / 3.0f - t2 * (1.0f / 5.0f - t2 * (1.0f / 7.0f))));
    }
    return atan(y, x);
}

// Phase of wave w at the unit direction v = v_c + dv (only the offset is needed); also the unit direction of travel
// d_i (Eq. 7, normalised: away from o_i) and 1 - |v . o_i| (Eq. 11's argument), precise
// near the origin as sin^2 / (1 + |cos|).
float gerstnerPhase(OceanWave w, vec3 dv, OUT(vec3) travel, OUT(float) oneMinusAbsCos) {
    vec3 o = oceanXyz(w.originKr);
    vec3 e = oceanXyz(w.frameE);
    vec3 f = cross(o, e);
    float sinC = w.frameE.w;
    float cosC = w.shape.z;
    float dc = dot(dv, o);
    float de = dot(dv, e);
    float df = dot(dv, f);
    float sinE = sinC + de;
    float sinT = sqrt(sinE * sinE + df * df);
    float ds = (de * (2.0f * sinC + de) + df * df) / max(sinT + sinC, 1.0e-30f);
    float dTheta = gerstnerAngle(ds * cosC - dc * sinC, 1.0f + dc * cosC + ds * sinC);
    float cosT = cosC + dc;
    // Eq. 7: v x ((v - o) x v) = v (v.o) - o, of length sin t. With v = cos t o + sin t u (u the
    // unit tangent at o towards v, from the offsets: (sinE e + df f) / sin t), that is
    // sin t (cos t u - sin t o): normalised without forming v cos t - o, which cancels in
    // float near the origin and the antipode.
    vec3 towards = (e * sinE + f * df) / max(sinT, 1.0e-30f);
    travel = towards * cosT - o * sinT;
    oneMinusAbsCos = sinT * sinT / (1.0f + abs(cosT));
    // Reduced to about [-pi, pi] before it reaches sin and cos: GPUs' sin and cos lose
    // accuracy fast for large arguments (tens of thousands of radians 2 km away).
    float phase = w.originKr.w * dTheta;
    phase -= 6.2831853f * floor(phase * 0.15915494f + 0.5f);
    return phase + w.shape.w;
}

// Eq. 11: Q' = Q smoothstep(e0, e1, 1 - |v . o|).
// e1 <= e0 (possible after rounding to float) is a step at e0, as in the CPU reference:
// GLSL leaves smoothstep undefined there.
float gerstnerSteepness(OceanWave w, float oneMinusAbsCos, float e0, float e1) {
    float fade = e1 > e0 ? smoothstep(e0, e1, oneMinusAbsCos) : step(e0, oneMinusAbsCos);
    return w.shape.y * fade;
}

// How much of a wave a surface sampled every `footprint` metres can carry: 1 for
// wavelengths of more than 4 footprints, 0 below 2 (Nyquist is 2), smooth between.
// Geometry uses the vertex spacing, shading the pixel footprint; what the shading drops
// becomes slope variance (roughness) instead.
float gerstnerLod(OceanWave w, float footprint) {
    return smoothstep(2.0f, 4.0f, w.scale.y / max(footprint, 1.0e-6f));
}
