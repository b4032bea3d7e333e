#pragma once
// What the inspector and the gizmo change, as data: a body's whole editable state at one frame.
// An edit is applied between frames; a session logs the live ones, so a recording can apply them
// again at the same frames and a replay of a poked run is as exact as one left alone.

#include "world/world.h"

#include <optional>
#include <string>

namespace stepwise {

// [ch09-body-edit]
struct BodyEdit {
    long frame = 0;                          // applied when World::frame is this, before its step
    int body = -1;
    Transform transform;
    Vec3 linearVelocity = Vec3::Zero();      // of the centre of mass, m/s
    Vec3 angularVelocity = Vec3::Zero();     // rad/s
    Real mass = 0;                           // kg; dynamic bodies only (others keep 0)
    Mat3 inertiaLocal = Mat3::Zero();        // kg m^2 about the centre of mass, body axes
};
// [ch09-body-edit]

/// The edit that changes nothing: the body's state now, at the world's frame.
BodyEdit currentState(const World& world, int body);

/// An empty string when the edit can be applied, else why not, naming the field: a body that does
/// not exist, a non-finite number, a non-positive mass, an inertia that is not symmetric positive
/// definite, a rotation far from unit length.
std::string validateEdit(const World& world, const BodyEdit& edit);

/// Writes the edit into the world (normalising the rotation, recomputing the inverse mass and
/// inertia). Throws std::invalid_argument with validateEdit's message when it cannot.
void applyEdit(World& world, const BodyEdit& edit);

/// What the gizmo does: moves the body to `transform` and stops it, since a velocity kept from
/// before the drag would fling it.
BodyEdit moveEdit(const World& world, int body, const Transform& transform);

}  // namespace stepwise
