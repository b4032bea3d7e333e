#pragma once
// Chapter 12's scenes: the big pyramids and the mixed pile, where the planner's substeps and the
// shock sweep decide whether the stacks stand (`stepwise bench speed` measures them).

#include "app/registry.h"

namespace stepwise {

void addChapter12Scenes(Registry& registry);

}  // namespace stepwise
