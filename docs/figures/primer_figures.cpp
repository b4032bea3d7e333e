// Figures for the primer, computed by the engine's own mass properties and chapter 4's solver.
#include "figures.h"

#include "04_pgs/solver.h"
#include "world/shape.h"

#include <cstdio>

namespace figures {

using namespace stepwise;

namespace {

// One row between a static ground (body 0) and `body` (body 1) along `direction` at arm `arm`.
ConstraintRow rowAt(const Vec3& direction, const Vec3& arm) {
    ConstraintRow row;
    row.bodyA = 0;
    row.bodyB = 1;
    row.linearB = direction;
    row.angularB = arm.cross(direction);
    return row;
}

}  // namespace

bool drawImpulseArm(const std::string& path) {
    // A 2 x 1 m box of 1 kg, seen from the side, pushed upwards at points along its bottom face.
    // The effective mass (chapter 4's effectiveMass, from the engine's inertia of the box) is
    // the box's mass at the centre, where the push only lifts, and falls towards the corners,
    // where part of the push turns the box instead.
    const Shape shape = Shape::box(Vec3(1, Real(0.5), Real(0.5)));
    const MassProperties mass = computeMassProperties(shape, Real(1) / shapeVolume(shape));
    std::vector<SolverBody> bodies(2);
    bodies[1].inverseMass = 1 / mass.mass;
    bodies[1].inverseInertia = mass.inertia.inverse();

    Svg svg(640, 560);
    const Viewport boxView{0, 20, 640, 260, {0, -0.05}, 200};
    const Viewport plot{0, 330, 640, 200, {0, 0.5}, 200};
    svg.polygon(boxView, {{-1, -0.5}, {1, -0.5}, {1, 0.5}, {-1, 0.5}}, "fill:#dbe6f5;stroke:#3b6fb6;stroke-width:2");
    svg.origin(boxView);
    for (double x : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
        svg.line(boxView, {0, 0}, {x, -0.5}, "stroke:#888;stroke-dasharray:4 3");
        svg.arrow(boxView, {x, -0.85}, {x, -0.52}, "#c0392b");
    }
    svg.text(boxView, {-1.5, -0.75}, "push n", "fill:#c0392b");
    svg.text(boxView, {0.1, 0.2}, "centre of mass");
    svg.text(boxView, {0.55, -0.3}, "arm r", "fill:#666");

    // The curve m_eff(x) / m, and the axis it is read against.
    std::vector<Point2> curve;
    for (int k = 0; k <= 80; ++k) {
        const Real x = Real(-1 + k / 40.0);
        const Real meff = effectiveMass(rowAt(Vec3::UnitY(), Vec3(x, Real(-0.5), 0)), bodies);
        curve.push_back({double(x), double(meff * bodies[1].inverseMass)});
    }
    svg.line(plot, {-1.1, 0}, {1.1, 0}, "stroke:#333");
    svg.line(plot, {-1.1, 0}, {-1.1, 1.05}, "stroke:#333");
    svg.line(plot, {-1.1, 1}, {1.1, 1}, "stroke:#bbb;stroke-dasharray:4 3");
    svg.polyline(plot, curve, "stroke:#c0392b;stroke-width:3");
    svg.text(plot, {-1.45, 0.97}, "m");
    svg.text(plot, {-1.5, 0.0}, "0");
    char label[160];
    std::snprintf(label, sizeof label, "at the end: %.2f m", double(curve.back().y));
    svg.text(plot, {0.55, curve.back().y + 0.1}, label, "fill:#c0392b");
    svg.textAt({10, 22}, "the effective mass along n of a push at each point of the bottom face", "fill:#333");
    return svg.save(path);
}

bool drawComplementarity(const std::string& path) {
    // Left: a 1 kg ball on the ground arrives with normal speed u0, from -2 (approaching) to 2 m/s
    // (leaving); one row of chapter 4's solver answers each. Every answer lies on one of two
    // half-axes: the ball leaves and the contact does nothing, or the contact pushes and the ball
    // stops approaching. Right: a friction row bounded by mu lambda_n = 0.5 N s against the
    // sliding speed the ball arrives with: it stops the slide when it can, else pushes at its bound.
    std::vector<SolverBody> bodies(2);
    bodies[1].inverseMass = 1;
    bodies[1].inverseInertia = Mat3::Identity() * Real(1 / (0.4 * 0.25 * 0.25));
    const Vec3 arm(0, Real(-0.25), 0);
    Svg svg(820, 400);
    const Viewport left{0, 40, 410, 340, {0.5, 0.6}, 75};
    const Viewport right{410, 40, 410, 340, {0, 0}, 75};
    std::vector<Point2> normal, friction;
    for (int k = 0; k <= 40; ++k) {
        const Real incoming = Real(-2 + k / 10.0);
        bodies[1].linearVelocity = Vec3(0, incoming, 0);
        bodies[1].angularVelocity = Vec3::Zero();
        std::vector<ConstraintRow> rows = {rowAt(Vec3::UnitY(), arm)};
        rows[0].lower = 0;  // a contact pushes, never pulls
        computeEffectiveMasses(rows, bodies);
        solveGaussSeidel(rows, bodies, 1);
        normal.push_back({double(rowVelocity(rows[0], bodies)), double(rows[0].impulse)});

        bodies[1].linearVelocity = Vec3(incoming, 0, 0);
        bodies[1].angularVelocity = Vec3::Zero();
        rows = {rowAt(Vec3::UnitX(), arm)};
        rows[0].lower = Real(-0.5), rows[0].upper = Real(0.5);
        computeEffectiveMasses(rows, bodies);
        solveGaussSeidel(rows, bodies, 1);
        friction.push_back({double(incoming), double(rows[0].impulse) / 0.5});
    }
    svg.arrow(left, {-0.3, 0}, {2.4, 0}, "#333");
    svg.arrow(left, {0, -0.3}, {0, 2.3}, "#333");
    svg.text(left, {1.6, -0.3}, "u after (m/s)");
    svg.text(left, {0.1, 2.2}, "lambda (N s)");
    for (const Point2& answer : normal) svg.dot(left, answer, 4, "#3b6fb6");
    svg.text(left, {0.3, 1.5}, "pushes: u = 0", "fill:#3b6fb6");
    svg.text(left, {0.8, 0.2}, "leaves: lambda = 0", "fill:#3b6fb6");
    svg.arrow(right, {-2.4, 0}, {2.4, 0}, "#333");
    svg.arrow(right, {0, -1.5}, {0, 1.5}, "#333");
    svg.text(right, {0.9, 0.2}, "slide before (m/s)");
    svg.text(right, {0.1, 1.3}, "lambda_t / (mu lambda_n)");
    svg.polyline(right, friction, "stroke:#e08a2e;stroke-width:3");
    for (const Point2& answer : friction) svg.dot(right, answer, 3, "#b0661e");
    svg.line(right, {-2.4, 1}, {2.4, 1}, "stroke:#bbb;stroke-dasharray:4 3");
    svg.line(right, {-2.4, -1}, {2.4, -1}, "stroke:#bbb;stroke-dasharray:4 3");
    svg.text(right, {-2.4, 1.08}, "+1", "fill:#777");
    svg.text(right, {-2.4, -1.25}, "-1", "fill:#777");
    svg.textAt({10, 22}, "a contact row: either it pushes or the bodies part", "fill:#333");
    svg.textAt({420, 22}, "a friction row: clamped to plus or minus mu lambda_n", "fill:#333");
    return svg.save(path);
}

}  // namespace figures
