// Figures for chapter 9, computed by the engine's own debugger: the hit result tree of a scene,
// the history ring with a rewind, speculative steps and the resume, and the slab test of a ray
// cast against a box.
#include "figures.h"

#include "08_joints/chapter.h"
#include "09_debug/debug_session.h"
#include "09_debug/hit_tree.h"
#include "09_debug/ray_cast.h"
#include "09_debug/scenes.h"
#include "world/state_hash.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace figures {

using namespace stepwise;

// Named, not anonymous: in a unity build the figure files share one translation unit.
namespace debug_figures {

/// An oblique view of the scene (x right, y up, z drawn up and to the right), so that the four
/// corners of a box resting on the ground fall apart on the page.
Point2 oblique(const Vec3& p) {
    return {static_cast<double>(p.x()) + 0.45 * static_cast<double>(p.z()),
            static_cast<double>(p.y()) + 0.3 * static_cast<double>(p.z())};
}

/// A viewport whose engine plane is the canvas in pixels, y up from the canvas's bottom: for plots
/// with different scales along x and y.
Viewport pixelView(double width, double height) { return Viewport{0, 0, width, height, {width / 2, height / 2}, 1}; }

void drawBoxEdges(Svg& svg, const Viewport& view, const Body& body, const std::string& style) {
    const Vec3 half = body.shape.halfExtents;
    Vec3 corners[8];
    for (int i = 0; i < 8; ++i)
        corners[i] = body.transform.apply(Vec3((i & 1) ? half.x() : -half.x(), (i & 2) ? half.y() : -half.y(),
                                               (i & 4) ? half.z() : -half.z()));
    for (int i = 0; i < 8; ++i)
        for (int bit : {1, 2, 4})
            if (!(i & bit)) svg.line(view, oblique(corners[i]), oblique(corners[i | bit]), style);
}

}  // namespace debug_figures

bool drawHitTree(const std::string& path) {
    // debug-drop through chapter 9's pipeline (chapter 8's) to frame 90, the frame of the demo's
    // screenshot: the tree of its contact cache, drawn as nodes, beside the scene with each point.
    using debug_figures::drawBoxEdges, debug_figures::oblique, debug_figures::pixelView;
    World world = buildDebugDrop();
    Pipeline pipeline = makeChapter08Pipeline(world);
    while (world.frame < 90) pipeline.step(world);
    const HitTree tree = buildHitTree(world);

    const double rowHeight = 26;
    int rows = 1;
    for (const HitPair& pair : tree.pairs) {
        rows += 1;
        for (const HitManifold& manifold : pair.manifolds) rows += 1 + static_cast<int>(manifold.points.size());
    }
    const double height = std::max(360.0, 70 + rows * rowHeight);
    Svg svg(1120, height);
    const Viewport scene{0, 40, 340, height - 60, {0.45, 0.4}, 130};
    const char* const colours[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd"};

    // The scene: the ground as a patch, the box's edges, the ball's outline, each point numbered.
    svg.polygon(scene, {oblique(Vec3(Real(-0.8), 0, Real(-0.6))), oblique(Vec3(Real(1.6), 0, Real(-0.6))),
                        oblique(Vec3(Real(1.6), 0, Real(0.8))), oblique(Vec3(Real(-0.8), 0, Real(0.8)))},
                "fill:#eee;stroke:#999");
    for (const Body& body : world.bodies) {
        if (body.shape.type == ShapeType::Box && body.type == BodyType::Dynamic) drawBoxEdges(svg, scene, body, "stroke:#555;stroke-width:1.5");
        if (body.shape.type == ShapeType::Sphere)
            svg.circle(scene, oblique(body.transform.position), double(body.shape.radius), "fill:none;stroke:#555;stroke-width:1.5");
    }
    svg.textAt({12, 24}, "debug-drop at frame 90: buildHitTree(world)", "fill:#333");

    // The tree: one row a node, indented by depth, joined to its parent by an elbow.
    const Viewport page = pixelView(1120, height);
    double y = height - 60;
    const double rootX = 360;
    svg.textAt({rootX, height - y}, "HitTree: " + std::to_string(tree.pairs.size()) + " pairs, " +
                                        std::to_string(tree.pointCount()) + " points",
               "font-weight:bold");
    const auto elbow = [&](double parentX, double parentY, double childX, double childY) {
        svg.polyline(page, {{parentX + 8, parentY - 6}, {parentX + 8, childY + 4}, {childX - 4, childY + 4}},
                     "stroke:#999;stroke-width:1");
    };
    for (std::size_t p = 0; p < tree.pairs.size(); ++p) {
        const HitPair& pair = tree.pairs[p];
        const std::string colour = colours[p % 4];
        const double pairY = y - rowHeight;
        elbow(rootX, y, rootX + 24, pairY);
        svg.textAt({rootX + 24, height - pairY}, "pair " + describePair(pair), "fill:" + colour + ";font-weight:bold");
        y = pairY;
        for (const HitManifold& manifold : pair.manifolds) {
            const double manifoldY = y - rowHeight;
            elbow(rootX + 24, pairY, rootX + 48, manifoldY);
            svg.textAt({rootX + 48, height - manifoldY}, "manifold, " + describeManifold(manifold), "fill:#333");
            y = manifoldY;
            for (std::size_t i = 0; i < manifold.points.size(); ++i) {
                const HitPoint& point = manifold.points[i];
                const double pointY = y - rowHeight;
                elbow(rootX + 48, manifoldY, rootX + 72, pointY);
                svg.textAt({rootX + 72, height - pointY}, describePoint(static_cast<int>(i), point), "fill:" + colour);
                y = pointY;
                // The same point in the scene: a dot on the surface, its number beside it.
                const Point2 at = oblique(point.position);
                svg.dot(scene, at, 5, colour);
                svg.arrow(scene, at, oblique(point.position + Real(0.25) * manifold.normal), colour, 1.5);
                svg.text(scene, {at.x + 0.03, at.y - 0.12}, "#" + std::to_string(i), "fill:" + colour + ";font-size:12px");
            }
        }
    }
    return svg.save(path);
}

namespace debug_figures {

/// What the timeline figure shows, from a real DebugSession on debug-drop: the ball's height on
/// the live frames and on the speculative ones, the ring's span, and what the session answered.
struct RewindRun {
    std::vector<Point2> live, speculative;   // (frame, ball height in m)
    long liveFrames = 150, landing = 34, oldest = -1, newest = -1;
    int capacity = 0;
    bool refused = false;         // rewindTo a frame older than the ring returned false
    bool ringUntouched = false;   // the speculative steps left the ring as it was
    bool sameBits = false;        // resume() gave back the live frame with its state hash
};

RewindRun runRewind() {
    // 150 live frames fill the 120-frame ring with frames 31 to 150; a rewind to frame 34 lands
    // while the ball still falls; a throw up and 40 speculative steps leave the ring and the live
    // world alone; resume() brings back frame 150, same hash.
    RewindRun run;
    World world = buildDebugDrop();
    Pipeline pipeline = makeChapter08Pipeline(world);
    DebugSession session(std::move(world), std::move(pipeline));
    const int ball = session.world().findBody("ball");
    const auto sample = [&] {
        return Point2{double(session.world().frame), double(session.world().bodies[std::size_t(ball)].transform.position.y())};
    };
    run.live.push_back(sample());
    while (session.world().frame < run.liveFrames) {
        session.step();
        run.live.push_back(sample());
    }
    const History& history = session.history();
    run.oldest = history.oldestFrame();
    run.newest = history.newestFrame();
    run.capacity = history.capacity();
    const std::uint64_t liveHash = session.frameHashes().back();
    run.refused = !session.rewindTo(run.oldest - 1);
    session.rewindTo(run.landing);
    BodyEdit push = currentState(session.world(), ball);
    push.linearVelocity.y() = 4;   // an inspector edit while rewound (up at 4 m/s): logged nowhere
    session.edit(push);
    run.speculative.push_back(sample());
    for (int k = 0; k < 40; ++k) {
        session.step();
        run.speculative.push_back(sample());
    }
    run.ringUntouched = history.newestFrame() == run.newest && history.size() == history.capacity();
    session.resume();
    run.sameBits = stateHash(session.world()) == liveHash && session.world().frame == run.liveFrames;
    return run;
}

}  // namespace debug_figures

bool drawRewindTimeline(const std::string& path) {
    // The history ring of debug-drop, a rewind, its speculative branch and the resume (runRewind).
    using debug_figures::pixelView;
    const debug_figures::RewindRun run = debug_figures::runRewind();
    const std::vector<Point2>& live = run.live;
    const std::vector<Point2>& speculative = run.speculative;
    const long oldest = run.oldest, newest = run.newest, liveFrames = run.liveFrames, landing = run.landing;
    const bool refused = run.refused, ringUntouched = run.ringUntouched, sameBits = run.sameBits;

    const double width = 960, height = 420, x0 = 60, y0 = 80, sx = 5.6, sy = 70;
    Svg svg(width, height);
    const Viewport page = pixelView(width, height);
    const auto at = [&](double frame, double metres) { return Point2{x0 + frame * sx, y0 + metres * sy}; };
    // The ring: the frames a rewind can land on.
    svg.rect(at(double(oldest), 0).x, height - at(0, 4.3).y, double(newest - oldest) * sx, 4.3 * sy, "#dbe9f6");
    svg.arrow(page, at(0, 0), at(double(liveFrames) + 12, 0), "#333", 1.5);
    svg.arrow(page, at(0, 0), at(0, 4.4), "#333", 1.5);
    for (int frame = 0; frame <= liveFrames; frame += 30) {
        svg.line(page, at(frame, 0), at(frame, -0.08), "stroke:#333");
        svg.text(page, {at(frame, 0).x - 8, at(0, -0.35).y}, std::to_string(frame), "font-size:12px");
    }
    svg.text(page, at(double(liveFrames) + 4, -0.35), "frame", "font-size:12px");
    svg.text(page, {at(0, 4.4).x + 8, at(0, 4.4).y - 14}, "ball height (m)", "font-size:12px");
    std::vector<Point2> gone, kept, branch;
    for (const Point2& sample : live) (sample.x < double(oldest) ? gone : kept).push_back(at(sample.x, sample.y));
    gone.push_back(kept.front());
    for (const Point2& sample : speculative) branch.push_back(at(sample.x, sample.y));
    svg.polyline(page, gone, "stroke:#999;stroke-width:2;stroke-dasharray:5 4");
    svg.polyline(page, kept, "stroke:#000;stroke-width:2");
    svg.polyline(page, branch, "stroke:#ff7f0e;stroke-width:2.5;stroke-dasharray:7 4");

    char label[200];
    std::snprintf(label, sizeof label, "history: the last %d frames (%ld to %ld)", run.capacity, oldest, newest);
    svg.text(page, at(double(oldest) + 2, 4.05), label, "fill:#1f77b4");
    std::snprintf(label, sizeof label, "frames 0 to %ld fell out of the ring: rewindTo(%ld) %s", oldest - 1,
                  oldest - 1, refused ? "returns false" : "DID NOT REFUSE");
    svg.text(page, at(1, 3.55), label, "fill:#777;font-size:12px");
    const Point2 landed = at(speculative.front().x, speculative.front().y);
    svg.dot(page, landed, 6, "#d62728");
    svg.line(page, at(double(landing) + 9.5, 0.52), landed, "stroke:#d62728;stroke-width:1");
    std::snprintf(label, sizeof label, "rewindTo(%ld) lands here; an edit throws the ball up at 4 m/s", landing);
    svg.text(page, at(double(landing) + 10, 0.45), label, "fill:#d62728;font-size:12px");
    std::snprintf(label, sizeof label, "%zu speculative steps: recorded nowhere%s", speculative.size() - 1,
                  ringUntouched ? ", the ring unchanged" : ", THE RING CHANGED");
    svg.text(page, at(speculative.back().x + 2, speculative.back().y + 0.05), label, "fill:#ff7f0e;font-size:12px");
    std::snprintf(label, sizeof label, "resume(): frame %ld, %s", liveFrames,
                  sameBits ? "the live state hash, bit for bit" : "STATE DIFFERS");
    svg.text(page, at(80, 0.95), label, "fill:#2ca02c;font-size:12px");
    svg.arrow(page, at(141, 1.0), at(double(liveFrames), 0.33), "#2ca02c", 1.5);
    for (int metres = 1; metres <= 3; ++metres) {
        svg.line(page, at(0, metres), at(-1.5, metres), "stroke:#333");
        svg.text(page, {at(0, metres).x - 20, at(0, metres).y - 4}, std::to_string(metres), "font-size:12px");
    }
    svg.textAt({12, 24}, "debug-drop under a DebugSession: the live run (black), the ring of kept frames (blue), a rewind (red) and its speculative branch (orange)",
               "fill:#333;font-size:13px");
    return sameBits && ringUntouched && refused && svg.save(path);
}

bool drawRaySlabs(const std::string& path) {
    // A box of half extents (1, 0.6) seen along z, and two rays. Each slab (|x| <= 1, |y| <= 0.6)
    // holds a ray over an interval [near, far] of its distance, drawn as a bar beside the ray;
    // the ray is in the box where the intervals overlap, from the latest near to the earliest
    // far. The upper ray's overlap: it enters through the x face. The lower ray leaves the x
    // slab before it enters the y slab: a miss. The red dot is where rayBox puts the entry.
    const Vec3 half(1, Real(0.6), 1);
    const Transform pose{Vec3::Zero(), Quat::Identity()};
    Svg svg(900, 500);
    const Viewport view{0, 90, 900, 410, {0.3, -0.55}, 110};
    svg.polygon(view, {{-1, -2.5}, {1, -2.5}, {1, 1.4}, {-1, 1.4}}, "fill:#1f77b4;fill-opacity:0.10;stroke:none");
    svg.polygon(view, {{-4, -0.6}, {4.5, -0.6}, {4.5, 0.6}, {-4, 0.6}}, "fill:#2ca02c;fill-opacity:0.10;stroke:none");
    svg.polygon(view, {{-1, -0.6}, {1, -0.6}, {1, 0.6}, {-1, 0.6}}, "fill:none;stroke:#000;stroke-width:2");
    svg.text(view, {-0.95, 1.2}, "x slab: |x| <= 1", "fill:#1f77b4");
    svg.text(view, {-3.7, 0.35}, "y slab: |y| <= 0.6", "fill:#2ca02c");
    const Vec3 origins[] = {Vec3(Real(-2.8), Real(-1.3), 0), Vec3(Real(-2.8), Real(-1.9), 0)};
    const Vec3 directions[] = {Vec3(3, Real(1.4), 0).normalized(), Vec3(3, Real(0.9), 0).normalized()};
    const char* const slabColours[] = {"#1f77b4", "#2ca02c"};
    const char* const names[] = {"upper", "lower"};
    int agreed = 0;
    for (int r = 0; r < 2; ++r) {
        const Vec3& origin = origins[r];
        const Vec3& direction = directions[r];
        double nears[2], fars[2];
        for (int axis = 0; axis < 2; ++axis) {
            const double o = double(origin[axis]), d = double(direction[axis]), h = double(half[axis]);
            nears[axis] = (-std::copysign(h, d) - o) / d;
            fars[axis] = (std::copysign(h, d) - o) / d;
        }
        const double entry = std::max(nears[0], nears[1]), exit = std::min(fars[0], fars[1]);
        const auto along = [&](double t, double aside) {
            const Vec3 p = origin + Real(t) * direction + Real(aside) * Vec3(-direction.y(), direction.x(), 0);
            return Point2{double(p.x()), double(p.y())};
        };
        svg.arrow(view, along(0, 0), along(std::min(std::max(fars[0], fars[1]), 7.5) + 0.4, 0), "#333", 1.5);
        for (int axis = 0; axis < 2; ++axis) {
            const double aside = axis == 0 ? 0.09 : -0.09;
            svg.line(view, along(nears[axis], aside), along(std::min(fars[axis], 7.5), aside),
                     std::string("stroke-width:5;stroke:") + slabColours[axis]);
            const Point2 start = along(nears[axis], aside * 2.4);
            svg.text(view, {start.x - 0.06, start.y - 0.06}, axis == 0 ? "x" : "y",
                     std::string("font-size:12px;font-weight:bold;fill:") + slabColours[axis]);
        }
        const RayHit hit = rayBox(Ray{origin, direction, kRealMax}, pose, half);
        char label[240];
        if (hit.hit) {
            svg.dot(view, {double(hit.point.x()), double(hit.point.y())}, 6, "#d62728");
            std::snprintf(label, sizeof label,
                          "%s ray: x slab [%.2f, %.2f], y slab [%.2f, %.2f]; enters at max(near) = %.2f <= min(far) = %.2f: "
                          "a hit (rayBox: %.2f)",
                          names[r], nears[0], fars[0], nears[1], fars[1], entry, exit, double(hit.distance));
        } else {
            std::snprintf(label, sizeof label,
                          "%s ray: x slab [%.2f, %.2f], y slab [%.2f, %.2f]; max(near) = %.2f > min(far) = %.2f: a miss "
                          "(rayBox: a miss)",
                          names[r], nears[0], fars[0], nears[1], fars[1], entry, exit);
        }
        svg.textAt({12, 52.0 + 22 * r}, label, "font-size:13px;fill:#333");
        agreed += hit.hit == (entry <= exit) ? 1 : 0;
    }
    svg.textAt({12, 24}, "The slab test: each slab holds a ray over an interval of its distance; the box holds it where they overlap",
               "fill:#333;font-size:13px");
    return agreed == 2 && svg.save(path);
}

}  // namespace figures
