#pragma once
// Chapter 13's `stepwise bench` suite.

#include "app/registry.h"

namespace stepwise {

/// `stepwise bench worlds`: a pile of 1,000 mixed bodies (boxes, balls, capsules, cans, tables)
/// dropped onto a terrain mesh of 100,352 triangles, stepped by chapter 13 and by Bullet beside it
/// when the program has the peer: ms per frame, bodies through the ground, the deepest contact
/// once settled. `--quick`: 200 bodies on 20,000 triangles.
BenchEntry worldsBench();

}  // namespace stepwise
