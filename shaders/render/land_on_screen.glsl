// Whether any ground above the sea is on screen this frame: the surface light marks it
// (render/surface_light.frag, where it lights such ground), and the sea's light (ocean/
// sea_light.frag) lists its pixels for the terrain reflection's search only then: the search
// can find nothing but ground above the sea (a reflected ray rises from the sea, in front of
// the floor below it), and on the open sea, where nearly every ray's long reach has land within
// the slope bound somewhere, that is what spares it. src/render/render_targets.cpp clears it
// to 0 before the surface light (RenderTargets::clearLandOnScreen).
layout(std430, binding = BUFFER_LAND_ON_SCREEN) buffer LandOnScreen {
    uint landOnScreen;
};

// Stored by every such pixel alike: no atomic needed.
void markLandOnScreen() {
    if (landOnScreen == 0u) landOnScreen = 1u;
}
