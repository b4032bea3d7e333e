#include "picking.h"

namespace stepwise::render {

namespace {
/// How close, in pixels, the cursor must come to a contact point to pick it: about the size its
/// cube is drawn at from a usual distance.
constexpr float kContactPickPixels = 8;
}  // namespace

Ray cursorRay(const Camera& camera, float x, float y, float width, float height) {
    Ray ray;
    ray.origin = camera.eye().cast<Real>();
    ray.direction = camera.pixelDirection(x, y, width, height).cast<Real>();
    ray.maxDistance = static_cast<Real>(camera.farPlane);
    return ray;
}

int pickBody(const World& world, const Ray& ray) {
    const WorldRayHit moving = castRay(world, ray, true);
    if (moving.body >= 0) return moving.body;
    return castRay(world, ray, false).body;
}

void clickAt(DemoState& state, const Camera& camera, float x, float y, float width, float height) {
    const Ray ray = cursorRay(camera, x, y, width, height);
    const int body = pickBody(state.world(), ray);
    if (state.views.contactPoints) {
        // The pick radius is measured at the depth of what the ray hits (or of the orbit centre),
        // so a contact is as easy to click from far away as from close up.
        const WorldRayHit hit = castRay(state.world(), ray, false);
        const Vec3f depthPoint = hit.body >= 0 ? hit.hit.point.cast<float>() : camera.target;
        const Real radius = static_cast<Real>(kContactPickPixels * camera.metresPerPixel(depthPoint, height));
        const HitSelection point = pickHitPoint(state.hitTree(), ray, radius);
        if (!point.empty()) {
            state.selectHit(point);
            state.revealSelection = true;
            return;
        }
    }
    state.selectedBody = body;
    state.selectHit(HitSelection());
}

}  // namespace stepwise::render
