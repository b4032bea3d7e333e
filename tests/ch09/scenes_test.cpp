// Chapter 9's scenes show what their observe lines promise: the drop stops twice, the hull shows
// an EPA face, the bullet tunnels without continuous collision and not with it, and the stack's
// impulses flicker without warm starting and settle with it.
#include "09_debug/debug_session.h"
#include "09_debug/debug_views.h"
#include "09_debug/scenes.h"

#include "app/registry.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace stepwise;

namespace {

World runScene(World world, int frames) {
    Pipeline pipeline = chapterRegistry().makePipeline(world);
    for (int frame = 0; frame < frames; ++frame) pipeline.step(world);
    return world;
}

/// Mean over the last frames of how much the bottom box's total normal impulse changes from one
/// frame to the next, relative to its mean: a steady stack near 0, a jittering one far above.
double impulseFlicker(World world) {
    Pipeline pipeline = chapterRegistry().makePipeline(world);
    const int bottom = world.findBody("box0");
    std::vector<double> totals;
    for (int frame = 0; frame < 240; ++frame) {
        pipeline.step(world);
        if (frame < 120) continue;
        double total = 0;
        for (const Contact& contact : world.contacts)
            if (contact.bodyA == 0 && contact.bodyB == bottom)
                for (int i = 0; i < contact.pointCount; ++i) total += double(contact.points[i].normalImpulse);
        totals.push_back(total);
    }
    double change = 0, mean = 0;
    for (std::size_t i = 1; i < totals.size(); ++i) change += std::abs(totals[i] - totals[i - 1]);
    for (double total : totals) mean += total;
    return (change / double(totals.size() - 1)) / (mean / double(totals.size()));
}

/// Per-point impulse flicker at the bottom box: the same, point by point (the total of a
/// rocking box can stay steady while its corners trade load).
double pointFlicker(World world) {
    Pipeline pipeline = chapterRegistry().makePipeline(world);
    const int bottom = world.findBody("box0");
    double change = 0, sum = 0;
    std::vector<double> previous;
    for (int frame = 0; frame < 240; ++frame) {
        pipeline.step(world);
        std::vector<double> now;
        for (const Contact& contact : world.contacts)
            if (contact.bodyA == 0 && contact.bodyB == bottom)
                for (int i = 0; i < contact.pointCount; ++i) now.push_back(double(contact.points[i].normalImpulse));
        if (frame >= 120 && now.size() == previous.size())
            for (std::size_t i = 0; i < now.size(); ++i) {
                change += std::abs(now[i] - previous[i]);
                sum += now[i];
            }
        previous = now;
    }
    return sum > 0 ? change / sum : 0;
}

}  // namespace

TEST_CASE("debug-drop: contact debug mode stops twice, box first", "[ch09][scenes]") {
    World world = buildDebugDrop();
    DebugSession session(world, chapterRegistry().makePipeline(world));
    session.rules.stopOnNewContact = true;
    std::vector<BodyPair> stoppedBy;
    std::string stops;
    for (int frame = 0; frame < 180; ++frame) {
        if (session.step() != StopReason::NewContact) continue;
        stoppedBy.push_back(session.newContacts().front());
        stops += " frame " + std::to_string(frame) + ": " + world.bodies[std::size_t(stoppedBy.back().bodyA)].name + "-" +
                 world.bodies[std::size_t(stoppedBy.back().bodyB)].name;
    }
    INFO("stops:" << stops);
    REQUIRE(stoppedBy.size() == 2);
    CHECK(stoppedBy[0].bodyB == world.findBody("box"));
    CHECK(stoppedBy[1].bodyB == world.findBody("ball"));
}

TEST_CASE("debug-hull-on-box: once the gem lands, its pair has an EPA face", "[ch09][scenes]") {
    const World world = runScene(buildDebugHullOnBox(), 90);
    const int gem = world.findBody("gem"), crate = world.findBody("crate");
    CHECK(world.bodies[std::size_t(gem)].transform.position.y() > Real(0.6));   // on the crate, not beside it
    const PairDiagnosis diagnosis = diagnosePair(world, crate, gem);
    REQUIRE(diagnosis.overlapping);
    CHECK(diagnosis.hasEpaFace);
    CHECK(diagnosis.normal.y() > Real(0.9));
}

TEST_CASE("debug-tunnel: the bullet passes the wall with ccd off, and stops at it with ccd on", "[ch09][scenes]") {
    const World off = runScene(buildDebugTunnel(), 30);
    const int bullet = off.findBody("bullet");
    CHECK(off.bodies[std::size_t(bullet)].transform.position.x() > 1);
    World fixed = buildDebugTunnel();
    fixed.settings.ccd = CcdMode::On;
    const World on = runScene(fixed, 30);
    CHECK(on.bodies[std::size_t(bullet)].transform.position.x() < 0);
}

TEST_CASE("debug-jitter: without warm starting the bottom contacts' impulses flicker; with it they settle", "[ch09][scenes]") {
    World cold = buildDebugJitter();
    World warm = cold;
    warm.settings.warmStarting = true;
    const double coldFlicker = pointFlicker(cold), warmFlicker = pointFlicker(warm);
    INFO("per-point flicker cold " << coldFlicker << ", warm " << warmFlicker << "; total cold " << impulseFlicker(cold)
                                   << ", warm " << impulseFlicker(warm));
    CHECK(coldFlicker > 5 * warmFlicker);
}
