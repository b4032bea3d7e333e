// Figures for chapter 8, computed by the engine's own joint frames, angles and ragdoll builder.
#include "figures.h"

#include "08_joints/builders.h"
#include "08_joints/joint_frame.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace figures {

using namespace stepwise;

namespace {

// A view from a little above and to the side: turned 0.5 rad about y, then tipped 0.45 rad
// about x, so that turns about the vertical show as ellipses.
Point2 jointOblique(const Vec3& p) {
    const double yaw = -0.5, pitch = 0.45;
    const double x = double(p.x()) * std::cos(yaw) + double(p.z()) * std::sin(yaw);
    const double z = -double(p.x()) * std::sin(yaw) + double(p.z()) * std::cos(yaw);
    return {x, double(p.y()) * std::cos(pitch) - z * std::sin(pitch)};
}

std::string jointText(const char* pattern, double a, double b = 0, double c = 0) {
    char text[200];
    std::snprintf(text, sizeof text, pattern, a, b, c);
    return text;
}

// The twelve edges of a box.
void jointWireBox(Svg& svg, const Viewport& view, const Vec3& half, const Transform& pose, const std::string& style) {
    for (int i = 0; i < 8; ++i)
        for (int axis = 0; axis < 3; ++axis) {
            if (i & (1 << axis)) continue;
            const auto corner = [&](int k) {
                return pose.apply(Vec3(k & 1 ? half.x() : -half.x(), k & 2 ? half.y() : -half.y(), k & 4 ? half.z() : -half.z()));
            };
            svg.line(view, jointOblique(corner(i)), jointOblique(corner(i | (1 << axis))), style);
        }
}

// An arc of `radius` about `axis` through `centre`, from direction `from` turned by angles a0 to a1.
std::vector<Point2> jointArc(const Vec3& centre, const Vec3& axis, const Vec3& from, double a0, double a1, double radius,
                        Point2 (*view)(const Vec3&)) {
    std::vector<Point2> points;
    for (int i = 0; i <= 32; ++i) {
        const double angle = a0 + (a1 - a0) * i / 32.0;
        points.push_back(view(centre + Real(radius) * (Eigen::AngleAxis<Real>(Real(angle), axis) * from)));
    }
    return points;
}

int jointAddBox(World& world, const char* name, BodyType type, const Vec3& half, const Transform& pose) {
    BodyDef def;
    def.name = name;
    def.type = type;
    def.shape = Shape::box(half);
    def.transform = pose;
    return addBody(world, def);
}

}  // namespace

bool drawHingeFrame(const std::string& path) {
    // A door (B) on a post (A), hinged about A's y axis. B has turned 0.6 rad about the axis and,
    // as a solve leaves it, slipped a little: its copy of the axis is tipped, its anchor apart.
    World world;
    const Vec3 postHalf(Real(0.08), Real(0.7), Real(0.08)), doorHalf(Real(0.5), Real(0.45), Real(0.03));
    const int post = jointAddBox(world, "post", BodyType::Static, postHalf, Transform{});
    const Vec3 anchor(Real(0.1), 0, 0);
    const Quat turned = Quat(Eigen::AngleAxis<Real>(Real(0.6), Vec3::UnitY())) * Quat(Eigen::AngleAxis<Real>(Real(0.12), Vec3::UnitX()));
    const Vec3 slip(Real(0.03), Real(-0.04), Real(0.02));
    const int door = jointAddBox(world, "door", BodyType::Dynamic, doorHalf,
                            Transform{anchor + slip + turned * Vec3(Real(0.52), 0, 0), turned});
    JointDesc hinge;
    hinge.type = JointType::Hinge;
    hinge.bodyA = post;
    hinge.bodyB = door;
    hinge.localAnchorA = anchor;
    hinge.localAnchorB = Vec3(Real(-0.52), 0, 0);
    hinge.axis = Vec3::UnitY();
    hinge.limits = std::make_pair(Real(-0.4), Real(1.3));
    const JointFrame frame = jointFrame(world, hinge);
    const Real angle = twistAngle(frame.deviation, hinge.axis);
    const Real tilt = swingAngle(frame);
    Vec3 b, c;
    tangentBasis(frame.axisA, b, c);

    Svg svg(900, 520);
    const Viewport view{0, 40, 620, 480, {Real(0.3), 0}, 300};
    jointWireBox(svg, view, postHalf, Transform{}, "stroke:#1f77b4;stroke-width:1.5");
    jointWireBox(svg, view, doorHalf, world.bodies[std::size_t(door)].transform, "stroke:#d62728;stroke-width:1.5");
    // The limits and the angle, in the plane across A's axis, from B's rest direction (A's x).
    const Vec3 rest = Vec3::UnitX();
    std::vector<Point2> range = jointArc(frame.anchorA, frame.axisA, rest, double(hinge.limits->first), double(hinge.limits->second), 0.4, jointOblique);
    range.insert(range.begin(), jointOblique(frame.anchorA));
    svg.polygon(view, range, "fill:#2ca02c;fill-opacity:0.12;stroke:#2ca02c;stroke-width:1");
    svg.polyline(view, jointArc(frame.anchorA, frame.axisA, rest, 0, double(angle), 0.3, jointOblique), "stroke:#000;stroke-width:2");
    svg.line(view, jointOblique(frame.anchorA), jointOblique(frame.anchorA + Real(0.4) * rest), "stroke:#000;stroke-width:1;stroke-dasharray:4 3");
    const Vec3 bDirection = world.bodies[std::size_t(door)].transform.rotation * Vec3::UnitX();
    svg.line(view, jointOblique(frame.anchorA), jointOblique(frame.anchorA + Real(0.4) * bDirection), "stroke:#000;stroke-width:1;stroke-dasharray:4 3");
    svg.text(view, jointOblique(frame.anchorA + Real(0.33) * (Eigen::AngleAxis<Real>(angle / 2, frame.axisA) * rest)), jointText("theta %.2f", double(angle)));
    // The axes: A's through A's anchor, B's copy through B's; the two directions across A's axis.
    svg.arrow(view, jointOblique(frame.anchorA - Real(0.55) * frame.axisA), jointOblique(frame.anchorA + Real(0.65) * frame.axisA), "#1f77b4", 2.5);
    svg.arrow(view, jointOblique(frame.anchorB - Real(0.45) * frame.axisB), jointOblique(frame.anchorB + Real(0.55) * frame.axisB), "#d62728", 2.5);
    svg.arrow(view, jointOblique(frame.anchorA), jointOblique(frame.anchorA + Real(0.2) * b), "#7f7f7f", 1.5);
    svg.arrow(view, jointOblique(frame.anchorA), jointOblique(frame.anchorA + Real(0.2) * c), "#7f7f7f", 1.5);
    svg.dot(view, jointOblique(frame.anchorA), 5, "#1f77b4");
    svg.dot(view, jointOblique(frame.anchorB), 5, "#d62728");
    svg.text(view, jointOblique(frame.anchorA + Real(0.67) * frame.axisA), "a_A", "fill:#1f77b4");
    svg.text(view, jointOblique(frame.anchorB + Real(0.58) * frame.axisB), "a_B", "fill:#d62728");
    svg.text(view, jointOblique(frame.anchorA + Real(0.22) * b), "b", "fill:#555");
    svg.text(view, jointOblique(frame.anchorA + Real(0.22) * c), "c", "fill:#555");
    svg.textAt({10, 24}, "a hinge: post A (blue), door B (red), the limits' range (green), the angle theta", "fill:#333");

    const double x = 630;
    svg.textAt({x, 90}, "jointFrame and the angles:");
    svg.textAt({x, 120}, jointText("theta = twistAngle = %.3f rad", double(angle)), "font-size:13px");
    svg.textAt({x, 142}, jointText("limits [%.1f, %.1f] rad", double(hinge.limits->first), double(hinge.limits->second)), "font-size:13px");
    svg.textAt({x, 172}, jointText("a_B off a_A: swingAngle = %.3f rad", double(tilt)), "font-size:13px");
    svg.textAt({x, 194}, jointText("a_B . b = %.3f, a_B . c = %.3f", double(frame.axisB.dot(b)), double(frame.axisB.dot(c))), "font-size:13px");
    svg.textAt({x, 216}, "(the two angular rows' errors)", "font-size:13px;fill:#555");
    svg.textAt({x, 246}, jointText("anchors apart: %.1f mm", double((frame.anchorB - frame.anchorA).norm()) * 1000), "font-size:13px");
    svg.textAt({x, 268}, "(the three point rows' error)", "font-size:13px;fill:#555");
    return svg.save(path);
}

bool drawSwingTwist(const std::string& path) {
    // A cone-twist joint with its axis along A's y: B has swung 0.5 rad about a direction across
    // the axis and twisted 0.4 rad about it. swingAngle and twistAngle take the turn apart.
    World world;
    const int a = jointAddBox(world, "A", BodyType::Static, Vec3(Real(0.2), Real(0.05), Real(0.2)), Transform{});
    const Vec3 across = Vec3(1, 0, 1).normalized();
    const Quat swing(Eigen::AngleAxis<Real>(Real(0.5), across));
    const Quat twist(Eigen::AngleAxis<Real>(Real(0.4), Vec3::UnitY()));
    const int b = jointAddBox(world, "B", BodyType::Dynamic, Vec3(Real(0.04), Real(0.5), Real(0.04)),
                         Transform{swing * Vec3(0, Real(0.55), 0), swing * twist});
    JointDesc joint;
    joint.type = JointType::ConeTwist;
    joint.bodyA = a;
    joint.bodyB = b;
    joint.localAnchorA = Vec3(0, Real(0.05), 0);
    joint.localAnchorB = Vec3(0, Real(-0.5), 0);
    joint.axis = Vec3::UnitY();
    joint.coneAngle = Real(0.7);
    joint.twistLimits = std::make_pair(Real(-0.5), Real(0.5));
    const JointFrame frame = jointFrame(world, joint);
    const Real swingMeasured = swingAngle(frame), twistMeasured = twistAngle(frame.deviation, joint.axis);

    Svg svg(900, 480);
    const Viewport view{0, 40, 600, 440, {Real(0.15), Real(0.55)}, 330};
    const Vec3 apex = frame.anchorA;
    // The cone: the circle one unit along A's axis at the cone angle, and two of its lines.
    const Vec3 onCone = Eigen::AngleAxis<Real>(joint.coneAngle, Vec3::UnitZ()) * frame.axisA;
    std::vector<Point2> rim = jointArc(apex, frame.axisA, onCone, 0, 2 * double(kPi), 1, jointOblique);
    svg.polygon(view, rim, "fill:#2ca02c;fill-opacity:0.1;stroke:#2ca02c;stroke-width:1.5");
    // Its outline: the lines from the apex to the rim's leftmost and rightmost points.
    const auto byX = [](const Point2& p, const Point2& q) { return p.x < q.x; };
    for (const Point2& edge : {*std::min_element(rim.begin(), rim.end(), byX), *std::max_element(rim.begin(), rim.end(), byX)})
        svg.line(view, jointOblique(apex), edge, "stroke:#2ca02c;stroke-width:1");
    jointWireBox(svg, view, Vec3(Real(0.04), Real(0.5), Real(0.04)), world.bodies[std::size_t(b)].transform,
            "stroke:#d62728;stroke-width:1;stroke-opacity:0.6");
    svg.arrow(view, jointOblique(apex), jointOblique(apex + Real(1.1) * frame.axisA), "#1f77b4", 2.5);
    svg.arrow(view, jointOblique(apex), jointOblique(apex + Real(1.1) * frame.axisB), "#d62728", 2.5);
    svg.text(view, jointOblique(apex + Real(1.13) * frame.axisA), "a_A", "fill:#1f77b4");
    svg.text(view, jointOblique(apex + Real(1.13) * frame.axisB), "a_B", "fill:#d62728");
    // The swing: the arc from A's axis to B's, in the plane they span.
    const Vec3 swingAxis = frame.axisA.cross(frame.axisB).normalized();
    svg.polyline(view, jointArc(apex, swingAxis, frame.axisA, 0, double(swingMeasured), 0.45, jointOblique), "stroke:#000;stroke-width:2");
    svg.text(view, jointOblique(apex + Real(0.5) * (Eigen::AngleAxis<Real>(swingMeasured / 2, swingAxis) * frame.axisA)),
             jointText("swing %.2f", double(swingMeasured)));
    // The twist: at B's axis, a mark that B carries against the mark the swing alone carries.
    const Quat swingOnly = frame.rotationA * swing;  // the swing part of the deviation, in the world
    const Vec3 tip = apex + Real(0.9) * frame.axisB;
    const Vec3 swungMark = swingOnly * Vec3::UnitX();
    const Vec3 bodyMark = world.bodies[std::size_t(b)].transform.rotation * Vec3::UnitX();
    svg.line(view, jointOblique(tip), jointOblique(tip + Real(0.25) * swungMark), "stroke:#000;stroke-width:1.5;stroke-dasharray:4 3");
    svg.line(view, jointOblique(tip), jointOblique(tip + Real(0.25) * bodyMark), "stroke:#d62728;stroke-width:2");
    svg.polyline(view, jointArc(tip, frame.axisB, swungMark, 0, double(twistMeasured), 0.18, jointOblique), "stroke:#000;stroke-width:2");
    svg.text(view, jointOblique(tip + Real(0.28) * bodyMark), jointText("twist %.2f", double(twistMeasured)));
    svg.textAt({10, 24}, "a cone-twist joint: the cone (green) that a_B may not leave, the swing and the twist", "fill:#333");

    const double x = 610;
    svg.textAt({x, 90}, "q = (qA^-1 qB) qref^-1 = swing * twist");
    svg.textAt({x, 120}, jointText("swingAngle = %.3f rad (built: 0.5)", double(swingMeasured)), "font-size:13px");
    svg.textAt({x, 142}, jointText("cone angle %.2f: inside, row not reached", double(joint.coneAngle)), "font-size:13px");
    svg.textAt({x, 172}, jointText("twistAngle = %.3f rad (built: 0.4)", double(twistMeasured)), "font-size:13px");
    svg.textAt({x, 194}, jointText("twist limits [%.1f, %.1f]: inside", double(joint.twistLimits->first), double(joint.twistLimits->second)),
               "font-size:13px");
    return svg.save(path);
}

bool drawRagdollLimits(const std::string& path) {
    // addRagdoll's body standing, its joints' limits drawn at the anchors: from the front, the
    // cones of the spine, neck, shoulders and hips; from the side, the ranges of the elbows and
    // knees (elbows bend forward, knees back).
    World world;
    const Ragdoll ragdoll = addRagdoll(world, RagdollSpec{});
    Svg svg(900, 560);
    const Viewport front{0, 40, 450, 520, {0, Real(0.95)}, 260};
    const Viewport sideView{450, 40, 450, 520, {0, Real(0.95)}, 260};
    const auto frontOf = [](const Vec3& p) { return Point2{double(p.x()), double(p.y())}; };
    const auto sideOf = [](const Vec3& p) { return Point2{double(p.z()), double(p.y())}; };
    for (int panel = 0; panel < 2; ++panel) {
        const Viewport& view = panel == 0 ? front : sideView;
        const auto project = [&](const Vec3& p) { return panel == 0 ? frontOf(p) : sideOf(p); };
        for (int body : ragdoll.bodies) {
            const Body& part = world.bodies[std::size_t(body)];
            const Transform& pose = part.transform;
            if (part.shape.type == ShapeType::Sphere) {
                svg.circle(view, project(pose.position), double(part.shape.radius), "fill:#ddd;stroke:#999");
            } else if (part.shape.type == ShapeType::Capsule) {
                const Vec3 end = Vec3(0, part.shape.halfHeight, 0);
                svg.line(view, project(pose.apply(-end)), project(pose.apply(end)),
                         jointText("stroke:#ddd;stroke-linecap:round;stroke-width:%.1f", 2 * double(part.shape.radius) * view.pixelsPerMetre));
            } else {
                const Vec3& h = part.shape.halfExtents;
                const Vec3 u = panel == 0 ? Vec3(h.x(), 0, 0) : Vec3(0, 0, h.z());
                const Vec3 v(0, h.y(), 0);
                svg.polygon(view, {project(pose.apply(-u - v)), project(pose.apply(u - v)), project(pose.apply(u + v)), project(pose.apply(-u + v))},
                            "fill:#ddd;stroke:#999");
            }
        }
        for (int index : ragdoll.joints) {
            const JointDesc& joint = world.joints[std::size_t(index)];
            const JointFrame frame = jointFrame(world, joint);
            const Vec3 child = world.bodies[std::size_t(joint.bodyB)].transform.position;
            std::vector<Point2> sector = {project(frame.anchorA)};
            if (joint.type == JointType::ConeTwist && panel == 0) {
                // The cone's outline in the front plane: the axis turned by the cone angle either way.
                for (int i = 0; i <= 24; ++i) {
                    const Real angle = joint.coneAngle * Real(2 * i - 24) / 24;
                    sector.push_back(project(frame.anchorA + Real(0.16) * (Eigen::AngleAxis<Real>(angle, Vec3::UnitZ()) * frame.axisA)));
                }
                svg.polygon(view, sector, "fill:#2ca02c;fill-opacity:0.25;stroke:#2ca02c;stroke-width:1");
                svg.text(view, project(frame.anchorA + Real(0.19) * frame.axisA),
                         jointText("%.0f", double(joint.coneAngle * 180 / kPi)), "font-size:11px;fill:#2ca02c");
            } else if (joint.type == JointType::Hinge && panel == 1 && frame.anchorA.x() > 0) {
                // The range the child's bone may sweep: its rest direction turned about the axis.
                const Vec3 rest = (child - frame.anchorA).normalized();
                for (int i = 0; i <= 24; ++i) {
                    const Real angle = joint.limits->first + (joint.limits->second - joint.limits->first) * Real(i) / 24;
                    sector.push_back(project(frame.anchorA + Real(0.16) * (Eigen::AngleAxis<Real>(angle, frame.axisA) * rest)));
                }
                svg.polygon(view, sector, "fill:#ff7f0e;fill-opacity:0.25;stroke:#ff7f0e;stroke-width:1");
                svg.text(view, project(frame.anchorA) , jointText(" [%.0f, %.0f]", double(joint.limits->first * 180 / kPi),
                                                                  double(joint.limits->second * 180 / kPi)), "font-size:11px;fill:#ff7f0e");
            }
            svg.dot(view, project(frame.anchorA), 3, "#000");
        }
    }
    svg.textAt({10, 24}, "addRagdoll's joints, in degrees: cones from the front (green), hinge ranges from the side (orange)", "fill:#333");
    svg.textAt({20, 540}, "front");
    svg.textAt({470, 540}, "side (facing right)");
    return svg.save(path);
}

}  // namespace figures
