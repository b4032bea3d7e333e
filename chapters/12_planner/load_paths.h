#pragma once
// Which mass ratios a frame's solve has to carry. A light body is hard for Gauss-Seidel only where
// a heavier one rests on it: each sweep moves a load across a contact in proportion to the masses
// on its two sides, and a 1 kg box under 1000 kg passes the load on a thousandth at a time. Two
// unlike bodies side by side in a pile, or a small one lying on a large one, carry nothing of the
// kind: counting them buys substeps that change nothing (bench speed's unlike pile: its touching
// pairs read about 150 to 1, its load paths 47 to 65 once it has landed; planner-fits section 9).

#include "world/world.h"

#include <vector>

namespace stepwise {

/// Scratch the load-path search reuses frame after frame.
struct LoadPathSearch {
    std::vector<int> bodies;          // the dynamic bodies of contacts that carry weight, highest first
    std::vector<int> start, below;    // per body, the bodies it rests on (compressed rows)
    std::vector<int> fill;            // where each body's next row goes while they are filled
    std::vector<Real> heaviestAbove;  // per body, the heaviest body resting on it through any path
    std::vector<Real> height;         // per body, its centre's height (along -gravity)
};

/// Contact normals within this angle of gravity carry weight (cos 60 degrees): a box resting on a
/// sphere's shoulder still carries; one leaning on a wall does not.
constexpr Real kLoadNormalCosine = Real(0.5);

/// The largest mass ratio along the frame's load paths: over every dynamic body, the heaviest body
/// resting on it (directly, or through the bodies between) over its own mass; 1 where no heavier
/// body rests on a lighter one. Under no gravity nothing rests on anything: every touching pair
/// of dynamic bodies counts, as `touchingRatio` gives it.
Real loadPathMassRatio(const World& world, const std::vector<int>& contactOrder, Real touchingRatio,
                       LoadPathSearch& search);

}  // namespace stepwise
