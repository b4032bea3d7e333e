// The contact cache across steps, and the search once per frame (speculative points that
// follow their bodies through the substeps) against the search every substep.
#include "04_pgs/chapter.h"
#include "04_pgs/scenes.h"
#include "ch04_support.h"
#include "support/fixture.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace stepwise;

TEST_CASE("a resting contact persists: same feature id, impulses carried, anchors on both bodies", "[ch04][cache]") {
    World world = test::makeWorld();
    test::addGround(world);
    const int ball = test::addSphere(world, Vec3(0, Real(0.498), 0), Real(0.5), BodyType::Dynamic, 1);
    const int box = test::addBox(world, Vec3(3, Real(0.498), 0), Vec3::Constant(Real(0.5)), BodyType::Dynamic,
                                 Quat::Identity(), 1);
    Pipeline pipeline = makeChapter04Pipeline(world);
    test::simulate(world, pipeline, 1.0);
    // Before the next search, the cache holds last step's solved points.
    const std::vector<Contact> before = world.contacts;
    REQUIRE(findContact(before, BodyPair{0, ball}) != nullptr);
    findContacts(world);
    const Contact* ballContact = findContact(world.contacts, BodyPair{0, ball});
    REQUIRE(ballContact != nullptr);
    const ContactPoint& point = ballContact->points[0];
    CHECK(point.featureId == makeFeatureId(makeFeature(FeatureKind::Face, 3), makeFeature(FeatureKind::Core, 0)));
    CHECK(point.persisted);
    CHECK(point.normalImpulse == findContact(before, BodyPair{0, ball})->points[0].normalImpulse);
    CHECK(point.normalImpulse > 0);
    // The anchors reproduce the world points.
    CHECK((world.bodies[0].transform.apply(point.localAnchorA) - point.pointA).norm() < 1e-5);
    CHECK((world.bodies[ball].transform.apply(point.localAnchorB) - point.pointB).norm() < 1e-5);
    // The box's one point is named by GJK/EPA features: a known kind on both sides.
    const Contact* boxContact = findContact(world.contacts, BodyPair{0, box});
    REQUIRE(boxContact != nullptr);
    CHECK((boxContact->points[0].featureId >> 29) != 0);
    CHECK((boxContact->points[0].featureId & 0xFFFF) >> 13 != 0);
}

TEST_CASE("contacts are listed in canonical pair order whatever order the candidates came in", "[ch04][cache]") {
    World world = buildSpherePitScene(20);
    Pipeline pipeline = makeChapter04Pipeline(world);
    test::simulate(world, pipeline, 2.0);
    std::vector<BodyPair> candidates = findAllPairCandidates(world);
    REQUIRE(candidates.size() > 10);
    World reversed = world;
    std::reverse(candidates.begin(), candidates.end());
    updateContacts(reversed, candidates);
    findContacts(world);
    REQUIRE(world.contacts.size() == reversed.contacts.size());
    for (std::size_t i = 0; i < world.contacts.size(); ++i) {
        CHECK(world.contacts[i].pair() == reversed.contacts[i].pair());
        if (i > 0) CHECK(world.contacts[i - 1].pair() < world.contacts[i].pair());
    }
}

TEST_CASE("searched once per frame, balls bounce to e^2 h through speculative points", "[ch04][cache]") {
    const Real height = 2;
    World world = buildBounceScene(height);
    world.settings.substeps = 64;
    Pipeline pipeline = makeChapter04Pipeline(world, StepOrder::SplitIntegration, ContactSearch::OncePerFrame);
    REQUIRE(pipeline.find(stage_group::kNarrowphase)->frequency == StageFrequency::FrameStart);
    const int ball = world.findBody("ball-e0.6");
    double apex = 0;
    bool bounced = false, falling = false;
    test::simulate(world, pipeline, 2.5, [&](const World& w) {
        const double bottom = w.bodies[ball].transform.position.y() - w.bodies[ball].shape.radius;
        const double vy = w.motionOf(ball)->linearVelocity.y();
        if (!bounced && vy > 0) bounced = true;
        if (bounced && !falling) {
            apex = std::max(apex, bottom);
            if (vy < 0) falling = true;
        }
    });
    INFO("apex " << apex << " m, e^2 h = " << 0.36 * height << " m");
    CHECK(falling);
    CHECK(test::relativeError(apex, 0.36 * height) < 0.02);
}

TEST_CASE("searched once per frame, a dropped ball comes to rest within the slop, points following their anchors",
          "[ch04][cache]") {
    World world = test::makeWorld();
    world.settings.substeps = 4;
    test::addGround(world);
    const int ball = test::addSphere(world, Vec3(0, Real(0.51), 0), Real(0.5), BodyType::Dynamic, 1);
    Pipeline pipeline = makeChapter04Pipeline(world, StepOrder::SplitIntegration, ContactSearch::OncePerFrame);
    double deepest = 0;
    test::simulate(world, pipeline, 3.0, [&](const World& w) {
        if (w.time > 1) deepest = std::max(deepest, static_cast<double>(test::overlapDepth(w, 0, ball)));
    });
    // The speculative point stops the ball at the surface before it overlaps: any depth from
    // 0 to the slop is at rest, and nothing pushes it deeper.
    CHECK(deepest <= world.settings.slop * 1.1);
    CHECK(std::abs(world.motionOf(ball)->linearVelocity.y()) < 1e-3);
}
