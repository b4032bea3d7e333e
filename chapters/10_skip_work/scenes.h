#pragma once
// The fast step's scenes (chapters 10 to 12): what it is measured on (`stepwise bench speed`) and
// what the demos show. All are plain worlds: the same scene a scene file describes, so Bullet can run it too.

#include "app/registry.h"
#include "world/world.h"

namespace stepwise {

/// `count` pyramids of `rows` rows of unit boxes (1 kg, 1.05 m apart, friction 0.6, as chapter 6's
/// pyramid), side by side 3 m apart along z, on one static ground reaching 5 m beyond them.
World buildPyramidRow(int count, int rows);

/// `count` bodies (boxes, spheres, irregular hulls and capsules in turn; without `roundShapes` only
/// boxes and hulls) dropped in a grid into a walled pit, from 1 m above its floor; sizes 0.3 to
/// 0.6 m, seeded. The walls stand higher than the highest body starts.
/// The spheres and capsules have a rolling resistance of kPileRollingResistance.
World buildMixedPile(int count, bool roundShapes = true);
constexpr Real kPileRollingResistance = Real(0.05);

void addChapter10Scenes(Registry& registry);

}  // namespace stepwise
