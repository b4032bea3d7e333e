#include "camera.h"

#include <algorithm>
#include <cmath>

namespace stepwise::render {

namespace {
constexpr float kMaxPitch = 1.5f;  // just short of straight up/down, where look-at degenerates

Vec3f fromEyeToTarget(float yaw, float pitch) {
    // Unit vector from the target towards the eye, reversed.
    return -Vec3f(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
}
}  // namespace

Vec3f Camera::forward() const { return fromEyeToTarget(yaw, pitch); }

Vec3f Camera::right() const { return forward().cross(Vec3f::UnitY()).normalized(); }

Vec3f Camera::eye() const { return mode == Mode::Orbit ? Vec3f(target - distance * forward()) : position; }

Mat4f Camera::view() const {
    // Right-handed look-at: the camera looks down its -Z axis.
    const Vec3f eyePoint = eye();
    const Vec3f z = -forward();
    const Vec3f x = Vec3f::UnitY().cross(z).normalized();
    const Vec3f y = z.cross(x);
    Mat4f m = Mat4f::Identity();
    m.block<1, 3>(0, 0) = x.transpose();
    m.block<1, 3>(1, 0) = y.transpose();
    m.block<1, 3>(2, 0) = z.transpose();
    m(0, 3) = -x.dot(eyePoint);
    m(1, 3) = -y.dot(eyePoint);
    m(2, 3) = -z.dot(eyePoint);
    return m;
}

Mat4f Camera::projection(float aspect) const {
    // D3D-style right-handed perspective: clip w = view depth, z/w in [0, 1].
    const float f = 1.0f / std::tan(0.5f * fovY);
    Mat4f m = Mat4f::Zero();
    m(0, 0) = f / std::max(aspect, 1e-3f);
    m(1, 1) = f;
    m(0, 2) = -shiftX;  // x_ndc = x_clip / w + shiftX, with w = -z_view
    m(2, 2) = farPlane / (nearPlane - farPlane);
    m(2, 3) = nearPlane * farPlane / (nearPlane - farPlane);
    m(3, 2) = -1;
    return m;
}

void Camera::frame(const Aabb& box, float aspect, float viewLeft, float viewRight) {
    if (!box.min.allFinite() || !box.max.allFinite() || (box.min.array() > box.max.array()).any()) return;
    viewLeft = std::clamp(viewLeft, 0.0f, 0.9f);
    viewRight = std::clamp(viewRight, viewLeft + 0.1f, 1.0f);
    const Vec3f center = box.center().cast<float>();
    const Vec3f half = box.extents().cast<float>().cwiseMax(Vec3f::Constant(0.25f));
    // Tangents of the half angles the box may fill, with a margin (kFill) around it.
    constexpr float kFill = 0.85f;
    const float tanY = std::tan(0.5f * fovY);
    const float tanUp = kFill * tanY;
    const float tanSide = kFill * tanY * std::max(aspect, 0.05f) * (viewRight - viewLeft);
    // The eye sits at target - distance * forward. A corner q (from the centre) is at depth
    // distance + q.f, and stays in view while |q.r| <= tanSide * depth and |q.u| <= tanUp * depth:
    // the smallest distance that satisfies every corner (tighter than a bounding sphere).
    const Vec3f along = forward(), side = right(), up = side.cross(along);
    float needed = 0.5f;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3f q((corner & 1) ? half.x() : -half.x(), (corner & 2) ? half.y() : -half.y(),
                      (corner & 4) ? half.z() : -half.z());
        const float depthOffset = q.dot(along);
        needed = std::max({needed, std::abs(q.dot(side)) / tanSide - depthOffset, std::abs(q.dot(up)) / tanUp - depthOffset,
                           2 * nearPlane - depthOffset});
    }
    distance = std::min(needed, 0.5f * farPlane);
    target = center;
    shiftX = viewLeft + viewRight - 1;  // the middle of the free part, in device x
    position = target - distance * forward();
}

void Camera::orbit(float deltaYaw, float deltaPitch) {
    const Vec3f pivot = mode == Mode::Orbit ? target : position;
    yaw += deltaYaw;
    pitch = std::clamp(pitch + deltaPitch, -kMaxPitch, kMaxPitch);
    if (mode == Mode::Orbit) target = pivot;
}

void Camera::pan(float dxPixels, float dyPixels, float viewportHeight) {
    const float metresPerPixel = 2 * distance * std::tan(0.5f * fovY) / std::max(viewportHeight, 1.0f);
    const Vec3f up = right().cross(forward());
    const Vec3f shift = (-dxPixels * right() + dyPixels * up) * metresPerPixel;
    target += shift;
    position += shift;
}

void Camera::zoom(float wheelSteps) {
    if (mode == Mode::Orbit) {
        distance = std::clamp(distance * std::pow(0.85f, wheelSteps), 0.1f, 0.5f * farPlane);
    } else {
        position += forward() * wheelSteps * 0.5f;
    }
}

void Camera::move(float alongForward, float alongRight, float alongUp) {
    const Vec3f shift = alongForward * forward() + alongRight * right() + alongUp * Vec3f::UnitY();
    if (mode == Mode::Orbit) target += shift;
    else position += shift;
}

void Camera::setMode(Mode next) {
    if (next == mode) return;
    if (next == Mode::Fly) position = eye();
    else target = position + distance * forward();
    mode = next;
}

bool Camera::project(const Vec3f& world, float width, float height, float& x, float& y) const {
    const Eigen::Vector4f clip = viewProjection(width / std::max(height, 1.0f)) * world.homogeneous();
    if (clip.w() <= nearPlane) return false;
    x = (clip.x() / clip.w() * 0.5f + 0.5f) * width;
    y = (0.5f - clip.y() / clip.w() * 0.5f) * height;
    return true;
}

Vec3f Camera::pixelDirection(float x, float y, float width, float height) const {
    // projection(): x_ndc = (f / aspect) x_view / depth + shiftX and y_ndc = f y_view / depth, so
    // at depth 1 the pixel's view-space point is ((x_ndc - shiftX) aspect / f, y_ndc / f, -1).
    const float aspect = width / std::max(height, 1.0f);
    const float f = 1.0f / std::tan(0.5f * fovY);
    const float ndcX = 2.0f * x / std::max(width, 1.0f) - 1.0f;
    const float ndcY = 1.0f - 2.0f * y / std::max(height, 1.0f);
    const Vec3f side = right(), up = side.cross(forward());
    return ((ndcX - shiftX) * aspect / f * side + ndcY / f * up + forward()).normalized();
}

float Camera::metresPerPixel(const Vec3f& world, float height) const {
    const float depth = std::max((world - eye()).dot(forward()), nearPlane);
    return 2.0f * depth * std::tan(0.5f * fovY) / std::max(height, 1.0f);
}

}  // namespace stepwise::render
