// Ocean: one vertex per grid point of its own projected grid; tessellation does the rest.
layout(location = 0) in vec2 gridCoordinate;
out vec2 vGrid;

void main() { vGrid = gridCoordinate; }
