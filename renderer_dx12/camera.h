#pragma once
// Orbit and fly cameras. Y is up; the projection maps depth to D3D's [0, 1] clip range.

#include "math/math.h"

#include <Eigen/Core>

namespace stepwise::render {

using Vec3f = Eigen::Vector3f;
using Mat4f = Eigen::Matrix4f;

struct Camera {
    enum class Mode { Orbit, Fly };
    Mode mode = Mode::Orbit;
    Vec3f target = Vec3f::Zero();   // orbit centre
    Vec3f position = Vec3f(0, 2, 10);  // fly camera eye
    float yaw = 0.6f;               // rad about +Y; 0 looks along -Z
    float pitch = 0.35f;            // rad above the horizon (orbit: eye above the target)
    float distance = 10;            // orbit radius, m
    float fovY = 0.87f;             // rad (50 degrees)
    float nearPlane = 0.05f;
    float farPlane = 2000;
    /// Lens shift in normalised device x (-1..1 spans the image): the point looked at lands at
    /// this x instead of the centre, so a scene can sit beside the ImGui panel while the
    /// orbit still turns about the scene.
    float shiftX = 0;

    Vec3f eye() const;
    Vec3f forward() const;          // unit view direction
    Vec3f right() const;
    Mat4f view() const;
    Mat4f projection(float aspect) const;
    Mat4f viewProjection(float aspect) const { return projection(aspect) * view(); }

    /// Looks at the box from the current direction, as close as keeps its eight corners in
    /// view, centred in the horizontal part [viewLeft, viewRight] of the image (fractions of
    /// its width; the rest is covered, e.g. by the panel).
    void frame(const Aabb& box, float aspect, float viewLeft = 0, float viewRight = 1);
    void orbit(float deltaYaw, float deltaPitch);
    void pan(float dxPixels, float dyPixels, float viewportHeight);
    void zoom(float wheelSteps);
    /// Fly: moves along forward/right/up by the given metres (orbit: moves the target).
    void move(float alongForward, float alongRight, float alongUp);
    void setMode(Mode next);

    /// Screen position (pixels, origin top-left) of a world point; false when behind the eye.
    bool project(const Vec3f& world, float width, float height, float& x, float& y) const;
    /// The inverse of project(): the ray from the eye through pixel (x, y) of a width x height
    /// view, as a unit direction. Picking casts it into the world.
    Vec3f pixelDirection(float x, float y, float width, float height) const;
    /// Metres one pixel spans at a world point's depth: turns a pick radius or a gizmo's size in
    /// pixels into metres.
    float metresPerPixel(const Vec3f& world, float height) const;
};

}  // namespace stepwise::render
