#include "render/frame_uniforms.h"

namespace planet {

FrameUniforms makeFrameUniforms(const Scene& scene, const Camera& camera, glm::ivec2 size) {
    const double aspect = static_cast<double>(size.x) / static_cast<double>(size.y);
    const glm::dmat4 clipFromView = camera.clipFromView(aspect);
    const double radius = scene.planetRadiusM();
    // Everything below is formed in double and only then rounded to float, so
    // the GPU never subtracts two planet-sized numbers.
    const glm::dvec3 centreFromCamera = -camera.position;
    const double distance = glm::length(camera.position);
    // The app keeps cameras outside the planet (sanitizeCamera); a camera at the
    // very centre still gets a defined up rather than a division by zero.
    const glm::dvec3 up = distance > 0.0 ? camera.position / distance : glm::dvec3(0.0, 0.0, 1.0);

    FrameUniforms u{};
    u.clipFromView = glm::mat4(clipFromView);
    u.viewFromClip = glm::mat4(glm::inverse(clipFromView));
    u.viewFromWorld = camera.viewFromWorldRotation();
    u.worldFromView = glm::mat4(glm::dmat4(camera.worldFromView()));
    u.planetCenterFromCamera = glm::vec4(glm::vec3(centreFromCamera), static_cast<float>(radius));
    u.cameraUp = glm::vec4(glm::vec3(up), static_cast<float>(distance - radius));
    u.sunDirection = glm::vec4(glm::vec3(scene.sunDirection()), static_cast<float>(scene.sun.angular_radius_rad));
    u.viewport = glm::vec4(size.x, size.y, 1.0f / static_cast<float>(size.x), 1.0f / static_cast<float>(size.y));
    u.camera = glm::vec4(static_cast<float>(camera.near_m), static_cast<float>(scene.render.exposure), 0.0f, 0.0f);
    return u;
}

}  // namespace planet
