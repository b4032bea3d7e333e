#pragma once
// The fast step's scenes (chapters 10 to 12): what it is measured on (`stepwise bench speed`) and
// what the demos show. All are plain worlds: the same scene a scene file describes, so Bullet can run it too.

#include "app/registry.h"
#include "world/world.h"

namespace stepwise {

/// `count` pyramids of `rows` rows of unit boxes (1 kg, `spacing` m apart, friction 0.6, as chapter
/// 6's pyramid), side by side 3 m apart along z, on one static ground reaching 5 m beyond them. At
/// the default 1.05 m a box touches only the boxes above and below it; at kTouchingSpacing it
/// touches its neighbours in the row as well, as bricks laid by hand do.
World buildPyramidRow(int count, int rows, Real spacing = Real(1.05));
constexpr Real kTouchingSpacing = 1;

/// `count` bodies (boxes, spheres, irregular hulls and capsules in turn; without `roundShapes` only
/// boxes and hulls) dropped in a grid into a walled pit, from 1 m above its floor; sizes 0.3 to
/// 0.6 m, seeded. The walls stand higher than the highest body starts.
/// The spheres and capsules have a rolling resistance of kPileRollingResistance.
World buildMixedPile(int count, bool roundShapes = true);

/// Sizes of a pile's bodies: each half extent (radius) drawn between these, m.
struct PileSizes {
    Real smallest = Real(0.3);
    Real largest = Real(0.6);
};
/// The same pile with sizes drawn from `sizes`: from 0.15 to 0.6 m the masses of one density lie
/// up to about 150 to 1 apart (a small sphere against a large box), the pile of unlike masses.
World buildMixedPile(int count, bool roundShapes, PileSizes sizes);
constexpr PileSizes kUnlikePileSizes{Real(0.15), Real(0.6)};
constexpr Real kPileRollingResistance = Real(0.05);

void addChapter10Scenes(Registry& registry);

}  // namespace stepwise
