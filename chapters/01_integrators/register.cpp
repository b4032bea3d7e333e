// Chapter 1 registers its demo scenes, its pipeline (the first one: just the integrator) and
// the integrator bench.
#include "01_integrators/bench_integrators.h"
#include "01_integrators/chapter.h"
#include "01_integrators/scenes.h"
#include "app/registry.h"

namespace stepwise {

void registerChapter01(Registry& registry) {
    registry.addChapter({1, addChapter01Scenes, makeChapter01Pipeline, {integratorsBench()}});
}

}  // namespace stepwise
