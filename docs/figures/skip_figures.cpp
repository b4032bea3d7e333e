// Figures for chapter 10, each from worlds stepped by chapter 10's own pipeline: the grown boxes and
// the pairs they keep, the contact cache's rule against the motion of real pairs, and islands
// falling asleep and waking.
#include "figures.h"

#include "04_pgs/scenes.h"
#include "10_skip_work/chapter.h"
#include "10_skip_work/scenes.h"
#include "world/world.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace figures {

using namespace stepwise;

namespace {

const char* const kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#17becf"};

/// A body's outline seen along z: the convex hull of its box's corners (x, y), or a circle's centre.
std::vector<Point2> outline(const Body& body) {
    std::vector<Point2> corners;
    const Vec3 half = body.shape.type == ShapeType::Box ? body.shape.halfExtents : Vec3::Constant(boundingRadius(body.shape));
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 local((corner & 1 ? 1 : -1) * half.x(), (corner & 2 ? 1 : -1) * half.y(), (corner & 4 ? 1 : -1) * half.z());
        const Vec3 p = body.transform.apply(local);
        corners.push_back({double(p.x()), double(p.y())});
    }
    // Gift wrapping: eight points, no need for more.
    std::vector<Point2> hull;
    std::size_t start = 0;
    for (std::size_t i = 1; i < corners.size(); ++i)
        if (corners[i].x < corners[start].x || (corners[i].x == corners[start].x && corners[i].y < corners[start].y)) start = i;
    std::size_t at = start;
    do {
        hull.push_back(corners[at]);
        std::size_t next = (at + 1) % corners.size();
        for (std::size_t i = 0; i < corners.size(); ++i) {
            const double cross = (corners[next].x - corners[at].x) * (corners[i].y - corners[at].y) -
                                 (corners[next].y - corners[at].y) * (corners[i].x - corners[at].x);
            if (cross < -1e-12) next = i;
        }
        at = next;
    } while (at != start && hull.size() <= corners.size());
    return hull;
}

void drawBody(Svg& svg, const Viewport& view, const Body& body, const std::string& colour, double opacity) {
    char style[160];
    std::snprintf(style, sizeof style, "fill:%s;fill-opacity:%.2f;stroke:%s;stroke-width:1.5", colour.c_str(), opacity,
                  colour.c_str());
    if (body.shape.type == ShapeType::Sphere)
        svg.circle(view, {double(body.transform.position.x()), double(body.transform.position.y())},
                   double(body.shape.radius), style);
    else
        svg.polygon(view, outline(body), style);
}

void drawAabb(Svg& svg, const Viewport& view, const Aabb& box, const std::string& style) {
    const double x0 = box.min.x(), x1 = box.max.x(), y0 = box.min.y(), y1 = box.max.y();
    svg.polygon(view, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, style);
}

Point2 centreOf(const World& world, int body) {
    const Vec3& p = world.bodies[std::size_t(body)].transform.position;
    return {double(p.x()), double(p.y())};
}

/// The grown boxes' scene: a pyramid of three rows on the ground and a box falling beside it.
World grownBoxesWorld() {
    World world = emptyWorld("grown-boxes");
    world.settings.sleeping = false;
    world.settings.broadphase = BroadphaseMode::Sap;  // a scene this small would get brute force
    addGroundPlane(world);
    for (int row = 0; row < 3; ++row)
        for (int i = 0; i < 3 - row; ++i)
            addCrate(world, "box", Vec3(Real(-2.2) + Real(1.05) * (Real(i) + Real(0.5) * Real(row)), Real(0.5) + Real(row), 0),
                     Vec3::Constant(Real(0.5)), 1, Material{});
    addCrate(world, "falling", Vec3(Real(1.6), Real(2.2), 0), Vec3::Constant(Real(0.4)), 1, Material{});
    return world;
}

/// One panel of the grown boxes: bodies, grown boxes (dashed), this step's boxes where asked, pairs.
void drawBroadphasePanel(Svg& svg, const Viewport& view, const World& world, const BroadphaseState& grown,
                         const std::vector<BodyPair>& pairs, int highlight) {
    svg.line(view, {-4.2, 0}, {3.4, 0}, "stroke:#555;stroke-width:2");
    for (std::size_t i = 1; i < world.bodies.size(); ++i) {
        const std::string colour = int(i) == highlight ? "#d62728" : "#1f77b4";
        drawBody(svg, view, world.bodies[i], colour, 0.25);
        drawAabb(svg, view, grown.enlargedBounds[i], "fill:none;stroke:" + colour + ";stroke-dasharray:5 3");
        if (int(i) != highlight) continue;
        const Aabb& box = grown.bounds[i];
        drawAabb(svg, view, box, "fill:none;stroke:#d62728;stroke-width:2.5");

    }
    for (const BodyPair& pair : pairs) {
        const Point2 a = centreOf(world, pair.bodyB);
        // The ground (body 0) is far below: its pairs end on its top face, under the body.
        const Point2 b = pair.bodyA == 0 ? Point2{a.x, 0} : centreOf(world, pair.bodyA);
        svg.line(view, a, b, "stroke:#000;stroke-width:2");
        svg.dot(view, a, 3, "#000");
    }
}

}  // namespace

namespace {

/// A close-up of one box's lower right corner: its grown box (dashed) and this frame's box (solid).
void drawCornerInset(Svg& svg, const Aabb& grown, const Aabb& now) {
    const double reach = 0.12;  // m of each edge drawn from the corner
    const Viewport inset{620, 385, 320, 150, {double(grown.max.x()) - 0.15, double(grown.min.y()) + 0.07}, 600};
    svg.rect(inset.left, inset.top, inset.width, inset.height, "#f7f7f7");
    const auto corner = [&](const Aabb& box, const std::string& style) {
        const Point2 at{double(box.max.x()), double(box.min.y())};
        svg.polyline(inset, {{at.x - reach, at.y}, at, {at.x, at.y + reach}}, style);
    };
    corner(grown, "stroke:#d62728;stroke-width:1.5;stroke-dasharray:5 3");
    corner(now, "stroke:#d62728;stroke-width:2.5");
    char label[120];
    std::snprintf(label, sizeof label, "red box, lower right corner: %.1f cm out",
                  100 * double(grown.min.y() - now.min.y()));
    svg.textAt({inset.left + 8, inset.top + 18}, label, "fill:#d62728;font-size:12px");
}

}  // namespace

bool drawGrownBoxes(const std::string& path) {
    World world = grownBoxesWorld();
    Pipeline pipeline = makeChapter10Pipeline(world);
    pipeline.step(world);  // the first frame sweeps
    const World swept = world;
    // Step until the falling box leaves the grown box it was swept in: the sweep runs again.
    int skipped = 0;
    World before = world;
    for (int frame = 1; frame < 120; ++frame) {
        before = world;
        pipeline.step(world);
        if (!world.broadphase.sweepSkipped) break;
        ++skipped;
    }
    if (world.broadphase.sweepSkipped || skipped == 0) {
        std::fprintf(stderr, "fig-skip-grown-boxes: the falling box never left its grown box\n");
        return false;
    }
    // The second panel: the grown boxes of the sweep, and the falling box's box of the frame that
    // left its grown one (this frame's boxes are the step's own, bounds).
    BroadphaseState left = before.broadphase;
    left.bounds = world.broadphase.bounds;

    Svg svg(960, 545);
    const Viewport first{0, 40, 480, 330, {-0.4, 1.5}, 78};
    const Viewport second{480, 40, 480, 330, {-0.4, 1.5}, 78};
    drawBroadphasePanel(svg, first, swept, swept.broadphase, swept.broadphase.enlargedPairs, -1);
    const std::size_t falling = world.bodies.size() - 1;
    drawBroadphasePanel(svg, second, before, left, {}, int(falling));
    drawCornerInset(svg, left.enlargedBounds[falling], left.bounds[falling]);
    char label[200];
    std::snprintf(label, sizeof label, "the sweep: %zu pairs kept (black)", swept.broadphase.enlargedPairs.size());
    svg.textAt({16, 26}, label, "fill:#333");
    std::snprintf(label, sizeof label, "%d frames later the red box leaves its grown box: sweep again", skipped + 1);
    svg.textAt({496, 26}, label, "fill:#333");
    svg.line(first, {2.7, -1}, {2.7, 4}, "stroke:#ccc");
    return svg.save(path);
}

namespace {

/// How a pair's manifold fares at the next frame: carried, slid along the face, or built again.
enum class CacheOutcome { Carried, Slid, Rebuilt };

struct Drift {
    double metres = 0, degrees = 0;
    CacheOutcome outcome = CacheOutcome::Rebuilt;
};

/// Every touching pair's motion since its manifold was built, read as the next frame's cache reads it.
void collectDrifts(const World& world, std::vector<Drift>& drifts) {
    const ContactCacheRule rule;
    for (const Contact& contact : world.contacts) {
        if (!contact.builtPoseKnown || contact.pointCount == 0) continue;
        const Body& a = world.bodies[std::size_t(contact.bodyA)];
        const Body& b = world.bodies[std::size_t(contact.bodyB)];
        const Quat inverseA = a.transform.rotation.conjugate();
        const Vec3 moved = inverseA * (b.transform.position - a.transform.position) - contact.builtRelativePosition;
        // The turn from the rotation between the two poses: atan2 keeps small angles that acos of a
        // float dot product rounds to 0 or to 0.04 degrees.
        const Quat turn = (inverseA * b.transform.rotation) * contact.builtRelativeRotation.conjugate();
        Drift drift;
        drift.metres = double(moved.norm());
        drift.degrees = 2 * std::atan2(double(turn.vec().norm()), std::abs(double(turn.w()))) * 180 / 3.141592653589793;
        if (drift.metres == 0 && drift.degrees == 0) continue;  // built this frame
        drift.outcome = turnSwing(contact, a, b) > rule.maxTranslation                ? CacheOutcome::Rebuilt
                        : manifoldStillValid(contact, a.transform, b.transform, rule) ? CacheOutcome::Carried
                        : faceContactSlides(contact, a, b, rule)                    ? CacheOutcome::Slid
                                                                                    : CacheOutcome::Rebuilt;
        drifts.push_back(drift);
    }
}

/// Three scenes, sleeping off so resting pairs keep being looked at: a resting pyramid, boxes
/// pushed along the ground, a small pile falling into its pit.
std::vector<Drift> cacheDrifts() {
    std::vector<World> worlds;
    worlds.push_back(buildPyramidRow(1, 6));
    World sliders = emptyWorld("sliders");
    addGroundPlane(sliders);
    for (int i = 0; i < 6; ++i) {
        const int box = addCrate(sliders, "slider", Vec3(0, Real(0.5), Real(2 * i)), Vec3::Constant(Real(0.5)), 1, Material{});
        sliders.motionOf(box)->linearVelocity = Vec3(Real(1 + i), 0, 0);
    }
    worlds.push_back(sliders);
    worlds.push_back(buildMixedPile(120, false));
    std::vector<Drift> drifts;
    for (World& world : worlds) {
        world.settings.sleeping = false;
        Pipeline pipeline = makeChapter10Pipeline(world);
        for (int frame = 0; frame < 180; ++frame) {
            pipeline.step(world);
            if (frame % 6 == 5) collectDrifts(world, drifts);
        }
    }
    return drifts;
}

}  // namespace

bool drawCacheRule(const std::string& path) {
    std::vector<Drift> drifts = cacheDrifts();
    // Log axes, in decades: x = log10 of the distance B moved in A's frame (m), y = log10 of the
    // angle it turned (degrees); a decade is 70 px across and 48 px up.
    const double xMin = -9, xMax = 0, yMin = -7, yMax = 2, across = 70, up = 48;
    Svg svg(760, 560);
    const Viewport view{70, 40, 630, 432, {(xMin + xMax) / 2 * across, (yMin + yMax) / 2 * up}, 1};
    const auto at = [&](double x, double y) { return Point2{x * across, y * up}; };
    const auto drift = [&](double metres, double degrees) {
        return at(std::clamp(std::log10(std::max(metres, 1e-30)), xMin, xMax),
                  std::clamp(std::log10(std::max(degrees, 1e-30)), yMin, yMax));
    };
    // The turn that swings a unit box's corner (0.87 m from its centre) the rule's 1 mm.
    const double limitY = std::log10(2 * std::asin(0.001 / (2 * std::sqrt(0.75))) * 180 / 3.141592653589793);
    svg.polygon(view, {at(xMin, yMin), at(-3, yMin), at(-3, limitY), at(xMin, limitY)}, "fill:#2ca02c;fill-opacity:0.12");
    svg.polyline(view, {at(-3, yMin), at(-3, limitY), at(xMin, limitY)}, "stroke:#2ca02c;stroke-width:2");
    svg.polygon(view, {at(xMin, yMin), at(xMax, yMin), at(xMax, yMax), at(xMin, yMax)}, "fill:none;stroke:#333");
    char tick[24];
    for (int e = int(xMin); e <= int(xMax); ++e) {
        std::snprintf(tick, sizeof tick, "1e%d", e);
        svg.text(view, at(double(e) - 0.2, yMin - 0.45), tick, "fill:#333;font-size:12px");
    }
    for (int e = int(yMin); e <= int(yMax); ++e) {
        std::snprintf(tick, sizeof tick, "1e%d", e);
        svg.text(view, at(xMin - 0.75, double(e) - 0.1), tick, "fill:#333;font-size:12px");
    }
    svg.text(view, at(-6.8, yMin - 1.0), "how far B moved in A's frame since the build (m)", "fill:#333");
    svg.text(view, at(xMin + 0.1, yMax - 0.4), "how far B turned relative to A (degrees)", "fill:#333");
    svg.text(view, at(xMin + 0.2, limitY + 0.2), "1 mm, and a unit box's corner swung 1 mm: carried", "fill:#2ca02c");
    svg.text(view, at(xMin + 0.1, yMin + 0.15), "(no turn at all: on the bottom line)", "fill:#333;font-size:12px");
    const char* const colours[] = {"#2ca02c", "#1f77b4", "#d62728"};
    int counts[3] = {0, 0, 0};
    const std::size_t stride = std::max<std::size_t>(1, drifts.size() / 2500);
    for (std::size_t i = 0; i < drifts.size(); ++i) {
        const int kind = int(drifts[i].outcome);
        ++counts[kind];
        if (i % stride == 0) svg.dot(view, drift(drifts[i].metres, drifts[i].degrees), 2, colours[kind]);
    }
    char label[240];
    std::snprintf(label, sizeof label, "touching pairs, next frame: %d carried (green), %d slid along a face (blue), %d built again (red)",
                  counts[0], counts[1], counts[2]);
    svg.textAt({16, 24}, label, "fill:#333");
    return svg.save(path);
}

namespace {

/// The islands' scene: a three-row pyramid, a stack of three, a box pushed along the ground, and a
/// ball high above the stack that lands on it after the stack has gone to sleep.
World islandsWorld() {
    World world = emptyWorld("islands");
    addGroundPlane(world);
    for (int row = 0; row < 3; ++row)
        for (int i = 0; i < 3 - row; ++i)
            addCrate(world, "pyramid", Vec3(Real(-4.2) + Real(1.05) * (Real(i) + Real(0.5) * Real(row)), Real(0.5) + Real(row), 0),
                     Vec3::Constant(Real(0.5)), 1, Material{});
    for (int level = 0; level < 3; ++level)
        addCrate(world, "stack", Vec3(Real(0.3), Real(0.5) + Real(level), 0), Vec3::Constant(Real(0.5)), 1, Material{});
    const int slider = addCrate(world, "slider", Vec3(Real(1.8), Real(0.4), 0), Vec3::Constant(Real(0.4)), 1, Material{});
    world.motionOf(slider)->linearVelocity = Vec3(Real(4.5), 0, 0);
    addBall(world, "ball", Vec3(Real(0.3), Real(8.5), 0), Real(0.35), 1, Material{});
    return world;
}

/// The islands as the sleep pass joins them: awake dynamic bodies linked by touching contacts.
std::vector<int> islandsOf(const World& world) {
    std::vector<int> parent(world.bodies.size());
    for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = int(i);
    const auto root = [&](int body) {
        while (parent[std::size_t(body)] != body) body = parent[std::size_t(body)];
        return body;
    };
    const auto awake = [&](int body) {
        const Motion* motion = world.motionOf(body);
        return world.bodies[std::size_t(body)].type == BodyType::Dynamic && motion && !motion->asleep;
    };
    for (const Contact& contact : world.contacts)
        if (contact.pointCount > 0 && awake(contact.bodyA) && awake(contact.bodyB)) {
            const int a = root(contact.bodyA), b = root(contact.bodyB);
            parent[std::size_t(std::max(a, b))] = std::min(a, b);
        }
    for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = root(int(i));
    return parent;
}

void drawIslandsPanel(Svg& svg, const Viewport& view, const World& world, const std::string& title) {
    svg.line(view, {-5.6, 0}, {5.4, 0}, "stroke:#555;stroke-width:2");
    const std::vector<int> island = islandsOf(world);
    std::map<int, std::string> colourOf;
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        const Motion* motion = world.motionOf(int(i));
        if (!motion) continue;
        if (motion->asleep) {
            drawBody(svg, view, world.bodies[i], "#999999", 0.35);
            continue;
        }
        // An island's colour follows its root, the smallest body index: the same island keeps it.
        colourOf[island[i]] = kPalette[std::size_t(island[i]) % 7];
        drawBody(svg, view, world.bodies[i], colourOf[island[i]], 0.45);
    }
    char label[200];
    std::snprintf(label, sizeof label, "t = %.2f s: %zu awake islands, %d bodies asleep", world.time, colourOf.size(),
                  countSleeping(world));
    svg.textAt({view.left + 10, view.top + 18}, title, "fill:#333");
    svg.textAt({view.left + 10, view.top + 38}, label, "fill:#333;font-size:12px");
}

bool asleepAll(const World& world, const char* name) {
    for (std::size_t i = 0; i < world.bodies.size(); ++i)
        if (world.bodies[i].name == name && !world.motionOf(int(i))->asleep) return false;
    return true;
}

}  // namespace

bool drawIslands(const std::string& path) {
    World world = islandsWorld();
    Pipeline pipeline = makeChapter10Pipeline(world);
    const int ball = world.findBody("ball");
    pipeline.step(world);
    const World start = world;
    World resting, woken;
    bool restingFound = false, wokenFound = false;
    for (int frame = 1; frame < 300 && !wokenFound; ++frame) {
        pipeline.step(world);
        const bool stillSlides = !world.motionOf(world.findBody("slider"))->asleep;
        if (!restingFound && asleepAll(world, "pyramid") && asleepAll(world, "stack") && stillSlides) {
            resting = world;
            restingFound = true;
        }
        const bool ballLanded = std::any_of(world.contacts.begin(), world.contacts.end(), [&](const Contact& contact) {
            return contact.pointCount > 0 && contact.bodyB == ball && world.bodies[std::size_t(contact.bodyA)].name == "stack";
        });
        if (restingFound && ballLanded && !asleepAll(world, "stack")) {
            woken = world;
            wokenFound = true;
        }
    }
    if (!restingFound || !wokenFound) {
        std::fprintf(stderr, "fig-skip-islands: the scene did not sleep and wake as drawn (%d, %d)\n", restingFound, wokenFound);
        return false;
    }
    Svg svg(1080, 400);
    const double scale = 31;
    const Viewport panels[] = {{0, 10, 360, 390, {0, 5.3}, scale}, {360, 10, 360, 390, {0, 5.3}, scale},
                               {720, 10, 360, 390, {0, 5.3}, scale}};
    drawIslandsPanel(svg, panels[0], start, "all awake, one colour per island");
    drawIslandsPanel(svg, panels[1], resting, "pyramid and stack asleep (grey)");
    drawIslandsPanel(svg, panels[2], woken, "the ball lands: the stack wakes whole");
    svg.line(panels[1], {-5.8, -1}, {-5.8, 11}, "stroke:#ccc");
    svg.line(panels[2], {-5.8, -1}, {-5.8, 11}, "stroke:#ccc");
    return svg.save(path);
}

}  // namespace figures
