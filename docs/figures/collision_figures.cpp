// Figures for chapters 2 and 3, computed by the engine's own collision code: whatever the
// figure shows is what the code does.
#include "figures.h"

#include "02_gjk/closest_point.h"
#include "02_gjk/support.h"
#include "03_epa/narrowphase.h"

#include <algorithm>
#include <cmath>

namespace figures {

using namespace stepwise;

namespace {

constexpr const char* kBlue = "#3b6fb6";
constexpr const char* kOrange = "#e08a2e";
constexpr const char* kRed = "#c0392b";
constexpr const char* kGreen = "#2e8b57";

Point2 flat(const Vec3& v) { return {double(v.x()), double(v.y())}; }

Transform turnedAboutZ(Real x, Real y, Real degrees) {
    Transform transform;
    transform.position = Vec3(x, y, 0);
    transform.rotation = Quat(Eigen::AngleAxis<Real>(degrees * Real(M_PI / 180), Vec3::UnitZ()));
    return transform;
}

// The box's outline in the z = 0 plane (boxes here only turn about z), from its support map:
// the farthest points along the four diagonal directions are its four corners.
std::vector<Point2> outline(const ConvexProxy& proxy) {
    std::vector<Point2> corners;
    const Transform& t = proxy.transform;
    for (Vec3 local : {Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3(-1, -1, 0), Vec3(1, -1, 0)})
        corners.push_back(flat(proxy.support(t.rotate(local))));
    return corners;
}

// Monotone-chain convex hull of points in the plane (Andrew 1979).
std::vector<Point2> convexHull(std::vector<Point2> points) {
    std::sort(points.begin(), points.end(), [](Point2 a, Point2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    auto cross = [](Point2 o, Point2 a, Point2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
    std::vector<Point2> hull(2 * points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
        hull[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);
    return hull;
}

}  // namespace

bool drawMinkowski(const std::string& path) {
    const Shape boxA = Shape::box(Vec3(Real(0.9), Real(0.45), Real(0.5)));
    const Shape boxB = Shape::box(Vec3(Real(0.55), Real(0.55), Real(0.5)));
    const ConvexProxy a{&boxA, turnedAboutZ(Real(0.5), Real(0.3), 20)};
    const ConvexProxy b{&boxB, turnedAboutZ(Real(-0.45), Real(-0.2), -15)};
    const Vec3 direction = Vec3(1, Real(0.7), 0).normalized();
    const SupportPoint support = minkowskiSupport(a, b, direction);

    Svg svg(900, 380);
    const Viewport left{0, 0, 450, 380, {0, 0.1}, 120};
    const Viewport right{450, 0, 450, 380, {0.75, 0.35}, 80};
    svg.polygon(left, outline(a), std::string("fill:#dbe6f5;stroke:") + kBlue + ";stroke-width:2");
    svg.polygon(left, outline(b), std::string("fill:#f8e3cc;stroke:") + kOrange + ";stroke-width:2;fill-opacity:0.7");
    svg.text(left, {1.3, 0.35}, "A", std::string("fill:") + kBlue + ";font-weight:bold");
    svg.text(left, {-0.5, -0.55}, "B", std::string("fill:") + kOrange + ";font-weight:bold");
    svg.arrow(left, {-1.5, 1.0}, {-1.5 + 0.5 * double(direction.x()), 1.0 + 0.5 * double(direction.y())}, "#000");
    svg.text(left, {-1.6, 1.15}, "d");
    svg.dot(left, flat(support.onA), 5, kBlue);
    svg.text(left, flat(support.onA + Vec3(Real(0.06), Real(0.02), 0)), "s_A(d)");
    svg.dot(left, flat(support.onB), 5, kOrange);
    svg.text(left, flat(support.onB + Vec3(Real(-0.55), Real(-0.2), 0)), "s_B(-d)");
    svg.textAt({10, 370}, "the two shapes and their support points", "fill:#555");

    // A - B: the hull of every corner difference (16 in this plane), drawn from the corners the
    // support maps give, and its support point from minkowskiSupport.
    std::vector<Point2> differences;
    for (Point2 p : outline(a))
        for (Point2 q : outline(b)) differences.push_back({p.x - q.x, p.y - q.y});
    for (Point2 p : differences) svg.dot(right, p, 2.5, "#999");
    svg.polygon(right, convexHull(differences), "fill:#e8e8e8;fill-opacity:0.6;stroke:#555;stroke-width:2");
    svg.origin(right);
    svg.text(right, {0.08, -0.2}, "origin: inside, so A and B overlap");
    const Point2 w = flat(support.w);
    const Point2 along{-double(direction.y()), double(direction.x())};
    svg.line(right, {w.x - 1.4 * along.x, w.y - 1.4 * along.y}, {w.x + 1.4 * along.x, w.y + 1.4 * along.y},
             "stroke:#000;stroke-dasharray:5,4");
    svg.dot(right, w, 6, kRed);
    svg.text(right, {w.x - 2.3, w.y + 0.35}, "s_A-B(d) = s_A(d) - s_B(-d)", std::string("fill:") + kRed);
    svg.textAt({460, 370}, "A - B (grey), its support point along d and the supporting line", "fill:#555");
    return svg.save(path);
}

bool drawVoronoiRegions(const std::string& path) {
    // Every pixel block asks closestPointToOrigin, the chapter's own routine, for the feature
    // of the triangle nearest to it (the triangle is moved so that the block is the origin).
    const Vec3 corners[3] = {Vec3(-1.2f, -0.7f, 0), Vec3(1.3f, -0.6f, 0), Vec3(-0.1f, 1.0f, 0)};
    Svg svg(640, 460);
    const Viewport view{0, 0, 640, 460, {0, 0.1}, 130};
    const char* colours[8] = {"#fde2c8", "#d9ecd0", "#d6e2f3", "#f3d6e8", "#e9e0f5", "#d0eeee", "#fbf3c4", "#eeeeee"};
    const double cell = 8;
    for (double py = 0; py < 460; py += cell) {
        int runRegion = -1;
        double runStart = 0;
        for (double px = 0; px <= 640; px += cell) {
            if (px >= 640) {  // end of the row: draw the last run
                svg.rect(runStart, py, px - runStart, cell, colours[runRegion]);
                break;
            }
            const double x = (px + cell / 2 - 320) / 130, y = 0.1 - (py + cell / 2 - 230) / 130;
            Vec3 moved[3];
            for (int i = 0; i < 3; ++i) moved[i] = corners[i] - Vec3(Real(x), Real(y), 0);
            const SimplexClosest closest = closestPointToOrigin(moved, 3, 1);
            int region = 6;  // the face
            if (closest.keptCount == 1) region = closest.kept[0];          // vertex 0, 1, 2
            if (closest.keptCount == 2) region = 2 + closest.kept[0] + closest.kept[1];  // edges 3, 4, 5
            if (region != runRegion) {  // one rectangle per run of equal regions
                if (runRegion >= 0) svg.rect(runStart, py, px - runStart, cell, colours[runRegion]);
                runRegion = region;
                runStart = px;
            }
        }
    }
    std::vector<Point2> triangle;
    for (const Vec3& corner : corners) triangle.push_back(flat(corner));
    svg.polygon(view, triangle, "fill:none;stroke:#333;stroke-width:2");
    const char* names[3] = {"A", "B", "C"};
    for (int i = 0; i < 3; ++i) {
        svg.dot(view, triangle[i], 4, "#333");
        svg.text(view, {triangle[i].x * 1.25, triangle[i].y * 1.25 + 0.05}, std::string("region of ") + names[i]);
    }
    svg.text(view, {-0.35, -0.05}, "face region");
    svg.text(view, {-0.2, -1.05}, "edge AB region");
    svg.text(view, {0.75, 0.55}, "edge BC region");
    svg.text(view, {-1.75, 0.45}, "edge AC region");
    svg.textAt({10, 450}, "colour: the feature closestPointToOrigin keeps for a query point there", "fill:#555");
    return svg.save(path);
}

bool drawContactArms(const std::string& path) {
    // A tilted box (B) pressed into a slab (A): chapter 3's contact, and the arms of chapter
    // 4's Jacobian J = (-n, -(r_A x n), n, r_B x n), each r from a centre of mass to the point.
    const Shape slab = Shape::box(Vec3(Real(1.6), Real(0.3), Real(1)));
    const Shape box = Shape::box(Vec3(Real(0.5), Real(0.35), Real(0.5)));
    const Transform slabPose = turnedAboutZ(Real(-0.6), 0, 0);
    const Transform boxPose = turnedAboutZ(Real(0.35), Real(0.78), 28);
    const ContactQuery contact = collideShapes(slab, slabPose, box, boxPose);
    Svg svg(640, 420);
    const Viewport view{0, 0, 640, 420, {0.1, 0.45}, 150};
    svg.polygon(view, outline({&slab, slabPose}), "fill:#e4e4e4;stroke:#666;stroke-width:2");
    svg.polygon(view, outline({&box, boxPose}), "fill:#dbe6f5;stroke:#3b6fb6;stroke-width:2;fill-opacity:0.8");
    const Point2 point = flat(contact.pointB), centerA = flat(slabPose.position), centerB = flat(boxPose.position);
    svg.arrow(view, centerA, point, kGreen);
    svg.arrow(view, centerB, point, kBlue);
    svg.arrow(view, point, {point.x + 0.5 * double(contact.normal.x()), point.y + 0.5 * double(contact.normal.y())},
              kRed, 2.5);
    svg.dot(view, centerA, 4, "#333");
    svg.dot(view, centerB, 4, "#333");
    svg.dot(view, point, 5, kRed);
    svg.text(view, {centerA.x - 0.2, centerA.y - 0.12}, "x_A (slab)");
    svg.text(view, {centerB.x + 0.08, centerB.y + 0.05}, "x_B (box)");
    svg.text(view, {(centerA.x + point.x) / 2, (centerA.y + point.y) / 2 - 0.15}, "r_A", std::string("fill:") + kGreen);
    svg.text(view, {(centerB.x + point.x) / 2 + 0.05, (centerB.y + point.y) / 2}, "r_B", std::string("fill:") + kBlue);
    svg.text(view, {point.x + 0.05, point.y + 0.45}, "n", std::string("fill:") + kRed);
    char label[200];
    const Vec3 armB = contact.pointB - boxPose.position;
    std::snprintf(label, sizeof label, "depth %.3f m;  (r_B x n)_z = %.3f m: a push along n also turns the box",
                  double(contact.depth), double(armB.cross(contact.normal).z()));
    svg.textAt({10, 410}, label, "fill:#555");
    return svg.save(path);
}

}  // namespace figures
