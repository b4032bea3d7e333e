#pragma once
// The energy tests of bouncing and spinning bodies: run a scene and keep the most energy it had.
#include "world/pipeline.h"
#include "world/world.h"

#include <algorithm>

namespace stepwise::test {

/// Steps `world` `frames` frames; the most total energy it had at the start or after any frame.
inline double mostEnergyOver(World& world, Pipeline& pipeline, int frames) {
    double most = computeEnergy(world).total();
    for (int frame = 0; frame < frames; ++frame) {
        pipeline.step(world);
        most = std::max(most, double(computeEnergy(world).total()));
    }
    return most;
}

}  // namespace stepwise::test
