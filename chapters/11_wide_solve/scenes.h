#pragma once
// Chapter 11's demo scene: a pyramid big enough to fill the wide blocks.

#include "app/registry.h"

namespace stepwise {

void addChapter11Scenes(Registry& registry);

}  // namespace stepwise
