// Tone mapping: linear HDR radiance -> display-ready sRGB.
//
// Operator (Bruneton's demo): display = 1 - exp(-frame.exposure * radiance) per
// channel, then the sRGB transfer function (IEC 61966-2-1). The result is
// written to an RGBA8 target as encoded sRGB values, so the window and the
// PNG writer show the very same bytes.
#include "common/frame_uniforms.glsl"

in vec2 vNdc;
layout(binding = UNIT_HDR_RADIANCE) uniform sampler2D hdrRadiance;
layout(location = 0) out vec4 outColor;

vec3 srgbFromLinear(vec3 c) {
    vec3 lo = 12.92 * c;
    vec3 hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(lo, hi, step(vec3(0.0031308), c));
}

void main() {
    vec3 radiance = texelFetch(hdrRadiance, ivec2(gl_FragCoord.xy), 0).rgb;
    vec3 display = 1.0 - exp(-frame.exposure * max(radiance, vec3(0.0)));
    outColor = vec4(srgbFromLinear(clamp(display, 0.0, 1.0)), 1.0);
}
