// When the whole sea is the ocean mesh's far field (issue 15; shaders/ocean/ocean.frag).
//
// The sea's mesh is a net of chords that sag below the sphere between its vertices by
// (edge length)^2 / 8r. Where that sag passes OCEAN_FAR_FIELD_SAG_M (half a metre), no wave
// shows and ocean.frag takes the pixel's point where its ray meets the sphere, not the chord's:
// the mesh only says which pixels are sea. The edge on screen only grows with the distance
// (ocean/edge_target.glsl: the target, up to OCEAN_FAR_EDGE_FACTOR times ocean.target_edge_px as
// the crests shrink below WAVE_VISIBLE_PIXELS), and so does its length in metres, so the sag is
// smallest at the nearest sea, no nearer than the camera's height above the highest crest. When
// the sag is past the far field's even there, every sea pixel is the sphere's, and the ocean pass
// draws ocean.frag's OCEAN_FAR_FIELD build once per pixel of the ground sphere's rectangle
// instead of the mesh (no vertex or tessellation work, no 4x4 blocks shaded per triangle).
#pragma once

namespace planet::ocean {

// ocean/edge_target.glsl's oceanEdgeTargetPixels: the mesh's edge target at `distanceM`, px.
double edgeTargetPixels(double distanceM, double radiansPerPixel, double maxWaveHeightM, double targetEdgePx);

// common/frame_uniforms.glsl's meshSagM: how far a chord `edgePixels` long on screen at
// `distanceM` sags below the sphere of radius `planetRadiusM`, m.
double meshSagM(double distanceM, double radiansPerPixel, double edgePixels, double planetRadiusM);

// Whether every sea pixel is in the far field (see above), for a camera `heightAboveSeaM` above
// the mean sea (<= 0 or not finite: never), a pixel's angle `radiansPerPixel`, the highest crest
// `maxWaveHeightM`, the ocean's target edge and the coarser of the terrain's and the ocean's
// (ocean.frag bounds the sag by both), on a planet of `planetRadiusM`.
bool seaIsFarField(double heightAboveSeaM, double radiansPerPixel, double maxWaveHeightM, double targetEdgePx,
                   double coarsestEdgePx, double planetRadiusM);

}  // namespace planet::ocean
