#pragma once
// Clicking in the scene: the camera ray through the cursor, cast into the world. A click picks a
// contact point when the contacts are shown and one lies under the cursor (selecting its node in
// the hit tree), else the nearest body, moving bodies before static ones (the ground is rarely
// what a click on a box standing on it means).

#include "09_debug/ray_cast.h"
#include "camera.h"
#include "demo_state.h"

namespace stepwise::render {

/// The ray from the eye through pixel (x, y) of a width x height view.
Ray cursorRay(const Camera& camera, float x, float y, float width, float height);

/// The body the ray meets first, dynamic and kinematic bodies before static ones; -1 for none.
int pickBody(const World& world, const Ray& ray);

/// What a click at pixel (x, y) selects (see the file comment); selects nothing on a miss.
void clickAt(DemoState& state, const Camera& camera, float x, float y, float width, float height);

}  // namespace stepwise::render
