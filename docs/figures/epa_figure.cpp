// Chapter 3's figure: EPA's polytope part way through a query, the face it expands next, the
// new support point and the horizon, all from the chapter's own EPA code.
#include "figures.h"

#include "02_gjk/gjk.h"
#include "03_epa/polytope.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace figures {

using namespace stepwise;

bool drawEpaHorizon(const std::string& path) {
    const Shape boxA = Shape::box(Vec3(Real(0.8), Real(0.5), Real(0.6)));
    const Shape boxB = Shape::box(Vec3(Real(0.5), Real(0.5), Real(0.5)));
    Transform poseA, poseB;
    poseB.position = Vec3(Real(0.7), Real(0.55), Real(0.3));
    poseB.rotation = Quat(Eigen::AngleAxis<Real>(Real(0.6), Vec3(1, 2, Real(0.5)).normalized()));
    const ConvexProxy a{&boxA, poseA};
    const ConvexProxy b{&boxB, poseB};
    // Stop EPA after k expansions, for the first k whose next step removes more than one face
    // (a single seen face is the dull case), and look at that step.
    EpaResult result;
    int closest = -1;
    SupportPoint next;
    auto seesFrom = [](const EpaPolytope& polytope, const SupportPoint& point, const EpaFace& f) {
        return !f.removed && f.normal.dot(point.w - polytope.vertices[std::size_t(f.vertices[0])].w) > 0;
    };
    for (int expansions = 0; expansions < 8; ++expansions) {
        EpaSettings settings;
        settings.maxExpansions = expansions;
        settings.keepPolytope = true;
        result = epaPenetration(a, b, gjkIntersect(a, b).simplex, settings);
        if (result.polytope.faces.empty()) return false;
        closest = epa_polytope::closestFace(result.polytope);
        next = minkowskiSupport(a, b, result.polytope.faces[std::size_t(closest)].normal);
        const auto seen = std::count_if(result.polytope.faces.begin(), result.polytope.faces.end(),
                                        [&](const EpaFace& f) { return seesFrom(result.polytope, next, f); });
        if (seen > 1) break;
    }
    const EpaPolytope& polytope = result.polytope;
    auto sees = [&](const EpaFace& f) { return seesFrom(polytope, next, f); };

    // An orthographic view from a fixed direction: screen x, y from two axes across it.
    const Vec3 toViewer = Vec3(Real(0.5), Real(0.6), 1).normalized();
    const Vec3 screenX = Vec3::UnitY().cross(toViewer).normalized();
    const Vec3 screenY = toViewer.cross(screenX);
    auto project = [&](const Vec3& p) { return Point2{double(p.dot(screenX)), double(p.dot(screenY))}; };
    auto corners = [&](const EpaFace& f) {
        std::vector<Point2> points;
        for (int v : f.vertices) points.push_back(project(polytope.vertices[std::size_t(v)].w));
        return points;
    };

    Svg svg(640, 480);
    Vec3 middle = Vec3::Zero();
    for (const SupportPoint& vertex : polytope.vertices) middle += vertex.w / Real(polytope.vertices.size());
    const Viewport view{0, 30, 640, 420, project(middle), 110};
    // Back faces first, as dashed outlines; then front faces, filled by their role.
    for (const EpaFace& f : polytope.faces)
        if (!f.removed && f.normal.dot(toViewer) <= 0) svg.polygon(view, corners(f), "fill:none;stroke:#bbb;stroke-dasharray:4,3");
    for (std::size_t i = 0; i < polytope.faces.size(); ++i) {
        const EpaFace& f = polytope.faces[i];
        if (f.removed || f.normal.dot(toViewer) <= 0) continue;
        const char* fill = int(i) == closest ? "#9fbbe6" : sees(f) ? "#f4c7c0" : "#eeeeee";
        svg.polygon(view, corners(f), std::string("fill:") + fill + ";fill-opacity:0.85;stroke:#777;stroke-width:1");
    }
    // The horizon: edges of seen faces whose neighbour across the edge is not seen.
    int horizonEdges = 0;
    for (const EpaFace& f : polytope.faces) {
        if (!sees(f)) continue;
        for (int edge = 0; edge < 3; ++edge) {
            const int across = f.neighbours[edge];
            if (across >= 0 && sees(polytope.faces[std::size_t(across)])) continue;
            ++horizonEdges;
            const Vec3& from = polytope.vertices[std::size_t(f.vertices[edge])].w;
            const Vec3& to = polytope.vertices[std::size_t(f.vertices[(edge + 1) % 3])].w;
            svg.line(view, project(from), project(to), "stroke:#c0392b;stroke-width:3.5");
            svg.line(view, project(next.w), project(from), "stroke:#c0392b;stroke-dasharray:5,4");  // the new fan
        }
    }
    svg.origin(view, project(Vec3::Zero()));
    const Point2 w = project(next.w);
    svg.dot(view, w, 6, "#c0392b");
    svg.text(view, {w.x + 0.06, w.y + 0.06}, "new support point w", "fill:#c0392b");
    svg.textAt({10, 20}, "blue: the face nearest the origin (+); pink: faces w sees; red: the horizon, and dashed the new faces", "fill:#333");
    char caption[200];
    std::snprintf(caption, sizeof caption,
                  "EPA on two boxes after %d expansions: %d live faces; the next step removes %d and fans %d new ones",
                  result.iterations, int(std::count_if(polytope.faces.begin(), polytope.faces.end(),
                                                       [](const EpaFace& f) { return !f.removed; })),
                  int(std::count_if(polytope.faces.begin(), polytope.faces.end(), sees)), horizonEdges);
    svg.textAt({10, 470}, caption, "fill:#555;font-size:12px");
    return svg.save(path);
}

}  // namespace figures
