// Chapter 6 in the programs. (The pipeline, scenes, benches and demo are registered here by the
// solver half of the chapter.)
#include "app/registry.h"

namespace stepwise {

void registerChapter06(Registry& /*registry*/) {}

}  // namespace stepwise
