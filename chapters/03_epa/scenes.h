#pragma once
// Chapter 3's demo scenes: EPA one expansion at a time on a pair of boxes, and a gallery of
// shape pairs with the contact each routine finds.

#include "03_epa/epa.h"
#include "world/world.h"

#include <optional>

namespace stepwise {

class DebugDraw;
class Registry;

/// Two overlapping boxes for the EPA stepper: A static, B turning slowly in zero gravity.
World buildEpaStepper();

/// Pairs of every shape combination, overlapping, B turning: closed forms and GJK + EPA.
World buildContactGallery();

/// EPA on bodies A and B stopped after `expansions` (< 0: run to convergence), keeping the
/// polytope; nullopt when GJK finds the pair apart.
std::optional<EpaResult> epaStoppedAfter(const World& world, int bodyA, int bodyB, int expansions);

/// What the stepper draws: the contact (red cubes on each shape, yellow normal arrow), and
/// beside the bodies, at half size around `polytopeAnchor`, the EPA polytope of A - B in
/// wireframe with its closest face in blue and the origin in white. `expansions` < 0 shows the
/// converged polytope.
EpaResult drawEpaStep(const World& world, int bodyA, int bodyB, int expansions, const Vec3& polytopeAnchor,
                      DebugDraw& draw);

void addChapter03Scenes(Registry& registry);

}  // namespace stepwise
