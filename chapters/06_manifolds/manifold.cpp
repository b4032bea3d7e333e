// The narrowphase stage of chapter 6.
#include "06_manifolds/manifold.h"

#include "03_epa/chapter.h"

#include <algorithm>
#include <string>

namespace stepwise {

int updateManifolds(World& world, Real lookAhead, const ManifoldOptions& /*options*/) {
    // First cut: chapter 3's one point per pair (the manifolds follow).
    return updateContacts(world, world.candidatePairs, static_cast<int>(std::max<Real>(0, lookAhead)));
}

}  // namespace stepwise
