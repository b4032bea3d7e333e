#include "08_joints/joint_view.h"

#include "08_joints/joint_frame.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace stepwise {

namespace {

// Sizes of the drawing, m: large enough to read at the demo's scale, small beside a 1 m body.
constexpr Real kAxisHalfLength = Real(0.3);
constexpr Real kArcRadius = Real(0.3);
constexpr Real kTwistRadius = Real(0.12);
constexpr Real kTick = Real(0.06);
constexpr float kAnchorPixels = 7;

constexpr Color kLimitColor{0.85f, 0.85f, 0.88f, 1};   // what the joint allows: arcs, cone, travel
constexpr Color kMotorColor = colors::kGreen;

Color mix(Color a, Color b, float t) {
    t = std::clamp(t, 0.0f, 1.0f);
    return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t, 1};
}

// A unit vector perpendicular to `axis`: the zero of the angles drawn about it. Taken in body A's
// frame so that it turns with A and the drawing stays put relative to the joint.
Vec3 perpendicular(const Vec3& axis) {
    const Vec3 other = std::abs(axis.x()) < Real(0.9) ? Vec3::UnitX() : Vec3::UnitY();
    return axis.cross(other).normalized();
}

// `u` (perpendicular to the unit `axis`) turned by `angle` about it.
Vec3 turned(const Vec3& u, const Vec3& axis, Real angle) {
    return u * math::cos(angle) + axis.cross(u) * math::sin(angle);
}

// The arc of angles [lo, hi] about `axis`, from the zero direction `u`, with radial ends.
void arc(DebugDraw& draw, const Vec3& center, const Vec3& axis, const Vec3& u, Real radius, Real lo, Real hi,
         Color color) {
    const int segments = std::max(2, int(std::ceil((hi - lo) / (10 * kDegree))));
    Vec3 previous = center + radius * turned(u, axis, lo);
    draw.line(center, previous, color);
    for (int i = 1; i <= segments; ++i) {
        const Vec3 next = center + radius * turned(u, axis, lo + (hi - lo) * Real(i) / Real(segments));
        draw.line(previous, next, color);
        previous = next;
    }
    draw.line(center, previous, color);
}

// Where B carries the zero direction now, flattened onto the plane of `axis`: the hand of the dial.
Vec3 handOf(const JointFrame& frame, const Vec3& localZero, const Vec3& axis) {
    const Vec3 carried = frame.rotationA * (frame.deviation * localZero);
    const Vec3 flat = carried - axis * axis.dot(carried);
    return flat.norm() > Real(1e-6) ? Vec3(flat.normalized()) : Vec3(frame.rotationA * localZero);
}

void drawHinge(DebugDraw& draw, const JointFrame& frame, const JointDesc& joint, Color color) {
    const Vec3 axis = frame.axisA, zero = perpendicular(joint.axis);
    draw.line(frame.anchorA - axis * kAxisHalfLength, frame.anchorA + axis * kAxisHalfLength, colors::kCyan);
    const auto [lo, hi] = joint.limits.value_or(std::pair<Real, Real>(-kPi, kPi));
    arc(draw, frame.anchorA, axis, frame.rotationA * zero, kArcRadius, lo, hi, kLimitColor);
    const Vec3 hand = handOf(frame, zero, axis);
    draw.line(frame.anchorA, frame.anchorA + hand * kArcRadius, color);
    if (joint.motor && joint.motor->speed != 0) {
        // The way the motor drives: along the dial's rim, from the hand's tip.
        const Vec3 tip = frame.anchorA + hand * kArcRadius;
        const Real sign = joint.motor->speed > 0 ? 1 : -1;
        draw.arrow(tip, tip + axis.cross(hand) * (sign * Real(0.15)), kMotorColor);
    }
}

void drawConeTwist(DebugDraw& draw, const JointFrame& frame, const JointDesc& joint, Color color) {
    // The cone: its axis, a ring at the cone angle and lines from the apex to the ring.
    const Vec3 axis = frame.axisA, zero = frame.rotationA * perpendicular(joint.axis);
    draw.line(frame.anchorA, frame.anchorA + axis * kArcRadius, colors::kCyan);
    const Real cone = std::max(joint.coneAngle, Real(1e-3));
    const Vec3 ringCenter = frame.anchorA + axis * (kArcRadius * math::cos(cone));
    const Real ringRadius = kArcRadius * math::sin(cone);
    constexpr int kRing = 24;
    for (int i = 0; i < kRing; ++i) {
        const Vec3 from = ringCenter + ringRadius * turned(zero, axis, 2 * kPi * Real(i) / kRing);
        const Vec3 to = ringCenter + ringRadius * turned(zero, axis, 2 * kPi * Real(i + 1) / kRing);
        draw.line(from, to, colors::kMagenta);
        if (i % 3 == 0) draw.line(frame.anchorA, from, colors::kMagenta);
    }
    // B's twist axis, and at its end the twist limits about it. The zero of the twist is A's zero
    // carried by the swing (the shortest turn from A's axis to B's), as swingAngle and twistAngle
    // split the deviation.
    const Vec3 axisB = frame.axisB, end = frame.anchorB + axisB * kArcRadius;
    draw.line(frame.anchorB, end, color);
    const Vec3 twistZero = Quat::FromTwoVectors(axis, axisB) * zero;
    if (joint.twistLimits)
        arc(draw, end, axisB, twistZero, kTwistRadius, joint.twistLimits->first, joint.twistLimits->second, kLimitColor);
    draw.line(end, end + handOf(frame, perpendicular(joint.axis), axisB) * kTwistRadius, color);
}

void drawSlider(DebugDraw& draw, const JointFrame& frame, const JointDesc& joint, Color color) {
    const Vec3 axis = frame.axisA, side = frame.rotationA * perpendicular(joint.axis);
    if (joint.limits) {
        // The travel allowed, with a tick across each end.
        const Vec3 lo = frame.anchorA + axis * joint.limits->first, hi = frame.anchorA + axis * joint.limits->second;
        draw.line(lo, hi, kLimitColor);
        for (const Vec3& end : {lo, hi}) draw.line(end - side * kTick, end + side * kTick, kLimitColor);
    } else {
        draw.line(frame.anchorA - axis * kAxisHalfLength, frame.anchorA + axis * kAxisHalfLength, colors::kCyan);
    }
    // Where B is along the travel.
    draw.line(frame.anchorB - side * kTick, frame.anchorB + side * kTick, color);
    if (joint.motor && joint.motor->speed != 0)
        draw.arrow(frame.anchorB, frame.anchorB + axis * (joint.motor->speed > 0 ? Real(0.2) : Real(-0.2)), kMotorColor);
}

}  // namespace

Color stretchColor(Real stretch) {
    if (stretch < 0) return mix(colors::kGreen, colors::kCyan, float(-stretch / Real(0.25)));
    if (stretch >= Real(0.25)) return colors::kOrange;
    if (stretch < Real(0.1)) return mix(colors::kGreen, colors::kYellow, float(stretch / Real(0.1)));
    return mix(colors::kYellow, colors::kOrange, float((stretch - Real(0.1)) / Real(0.15)));
}

std::string describeJoint(const JointDesc& joint) {
    std::string out = toString(joint.type);
    const auto add = [&out](const char* format, auto... values) {
        char text[64];
        std::snprintf(text, sizeof text, format, values...);  // callers pass doubles and strings
        out += text;
    };
    const auto degrees = [](Real radians) { return double(radians / kDegree); };
    const std::pair<Real, Real> none(0, 0);
    switch (joint.type) {
        case JointType::Distance:
            if (joint.springHertz > 0)
                add(" spring %.3g Hz, ratio %.3g", double(joint.springHertz), double(joint.springDampingRatio));
            break;
        case JointType::Hinge:
        case JointType::Slider: {
            const bool hinge = joint.type == JointType::Hinge;
            const auto [lo, hi] = joint.limits.value_or(none);
            if (joint.limits && hinge) add(" [%.0f, %.0f] deg", degrees(lo), degrees(hi));
            if (joint.limits && !hinge) add(" [%.3g, %.3g] m", double(lo), double(hi));
            if (joint.motor)
                add(hinge ? "%s motor %.3g rad/s, %.3g N m" : "%s motor %.3g m/s, %.3g N", joint.limits ? "," : "",
                    double(joint.motor->speed), double(joint.motor->maxForce));
            break;
        }
        case JointType::ConeTwist: {
            add(" cone %.0f deg", degrees(joint.coneAngle));
            const auto [lo, hi] = joint.twistLimits.value_or(none);
            if (joint.twistLimits) add(", twist [%.0f, %.0f] deg", degrees(lo), degrees(hi));
            break;
        }
        case JointType::BallSocket:
        case JointType::Fixed: break;
    }
    return out;
}

// [ch08-joint-view]
void drawJoint(DebugDraw& draw, const World& world, const JointDesc& joint, Real labelHeight) {
    if (!jointBodiesValid(world, joint)) return;
    const JointFrame frame = jointFrame(world, joint);
    // A spring is meant to stretch: its colour says how far, and only rigid joints turn red.
    const bool spring = joint.type == JointType::Distance && joint.springHertz > 0;
    const bool off = !spring && measureJointError(world, joint).position > kJointErrorShown;
    const Color color = off ? colors::kRed : colors::kOrange;
    switch (joint.type) {
        case JointType::Distance: {
            const Real rest = joint.length.value_or(0);
            const Real length = (frame.anchorB - frame.anchorA).norm();
            const Real stretch = rest > 0 ? (length - rest) / rest : 0;
            draw.line(frame.anchorA, frame.anchorB, off ? colors::kRed : stretchColor(stretch));
            break;
        }
        case JointType::BallSocket: draw.line(frame.anchorA, frame.anchorB, color); break;
        case JointType::Hinge: drawHinge(draw, frame, joint, color); break;
        case JointType::ConeTwist: drawConeTwist(draw, frame, joint, color); break;
        case JointType::Slider: drawSlider(draw, frame, joint, color); break;
        case JointType::Fixed:
            // A small wire cube in A's frame: the weld.
            draw.box(Transform{frame.anchorA, frame.rotationA}, Vec3::Constant(Real(0.04)), color, Fill::Wire);
            break;
    }
    draw.point(frame.anchorA, kAnchorPixels, off ? colors::kRed : colors::kYellow);
    draw.point(frame.anchorB, kAnchorPixels, off ? colors::kRed : colors::kYellow);
    if (labelHeight > 0) draw.text(frame.anchorA + Vec3(0, labelHeight, 0), describeJoint(joint), colors::kWhite);
}
// [ch08-joint-view]

void JointView::draw(const World& world, DebugDraw& draw) const {
    // Labels at two heights in turn: neighbours' labels, which run right, do not overlap.
    for (std::size_t i = 0; i < world.joints.size(); ++i)
        drawJoint(draw, world, world.joints[i], labels_ ? Real(0.45) + Real(0.3) * Real(i % 2) : 0);
    // Each kinematic path as the line its body's origin runs along, ends marked.
    for (const KinematicPath& path : world.kinematicPaths) {
        const Vec3 from = path.center - path.amplitude, to = path.center + path.amplitude;
        draw.line(from, to, colors::kBlue);
        draw.point(from, kAnchorPixels, colors::kBlue);
        draw.point(to, kAnchorPixels, colors::kBlue);
    }
}

SceneViewFactory jointView(bool labels) {
    return [labels] { return std::unique_ptr<SceneView>(std::make_unique<JointView>(labels)); };
}

}  // namespace stepwise
