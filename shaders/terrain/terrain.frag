// The terrain mesh's fragments: the point, its direction and its steps to the next pixels
// (terrain/mesh_surface.glsl), for the ground's material pass (terrain/ground_material.frag),
// which forms the G-buffer's normal, albedo and material once per pixel where the terrain is the
// nearest surface (the stencil: 2 where the detail's program is drawn, 1 elsewhere,
// src/render/renderer.cpp). Nothing else runs here: a software renderer shades a 4x4 block for
// every triangle that touches it, two to nine times the pixels (see mesh_surface.glsl).
#include "terrain/mesh_surface.glsl"

in vec3 teDirection;
in vec3 tePointFromCamera;

layout(location = 0) out vec4 outSurface0;
layout(location = 1) out vec4 outSurface1;
layout(location = 2) out vec4 outSurface2;

void main() {
    TerrainFragment f =
        TerrainFragment(tePointFromCamera, teDirection, dFdx(tePointFromCamera), dFdy(tePointFromCamera));
    packTerrainFragment(f, outSurface0, outSurface1, outSurface2);
}
