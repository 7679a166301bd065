#include "terrain/placeholder_sphere.h"

namespace planet {

void PlaceholderSphere::draw(const PlanetParams& planet) const {
    const glm::vec3 albedo(planet.albedo);
    glProgramUniform3fv(pass_.program().id(), glGetUniformLocation(pass_.program().id(), "uAlbedo"), 1, &albedo.x);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);  // reversed-Z
    glDepthMask(GL_TRUE);
    pass_.draw();
    glDisable(GL_DEPTH_TEST);
}

}  // namespace planet
