// Terrain: one vertex per grid point; the tessellation stages do the rest.
layout(location = 0) in vec2 gridCoordinate;
out vec2 vGrid;

void main() { vGrid = gridCoordinate; }
