// Figures for chapter 6, computed by the engine's own clipping and manifold code.
#include "figures.h"

#include "06_manifolds/clipping.h"
#include "06_manifolds/manifold.h"
#include "06_manifolds/polytope_faces.h"
#include "06_manifolds/polytope_manifold.h"
#include "06_manifolds/reduction.h"
#include "03_epa/narrowphase.h"

#include <algorithm>
#include <cmath>

#include <cstdio>

namespace figures {

using namespace stepwise;

namespace {

Point2 topView(const Vec3& p) { return {static_cast<double>(p.x()), static_cast<double>(-p.z())}; }
Point2 sideView(const Vec3& p) { return {static_cast<double>(p.x()), static_cast<double>(p.y())}; }

std::vector<Vec3> worldCorners(const Shape& shape, const Transform& transform, int face) {
    std::vector<Vec3> corners;
    for (const Vec3& corner : polytopeFace(shape, face).corners) corners.push_back(transform.apply(corner));
    return corners;
}

}  // namespace

bool drawManifoldClipping(const std::string& path) {
    // A unit box (B) resting 1 cm deep across the corner of a slab (A), turned 30 degrees. Left,
    // seen from above: the reference face (the slab's top), its four side planes, the incident
    // face (the box's bottom), the clipped patch and the four points kept. Right, seen from the
    // side with the box tipped by 8 degrees: only what lies below the reference face is kept.
    const Shape slab = Shape::box(Vec3(1, Real(0.25), Real(0.75)));
    const Shape box = Shape::box(Vec3(Real(0.5), Real(0.5), Real(0.5)));
    const Transform slabPose{Vec3::Zero(), Quat::Identity()};
    const Transform boxPose{Vec3(Real(0.85), Real(0.74), Real(0.6)),
                            Quat(Eigen::AngleAxis<Real>(Real(0.5236), Vec3::UnitY()))};

    Svg svg(960, 480);
    const Viewport top{0, 50, 480, 420, {0.3, -0.2}, 150};
    const Viewport side{480, 50, 480, 420, {0.35, 0.45}, 150};

    // Left: the reference face and its side planes (dashed lines running past the corners).
    const std::vector<Vec3> reference = worldCorners(slab, slabPose, 3);  // +y face
    std::vector<Point2> referenceOutline;
    for (const Vec3& corner : reference) referenceOutline.push_back(topView(corner));
    svg.polygon(top, referenceOutline, "fill:#1f77b4;fill-opacity:0.15;stroke:#1f77b4;stroke-width:2");
    for (std::size_t k = 0; k < reference.size(); ++k) {
        const Vec3& start = reference[k];
        const Vec3& end = reference[(k + 1) % reference.size()];
        const Vec3 along = (end - start).normalized();
        svg.line(top, topView(start - Real(0.6) * along), topView(end + Real(0.6) * along),
                 "stroke:#1f77b4;stroke-width:1;stroke-dasharray:5 4");
        const Vec3 middle = Real(0.5) * (start + end);
        const Vec3 outward = (end - start).cross(Vec3::UnitY()).normalized();
        svg.arrow(top, topView(middle), topView(middle + Real(0.15) * outward), "#1f77b4", 1.5);
    }
    // The incident face, clipped by the engine's own clipper.
    const std::vector<Vec3> incident = worldCorners(box, boxPose, 2);  // -y face
    std::vector<Point2> incidentOutline;
    std::vector<ClipVertex> polygon;
    for (const Vec3& corner : incident) {
        incidentOutline.push_back(topView(corner));
        ClipVertex vertex;
        vertex.position = corner;
        polygon.push_back(vertex);
    }
    svg.polygon(top, incidentOutline, "fill:#d62728;fill-opacity:0.12;stroke:#d62728;stroke-width:2");
    std::vector<ClipPlane> planes;
    for (std::size_t k = 0; k < reference.size(); ++k) {
        ClipPlane plane;
        plane.normal = (reference[(k + 1) % reference.size()] - reference[k]).cross(Vec3::UnitY()).normalized();
        plane.offset = plane.normal.dot(reference[k]);
        planes.push_back(plane);
    }
    const std::vector<ClipVertex> clipped = clipPolygon(polygon, planes, CrossingFeatures{});
    std::vector<Point2> patch;
    for (const ClipVertex& vertex : clipped) patch.push_back(topView(vertex.position));
    svg.polygon(top, patch, "fill:#2ca02c;fill-opacity:0.35;stroke:#2ca02c;stroke-width:2");
    for (const Point2& corner : patch) svg.dot(top, corner, 4, "#2ca02c");
    Contact contact;
    collideManifold(slab, slabPose, box, boxPose, 0, contact);
    for (int i = 0; i < contact.pointCount; ++i) {
        const Point2 at = topView(contact.points[i].pointA);
        svg.circle(top, at, 0.045, "fill:none;stroke:#000;stroke-width:2.5");
        char label[32];
        std::snprintf(label, sizeof label, "%d", i + 1);
        svg.text(top, {at.x + 0.05, at.y + 0.05}, label, "font-weight:bold");
    }
    svg.text(top, {-0.95, 0.55}, "reference face (A's top)", "fill:#1f77b4");
    svg.text(top, {0.2, -1.3}, "incident face (B's bottom)", "fill:#d62728");
    char caption[160];
    std::snprintf(caption, sizeof caption, "from above: %zu clipped corners (green), %d kept (circled, in order)",
                  clipped.size(), contact.pointCount);
    svg.textAt({10, 24}, caption, "fill:#333");

    // Right: side view of a tipped box; the points above the reference face are dropped.
    const Transform tipped{Vec3(Real(0.6), Real(0.8), 0), Quat(Eigen::AngleAxis<Real>(Real(0.14), Vec3::UnitZ()))};
    std::vector<Point2> slabSide = {{-1, -0.25}, {1, -0.25}, {1, 0.25}, {-1, 0.25}};
    svg.polygon(side, slabSide, "fill:#1f77b4;fill-opacity:0.15;stroke:#1f77b4;stroke-width:2");
    std::vector<Point2> boxSide;
    for (const Vec3& local : {Vec3(-0.5, -0.5, 0), Vec3(0.5, -0.5, 0), Vec3(0.5, 0.5, 0), Vec3(-0.5, 0.5, 0)})
        boxSide.push_back(sideView(tipped.apply(local)));
    svg.polygon(side, boxSide, "fill:#d62728;fill-opacity:0.12;stroke:#d62728;stroke-width:2");
    svg.line(side, {-1.1, 0.25}, {1.6, 0.25}, "stroke:#1f77b4;stroke-width:1;stroke-dasharray:5 4");
    Contact tippedContact;
    collideManifold(slab, slabPose, box, tipped, 0, tippedContact);
    for (const Vec3& corner : worldCorners(box, tipped, 2)) {
        const bool kept = corner.y() <= Real(0.25);
        svg.dot(side, sideView(corner), 5, kept ? "#2ca02c" : "#aaa");
    }
    for (int i = 0; i < tippedContact.pointCount; ++i) {
        svg.arrow(side, sideView(tippedContact.points[i].pointB), sideView(tippedContact.points[i].pointA), "#000", 2);
    }
    svg.text(side, {-0.95, 0.33}, "reference plane", "fill:#1f77b4");
    char sideCaption[160];
    std::snprintf(sideCaption, sizeof sideCaption, "from the side, tipped 8 degrees: %d points kept (green)",
                  tippedContact.pointCount);
    svg.textAt({490, 24}, sideCaption, "fill:#333");
    return svg.save(path);
}

}  // namespace figures

namespace figures {

bool drawManifoldReduction(const std::string& path) {
    // A unit box (B) turned 45 degrees about the vertical and tipped by 1.5 degrees, resting 1 cm
    // deep on a slab (A) a little wider than it. Seen from above: the clipped patch is an octagon;
    // the engine's reduction keeps four of its corners, in the order of its four rules, and each
    // point carries the feature id that names it from step to step.
    const Shape slab = Shape::box(Vec3(Real(0.6), Real(0.25), Real(0.6)));
    const Shape box = Shape::box(Vec3(Real(0.5), Real(0.5), Real(0.5)));
    const Transform slabPose{Vec3::Zero(), Quat::Identity()};
    const Quat turn = Quat(Eigen::AngleAxis<Real>(Real(0.026), Vec3::UnitX())) *
                      Quat(Eigen::AngleAxis<Real>(Real(0.7853982), Vec3::UnitY()));
    const Transform boxPose{Vec3(0, Real(0.74), 0), turn};
    const ContactQuery query = collideShapes(slab, slabPose, box, boxPose);
    ManifoldCandidates candidates;
    if (!polytopeManifold(slab, slabPose, box, boxPose, query, Real(0.01), candidates)) return false;
    int chosen[kMaxManifoldPoints];
    const int kept = reduceManifold(candidates.points, candidates.normal, chosen);

    Svg svg(940, 560);
    const Viewport view{0, 50, 940, 510, {0, 0}, 330};
    std::vector<Point2> slabOutline, boxOutline, patch, quad;
    for (const Vec3& corner : worldCorners(slab, slabPose, 3)) slabOutline.push_back(topView(corner));
    for (const Vec3& corner : worldCorners(box, boxPose, 2)) boxOutline.push_back(topView(corner));
    svg.polygon(view, slabOutline, "fill:#1f77b4;fill-opacity:0.12;stroke:#1f77b4;stroke-width:2");
    svg.polygon(view, boxOutline, "fill:#d62728;fill-opacity:0.08;stroke:#d62728;stroke-width:2");
    for (const ManifoldPoint& point : candidates.points) patch.push_back(topView(point.pointA));
    svg.polygon(view, patch, "fill:#2ca02c;fill-opacity:0.25;stroke:#2ca02c;stroke-width:1.5");
    for (int k = 0; k < kept; ++k) quad.push_back(topView(candidates.points[static_cast<std::size_t>(chosen[k])].pointA));
    // The quadrilateral in angular order about its centre, and both areas (shoelace).
    Point2 middle;
    for (const Point2& p : quad) middle.x += p.x / kept, middle.y += p.y / kept;
    std::sort(quad.begin(), quad.end(), [&](Point2 p, Point2 q) {
        return std::atan2(p.y - middle.y, p.x - middle.x) < std::atan2(q.y - middle.y, q.x - middle.x);
    });
    const auto area = [](const std::vector<Point2>& polygon) {
        double twice = 0;
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const Point2& p = polygon[i];
            const Point2& q = polygon[(i + 1) % polygon.size()];
            twice += p.x * q.y - q.x * p.y;
        }
        return std::abs(twice) / 2;
    };
    svg.polygon(view, quad, "fill:none;stroke:#000;stroke-width:2;stroke-dasharray:6 4");
    for (const ManifoldPoint& point : candidates.points) {
        const Point2 at = topView(point.pointA);
        svg.dot(view, at, 4, "#2ca02c");
        char depth[32];
        std::snprintf(depth, sizeof depth, "%.1f mm", double(point.depth) * 1000);
        svg.text(view, {at.x + 0.02, at.y - 0.06}, depth, "fill:#555;font-size:11px");
    }
    const char* const rules[] = {"deepest", "farthest", "largest triangle", "most area added"};
    for (int k = 0; k < kept; ++k) {
        const ManifoldPoint& point = candidates.points[static_cast<std::size_t>(chosen[k])];
        const Point2 at = topView(point.pointA);
        svg.circle(view, at, 0.035, "fill:none;stroke:#000;stroke-width:2.5");
        char label[80];
        std::snprintf(label, sizeof label, "%d %s, id %s", k + 1, rules[k], featureIdLabel(point.featureId).c_str());
        const bool left = at.x < 0;
        svg.text(view, {at.x + (left ? -0.06 : 0.06), at.y + 0.045}, label,
                 std::string("font-weight:bold;font-size:12px") + (left ? ";text-anchor:end" : ""));
    }
    char caption[200];
    std::snprintf(caption, sizeof caption, "%zu clipped corners (green), %d kept: they hold %.0f%% of the patch's area",
                  candidates.points.size(), kept, 100 * area(quad) / area(patch));
    svg.textAt({10, 22}, caption, "fill:#333");
    svg.textAt({10, 42}, "labels: the order of the rules, and A's feature / B's feature", "fill:#333;font-size:12px");
    return svg.save(path);
}

}  // namespace figures
