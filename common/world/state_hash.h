#pragma once
// A 64-bit fingerprint of a world's state: the exact bits of every body's pose and velocities,
// the simulated time and the frame count. Two runs that agree to the last bit give the same
// hash; one flipped bit anywhere gives a different one (FNV-1a, Fowler, Noll and Vo).

#include "world/world.h"

#include <cstdint>
#include <string>

namespace stepwise {

std::uint64_t stateHash(const World& world);

/// One body's part of the state (pose, and velocities when it moves), 32 bits: what a replay
/// compares to name the first body that parts from a recording.
std::uint32_t bodyStateHash(const World& world, std::size_t body);

/// "0x0123456789abcdef".
std::string hexHash(std::uint64_t hash);

}  // namespace stepwise
