// The persistent projected grid on the GPU (Michelic Eq. 1-4), mirror of
// src/grid/projected_grid.cpp: grid coordinate g in [-1, 1]^2 -> Eq. 2
// hemisphere pre-displacement shifted by z_s (Eq. 3) -> rotation into the
// world (Eq. 4, carried with the anchor) -> direction from the planet centre
// (Eq. 1). In double precision: the direction feeds positions of planet size
// that are then made camera-relative, and float would round them to half a
// metre (visible steps when standing on a beach).
uniform dmat3 uWorldFromGrid;
uniform double uZShift;
uniform int uGridExponent;       // n of Eq. 2
uniform dvec3 uCameraPosition;   // world frame, m
uniform double uPlanetRadius;    // m, sea level

double powInt(double x, int n) {
    double result = 1.0;
    for (int i = 0; i < n; ++i) result *= x;
    return result;
}

// Unit direction from the planet centre for grid coordinate g.
dvec3 gridDirection(vec2 g) {
    double gx = double(g.x), gy = double(g.y);
    double hemisphere = (1.0 - powInt(abs(gx), uGridExponent)) * (1.0 - powInt(abs(gy), uGridExponent));  // Eq. 2
    return normalize(uWorldFromGrid * dvec3(gx, gy, hemisphere + uZShift));                                 // Eq. 4, 1
}

// Camera-relative position (m, world axes) of the point at `radius` along a direction.
vec3 cameraRelative(dvec3 direction, double radius) { return vec3(direction * radius - uCameraPosition); }
