#pragma once
// stepwise_extremes (extremes.cpp): the pieces its tables share, and the tables of
// extremes_settle.cpp (mass ratios, sizes and speeds).
#include "world/world.h"

#include <string>

namespace stepwise::extremes {

/// "float" or "double": this build's Real.
const char* precision();

/// A box of `half` extents and `density` kg/m^3, added to `world`; its index.
int addBox(World& world, const std::string& name, BodyType type, const Vec3& position, const Vec3& half,
           Real density = 1000);

/// Whether every dynamic body's position and velocity are finite.
bool allFinite(const World& world);

/// Section 4: a light body under a heavy one, sizes far from a metre, speeds far from a walk.
void ratiosTable(bool quick);
void sizesTable(bool quick);
void speedTable(bool quick);

}  // namespace stepwise::extremes
