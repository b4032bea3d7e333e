// Figures for chapter 6, computed by the engine's own clipping and manifold code.
#include "figures.h"

#include "06_manifolds/clipping.h"
#include "06_manifolds/manifold.h"
#include "06_manifolds/polytope_faces.h"

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
