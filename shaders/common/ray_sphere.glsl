// Ray-sphere intersection in camera-relative form, precise at 2 m above a
// 6360 km sphere.
//
// Written in the C++-compatible subset of GLSL (scalar floats only) so the
// tests compile this very file as C++ (tests/test_ray_sphere.cpp).
//
// The ray starts at altitude h above a sphere of radius R, with mu the cosine
// between the ray and the radial up. With r = R + h the distances along the
// ray are t = -r mu +- sqrt(r^2 mu^2 - h (2R + h)): writing r^2 - R^2 as
// h (2R + h) keeps the small altitude exact instead of subtracting two numbers
// of size 4e13, and the near root is taken as c / (-r mu + sqrt(disc)) (product
// of the roots = h (2R + h)) to avoid cancellation when the hit is close.

// Distance to the nearest hit in front of the ray origin, or -1 for a miss.
float raySphereNearestHit(float altitude, float radius, float mu) {
    float r = radius + altitude;
    float c = altitude * (2.0f * radius + altitude);  // r^2 - R^2
    float disc = r * r * mu * mu - c;
    if (disc < 0.0f) return -1.0f;
    float s = sqrt(disc);
    if (altitude < 0.0f) return -r * mu + s;  // inside the sphere: the exit point
    if (mu >= 0.0f) return -1.0f;             // outside and looking away
    return c / (-r * mu + s);
}
