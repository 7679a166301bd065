// What a mesh's fragments leave at each pixel where their surface is the nearest, for a pass that
// shades those pixels once each over the whole frame: a software renderer shades a 4x4 block of
// pixels for every triangle that touches it, so a mesh's fragment shader pays two to nine times
// its pixels (`GL_FRAGMENT_SHADER_INVOCATIONS`, 1280x720: the terrain at `ground` 1 538 128 for
// about 460 000 ground pixels, at `mountains` 8 258 112; the ocean at `sea` 3 017 024 for 921 600).
// Three RGBA32F targets (src/render/render_targets.h, meshSurface), which the terrain fills and its
// material pass reads (terrain/terrain.frag, terrain/ground_material.frag), then the ocean (its sea
// surface: ocean/sea_surface.glsl).
//
// The terrain's: the fragment's camera-relative point (m, world axes, formed in double by the
// evaluation stage and interpolated), its direction from the planet centre (interpolated, not
// normalised) and the point's steps to the next pixel across and up (dFdx, dFdy: the pixel's
// footprint on the ground), as the mesh's fragment had them.
struct TerrainFragment {
    vec3 pointFromCamera;
    vec3 direction;
    vec3 stepX;
    vec3 stepY;
};

void packTerrainFragment(TerrainFragment f, out vec4 texel0, out vec4 texel1, out vec4 texel2) {
    texel0 = vec4(f.pointFromCamera, f.stepX.x);
    texel1 = vec4(f.direction, f.stepX.y);
    texel2 = vec4(f.stepY, f.stepX.z);
}

TerrainFragment unpackTerrainFragment(vec4 texel0, vec4 texel1, vec4 texel2) {
    return TerrainFragment(texel0.xyz, texel1.xyz, vec3(texel0.w, texel1.w, texel2.w), texel2.xyz);
}
