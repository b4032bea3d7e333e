// Figures for chapter 3, computed by the engine's own support maps, narrowphase and closed
// forms: the depth as the smallest reach of A - B, and the box-sphere contact's two cases.
#include "figures.h"

#include "02_gjk/support.h"
#include "03_epa/closed_form.h"
#include "03_epa/narrowphase.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace figures {

using namespace stepwise;

namespace {

constexpr const char* kReachBlue = "#3b6fb6";
constexpr const char* kReachOrange = "#e08a2e";
constexpr const char* kReachRed = "#c0392b";
constexpr double kReachPi = 3.14159265358979323846;

Point2 planar(const Vec3& v) { return {double(v.x()), double(v.y())}; }

Transform turnedInPlane(Real x, Real y, Real degrees) {
    Transform transform;
    transform.position = Vec3(x, y, 0);
    transform.rotation = Quat(Eigen::AngleAxis<Real>(degrees * Real(kReachPi / 180), Vec3::UnitZ()));
    return transform;
}

}  // namespace

bool drawDepthReach(const std::string& path) {
    // Two boxes turned about z only: A - B is a prism along z, and its section z = 0 is what
    // directions in the plane see. For each direction n the support map gives the reach
    // h(n) = n . s_{A-B}(n); the depth is the smallest reach, and the narrowphase (GJK, then
    // EPA) must land on the same direction and distance.
    const Shape boxA = Shape::box(Vec3(Real(0.9), Real(0.45), Real(0.5)));
    const Shape boxB = Shape::box(Vec3(Real(0.5), Real(0.5), Real(0.5)));
    const Transform ta = turnedInPlane(0, 0, 10);
    const Transform tb = turnedInPlane(Real(1.05), Real(0.45), -25);
    const ConvexProxy a{&boxA, ta};
    const ConvexProxy b{&boxB, tb};

    std::vector<Point2> boundary, reach;
    double smallest = 1e30;
    Point2 smallestAt;
    for (int step = 0; step < 720; ++step) {
        const double angle = 2 * kReachPi * step / 720;
        const Vec3 n(Real(std::cos(angle)), Real(std::sin(angle)), 0);
        const Vec3 w = minkowskiSupport(a, b, n).w;
        const double h = double(n.dot(w));
        boundary.push_back(planar(w));
        reach.push_back({h * std::cos(angle), h * std::sin(angle)});
        if (h < smallest) smallest = h, smallestAt = reach.back();
    }
    const ContactQuery contact = collideShapes(boxA, ta, boxB, tb);

    Svg svg(560, 520);
    const Viewport view{0, 0, 560, 440, {-0.95, -0.25}, 112};
    svg.polygon(view, boundary, std::string("fill:#e8eef8;stroke:") + kReachBlue + ";stroke-width:2");
    svg.polyline(view, reach, std::string("stroke:") + kReachOrange + ";stroke-width:2;stroke-dasharray:6,4");
    svg.origin(view);
    svg.arrow(view, {0, 0}, planar(contact.depth * contact.normal), kReachRed, 3);
    svg.dot(view, smallestAt, 4, kReachOrange);
    char label[160];
    svg.textAt({20, 450}, "blue: A - B, its section z = 0 (the boxes turn about z only)", std::string("fill:") + kReachBlue);
    svg.textAt({20, 472}, "dashed: h(n) n, the reach of A - B along each direction n", std::string("fill:") + kReachOrange);
    std::snprintf(label, sizeof label, "dot: the smallest reach, %.4f m; arrow: EPA's d n, d = %.4f m", smallest,
                  double(contact.depth));
    svg.textAt({20, 494}, label, std::string("fill:") + kReachRed);
    return svg.save(path);
}

bool drawBoxSphereCases(const std::string& path) {
    // A grid of sphere centres around and inside a box (seen along z). Each centre is joined to
    // the contact point collideBoxSphere puts on the box: outside, the clamped centre; inside,
    // the nearest face, so the inside splits into the faces' regions along the box's diagonals.
    const Vec3 halfExtents(Real(1.0), Real(0.6), Real(0.5));
    const Transform box = turnedInPlane(0, 0, 0);
    const Real radius = Real(0.3);
    Svg svg(600, 480);
    const Viewport view{0, 0, 600, 430, {0, 0}, 140};
    svg.polygon(view, {{1.0, 0.6}, {-1.0, 0.6}, {-1.0, -0.6}, {1.0, -0.6}}, "fill:#f2f2f2;stroke:#555;stroke-width:2");
    for (int i = -8; i <= 8; ++i) {
        for (int j = -6; j <= 6; ++j) {
            const Vec3 center(Real(0.17 * i + 0.03), Real(0.2 * j + 0.02), 0);
            const ContactQuery contact = collideBoxSphere(halfExtents, box, center, radius);
            const Vec3 local = center.cwiseAbs();
            const bool inside = local.x() <= halfExtents.x() && local.y() <= halfExtents.y();
            const char* colour = inside ? kReachOrange : kReachBlue;
            svg.line(view, planar(center), planar(contact.pointA), std::string("stroke:") + colour + ";stroke-width:1.5");
            svg.dot(view, planar(center), 2.5, colour);
        }
    }
    svg.textAt({20, 450}, "blue: centre outside, joined to the clamped centre", std::string("fill:") + kReachBlue);
    svg.textAt({20, 472}, "orange: centre inside, joined to the nearest face", std::string("fill:") + kReachOrange);
    return svg.save(path);
}

}  // namespace figures
