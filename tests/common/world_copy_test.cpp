// Copying the World is a complete snapshot: stages keep nothing of their own, so a copy taken
// mid-run and stepped on gives bit-identical states to the original (what rewind and replay
// rely on). Every built-in scene, through the latest chapter's pipeline, with and without
// substeps, with the broadphase auto chooses and with sweep and prune.
#include <catch2/catch.hpp>

#include "support/registry_fixture.h"
#include "app/runner.h"

#include <cstring>

using namespace stepwise;

namespace {

bool sameBits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(Real) * 3) == 0; }
bool sameBits(const Quat& a, const Quat& b) {
    return std::memcmp(a.coeffs().data(), b.coeffs().data(), sizeof(Real) * 4) == 0;
}

/// Every body's pose and velocity, and every contact point with its impulses, bit for bit.
bool identicalStates(const World& a, const World& b) {
    if (a.bodies.size() != b.bodies.size() || a.contacts.size() != b.contacts.size()) return false;
    for (std::size_t i = 0; i < a.bodies.size(); ++i) {
        if (!sameBits(a.bodies[i].transform.position, b.bodies[i].transform.position)) return false;
        if (!sameBits(a.bodies[i].transform.rotation, b.bodies[i].transform.rotation)) return false;
    }
    for (std::size_t i = 0; i < a.motions.size(); ++i) {
        if (!sameBits(a.motions[i].linearVelocity, b.motions[i].linearVelocity)) return false;
        if (!sameBits(a.motions[i].angularVelocity, b.motions[i].angularVelocity)) return false;
    }
    for (std::size_t c = 0; c < a.contacts.size(); ++c) {
        const Contact& x = a.contacts[c];
        const Contact& y = b.contacts[c];
        if (x.pair() != y.pair() || x.pointCount != y.pointCount || !sameBits(x.normal, y.normal)) return false;
        for (int p = 0; p < x.pointCount; ++p) {
            if (!sameBits(x.points[p].pointA, y.points[p].pointA) || x.points[p].featureId != y.points[p].featureId ||
                x.points[p].normalImpulse != y.points[p].normalImpulse)
                return false;
        }
    }
    return a.frame == b.frame;
}

}  // namespace

TEST_CASE("a copy of the world taken mid-run steps on exactly like the original", "[common][determinism]") {
    const Registry& registry = test::chapterRegistry();
    for (const SceneEntry& entry : registry.scenes()) {
        // Auto (brute force for small scenes), and sweep and prune forced: its kept order and
        // axis travel with the copy (World::broadphase).
        // The large scenes (the stress scenes, the pyramid) once, automatic broadphase, one substep: they took
        // two of CI's minutes in all four variants, and the small ones already cover them.
        const bool large = entry.build().bodies.size() > 60;
        for (BroadphaseMode broadphase : {BroadphaseMode::Auto, BroadphaseMode::Sap}) {
            for (int substeps : {1, 4}) {
                if (large && (broadphase != BroadphaseMode::Auto || substeps != 1)) continue;
                INFO("scene " << entry.name << ", " << substeps << " substeps, broadphase " << toString(broadphase));
                World original = loadSceneOrBuiltin(registry, entry.name);
                original.settings.substeps = substeps;
                original.settings.broadphase = broadphase;
                Pipeline pipeline = registry.makePipeline(original);
                for (int frame = 0; frame < 40; ++frame) pipeline.step(original);

                World copy = original;
                // A fresh pipeline, planned as the original's was, from the scene (chapter 7's CCD
                // plan looks at the speeds at the start; from the mid-run copy it may rightly differ):
                // nothing lives in a pipeline, so it carries the copy on alike.
                World scene = loadSceneOrBuiltin(registry, entry.name);
                scene.settings = original.settings;
                Pipeline copyPipeline = registry.makePipeline(scene);
                Pipeline sharedPipeline = pipeline;                   // or a copy of the running one
                World third = original;
                for (int frame = 0; frame < 60; ++frame) {
                    pipeline.step(original);
                    copyPipeline.step(copy);
                    sharedPipeline.step(third);
                }
                CHECK(identicalStates(original, copy));
                CHECK(identicalStates(original, third));
                CHECK(copy.candidatePairs == original.candidatePairs);
                if (original.broadphase.used == BroadphaseMode::Sap) {
                    // The copy went on from the original's sorted order, not from scratch.
                    CHECK(copy.broadphase.axis == original.broadphase.axis);
                    CHECK(copy.broadphase.fullSort == original.broadphase.fullSort);
                    CHECK(copy.broadphase.sortMoves == original.broadphase.sortMoves);
                }
            }
        }
    }
}
