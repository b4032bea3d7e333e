#pragma once
// Chapter 6's scenes: what stands only with manifolds and warm starting. Every box is a unit box
// (1 m tall) placed touching what is below it (depth 0), so that after settling each box should
// sit lower than its start by about the slop per contact beneath it: the measure of
// stacking_study.h.

#include "world/world.h"

namespace stepwise {

class Registry;

/// Friction of every stacking body and of the ground.
constexpr Real kStackFriction = Real(0.6);

/// `count` unit boxes of 1 kg, one on the other: "stack-16".
World buildBoxStack(int count = 16);

/// A pyramid of unit boxes of 1 kg, `rows` at the bottom and one at the top, 5 cm apart in a row
/// (each box rests on two): "pyramid-20" has 210 boxes.
World buildPyramid(int rows = 20);

/// A 100 kg box (3.2 m long) lying across three 1 kg unit boxes: "heavy-on-light".
World buildHeavyOnLight();

/// Four unit boxes of 1, 10, 100 and 1000 kg, the heaviest at the bottom ("tower-heavy-below")
/// or at the top ("tower-heavy-above").
World buildMassTower(bool heaviestAtBottom);

/// Pairs of thin plates leaning against each other with a plate across their tops, two storeys: "card-house".
World buildCardHouse();

/// A 1 kg unit box resting on a 30 degree ramp with mu = 0.8 (it should not move): "stack-ramp".
World buildStickingRamp(int* box = nullptr);

/// Registers the scenes above in the demo under "Stacking".
void addChapter06Scenes(Registry& registry);

}  // namespace stepwise
