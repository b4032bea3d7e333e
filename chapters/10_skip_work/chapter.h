#pragma once
// Chapter 10's pipeline: chapter 9's step (chapter 8's stages) doing only the work the frame needs.
// Four stages change: the broadphase sweeps only when a body has left its grown box
// (enlarged_bounds.h), the narrowphase carries a pair's manifold while the pair has not moved
// (contact_cache.h) and asks two boxes by separating axes (box_box.h), and islands at rest sleep
// (sleep.h): no stage moves, sweeps or queries them until something touches them.

#include "09_debug/chapter.h"
#include "10_skip_work/box_box.h"
#include "10_skip_work/contact_cache.h"
#include "10_skip_work/enlarged_bounds.h"
#include "10_skip_work/sleep.h"
#include "world/pipeline.h"

namespace stepwise {

/// What chapter 10 adds, each switchable for the A/B of the demo and the speed bench.
struct SkipWorkOptions {
    ContactCacheRule contactCache;  // enabled = false: every pair is queried every frame
    bool sleeping = true;           // with Settings::sleeping; false: never (the bench's A/B)
    bool enlargedBounds = true;     // sweep only when a body leaves its grown box; false: every step
    bool boxBoxQuery = true;        // two boxes by separating axes (box_box.h); false: GJK and EPA
    PairManifoldFunction pairManifold = nullptr;  // a later chapter's shapes (ManifoldOptions::pairManifold)
};

Pipeline makeChapter10Pipeline(const World& world);
Pipeline makeChapter10Pipeline(const World& world, const SkipWorkOptions& options);

}  // namespace stepwise
