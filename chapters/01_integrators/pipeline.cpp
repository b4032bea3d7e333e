#include "01_integrators/chapter.h"

#include "01_integrators/integrate.h"

namespace stepwise {

// [ch01-pipeline]
Pipeline makeChapter01Pipeline(const World& world) {
    Pipeline pipeline;
    Stage stage;
    stage.name = stageName(stage_group::kIntegrate, integratorLabel(world));
    stage.run = [](World& stepWorld, Real dt) { integrate(stepWorld, dt); };
    pipeline.add(std::move(stage));
    return pipeline;
}
// [ch01-pipeline]

}  // namespace stepwise
