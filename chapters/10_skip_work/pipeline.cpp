#include "10_skip_work/chapter.h"

#include "04_pgs/chapter.h"
#include "06_manifolds/chapter.h"

#include <algorithm>
#include <memory>

namespace stepwise {

namespace {

/// Chapter 5's sweep, run only when a body has left its grown box (the same pairs).
void growBounds(Pipeline& pipeline) {
    Stage* broadphase = pipeline.find(stage_group::kBroadphase);
    if (!broadphase) return;
    broadphase->run = [sweep = broadphase->run](World& stepWorld, Real dt) {
        if (chooseBroadphase(stepWorld) == BroadphaseMode::Sap)
            sweepAndPruneEnlarged(stepWorld);
        else
            sweep(stepWorld, dt);
    };
}

/// Chapter 6's manifolds behind the contact cache, with chapter 6's speculative look-ahead: the
/// whole frame for a substepped solve (relax, soft step), which moves the bodies through every
/// substep on the contacts found here.
void cacheContacts(Pipeline& pipeline, const World& world, const SkipWorkOptions& options) {
    Stage* narrowphase = pipeline.find(stage_group::kNarrowphase);
    if (!narrowphase || !options.contactCache.enabled) return;
    auto cache = std::make_shared<ContactCacheScratch>();
    const bool split = chooseStepOrder(world) == StepOrder::SplitIntegration;
    const ContactSearch search = chooseContactSearch(world);
    narrowphase->name = stageName(stage_group::kNarrowphase, "cached_manifold");
    narrowphase->run = [cache, rule = options.contactCache, boxBox = options.boxBoxQuery, split, search,
                        pairManifold = options.pairManifold](World& stepWorld, Real) {
        ManifoldOptions manifold;
        manifold.multiPoint = stepWorld.settings.manifoldContacts;
        manifold.pairManifold = pairManifold;
        if (boxBox) manifold.query = fastContactQuery;
        const bool wholeFrame = split && isSubstepped(stepWorld.settings.stabilisation);
        const int ahead = wholeFrame ? std::max(1, stepWorld.settings.substeps) : substepsAhead(stepWorld, search);
        updateManifoldsCached(stepWorld, static_cast<Real>(ahead), manifold, rule, *cache);
    };
}

}  // namespace

Pipeline makeChapter10Pipeline(const World& world) { return makeChapter10Pipeline(world, SkipWorkOptions{}); }

// [ch10-pipeline]
Pipeline makeChapter10Pipeline(const World& world, const SkipWorkOptions& options) {
    // Chapter 8's solve; its relax pass keeps the biased pass's joint rows (half the joint work of
    // a substep).
    JointOptions joints;
    joints.relaxOnBiasedRows = true;
    Pipeline pipeline = makeChapter08Pipeline(world, joints);
    if (options.enlargedBounds) growBounds(pipeline);
    cacheContacts(pipeline, world, options);
    if (!options.sleeping) {
        pipeline.setPlanNote(stage_group::kSleep, "off: switched off for comparison");
        return pipeline;
    }
    addSleepStages(pipeline, world);
    holdSleepersStill(pipeline);
    // A world asleep throughout has the pairs and contacts it had: nothing moved.
    for (const char* group : {stage_group::kBroadphase, stage_group::kNarrowphase}) {
        Stage* stage = pipeline.find(group);
        if (!stage) continue;
        stage->run = [run = stage->run](World& stepWorld, Real dt) {
            if (!everyBodyAsleep(stepWorld)) run(stepWorld, dt);
        };
    }
    return pipeline;
}
// [ch10-pipeline]

}  // namespace stepwise
