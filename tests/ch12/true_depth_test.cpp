// A contact never reads deeper than its shapes overlap. The fast step carries manifolds on their
// anchors (chapter 10's cache) and reads a sphere's or capsule's point again as its surface along the
// normal; a normal that is off by degrees would make that surface point read centimetres deep where
// the shapes only touch, and the solve would push the pair apart at metres per second. Here every
// contact of a dense pile of all five stress kinds is checked at the poses the narrowphase saw:
// against the shapes' overlap along the contact's own normal (the reach of A - B along it), and
// against chapter 3's depth, the least overlap over all directions. Every pair reads within 1 mm of
// it: two polytopes keep last frame's reference face (their feature ids, and so their warm start,
// hold through small turns) only while its points read no deeper than the shapes overlap.
#include "03_epa/narrowphase.h"
#include "02_gjk/support.h"
#include "05_sap/stress_scene.h"
#include "12_planner/chapter.h"
#include "12_planner/contact_truth.h"
#include "10_skip_work/scenes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

using namespace stepwise;

TEST_CASE("no contact of a pile of mixed shapes reads deeper than its shapes overlap, +1 mm", "[ch12][cache]") {
    StressParams params;
    params.count = 343;  // a 7 x 7 x 7 block: enough pairs that touch within round-off
    params.density = StressDensity::Dense;
    params.shape = StressShape::All;
    params.dropHeight = 0;
    World world = buildStressScene(params);
    Pipeline pipeline = makeChapter12Pipeline(world);
    std::vector<Transform> before;
    Real worstAlongNormal = 0, worstExcess = 0;
    std::string worst;
    int checkedContacts = 0, carried = 0;
    int frame = 0;
    // Checked between the contact search and the solve, at the poses the search saw (chapter 7's
    // times of impact move fast bodies within the step, so the frame's start is not that pose).
    Stage check;
    check.name = "check:true_depth";
    check.frequency = StageFrequency::FrameStart;
    check.run = [&](World& checked, Real) {
        before.clear();
        for (const Body& body : checked.bodies) before.push_back(body.transform);
        for (const Contact& contact : checked.contacts) {
            const std::size_t ia = static_cast<std::size_t>(contact.bodyA), ib = static_cast<std::size_t>(contact.bodyB);
            const Body& a = checked.bodies[ia];
            const Body& b = checked.bodies[ib];
            const ContactQuery truth = collideShapes(a.shape, before[ia], b.shape, before[ib]);
            const Real overlap = truth.intersect ? truth.depth : Real(0);
            const ConvexProxy proxyA{&a.shape, before[ia], SupportMode::Extents}, proxyB{&b.shape, before[ib], SupportMode::Extents};
            const Real alongNormal = contact.normal.dot(minkowskiSupport(proxyA, proxyB, contact.normal).w);
            for (int i = 0; i < contact.pointCount; ++i) {
                const Real depth = contact.points[i].depth;
                worstAlongNormal = std::max(worstAlongNormal, depth - alongNormal);
                if (depth - overlap > worstExcess) {
                    worstExcess = depth - overlap;
                    std::ostringstream text;
                    text << "frame " << frame << ": " << a.name << " - " << b.name << " reads " << depth
                         << " m deep where the shapes overlap " << overlap << " m (" << alongNormal << " m along its normal)";
                    worst = text.str();
                }
            }
            carried += contact.pointCount > 0 && contact.points[0].persisted ? 1 : 0;
            ++checkedContacts;
        }
    };
    pipeline.insertBefore(stage_group::kPlan, check);
    for (; frame < 300; ++frame) pipeline.step(world);
    CHECK(checkedContacts > 100000);
    CHECK(carried > checkedContacts / 2);  // the cache is at work
    INFO(worst);
    CHECK(worstAlongNormal < Real(0.001));
    CHECK(worstExcess < Real(0.001));
}

TEST_CASE("no pair of a pile overlaps more than 1 mm beyond its contact's deepest point", "[ch12][cache]") {
    // The other side of the rule above: a contact that reads shallower than its shapes overlap lets
    // them sink by the difference, and max_penetration, which reads the contacts, never sees it.
    // A capsule clipped against a face whose edge it overhangs read 3 cm apart 5 cm into a box; a
    // held face whose clip cut off the deepest corner read a hull 2 cm short; a box record carried
    // through a 1.5 degree turn missed the far corner sinking 1.6 cm. Two piles of two layers,
    // checked at the contact search of every frame of their first three seconds, while they land
    // (without those rules they read 20 and 7 mm short within it).
    for (const bool unlike : {false, true}) {
        World world = unlike ? buildMixedPile(300, true, kUnlikePileSizes) : buildMixedPile(300);
        world.settings.sleeping = false;
        SpeedOptions options;
        options.sleeping = false;
        const ContactDepthErrors worst = depthAgainstTrue(world, options, 180);
        INFO(world.name << ": deepest beyond the overlap " << worst.deeper << " m, overlap unseen " << worst.shallower << " m");
        CHECK(worst.shallower < Real(0.001));
        CHECK(worst.deeper < Real(0.001));
    }
}
