// Chapter 5 in the programs: the stress scenes with the broadphase overlay, the pipeline with
// its broadphase stage, the broadphase bench, `stepwise stress` and the scene files' "stress"
// generator.
#include "05_sap/benches.h"
#include "05_sap/chapter.h"
#include "05_sap/scenes.h"
#include "05_sap/stress_command.h"
#include "app/registry.h"

#include <utility>

namespace stepwise {

void registerChapter05(Registry& registry) {
    registry.addChapter({5, addChapter05Scenes, [](const World& world) { return makeChapter05Pipeline(world); },
                         {broadphaseBench()}});
    CommandEntry stress;
    stress.chapter = 5;
    stress.installWithRegistry = installStressCommand;
    registry.addCommand(std::move(stress));
    registry.addGenerator({"stress", [](World& world, const JsonCursor& parameters) {
                               addStressBodies(world, readStressParams(parameters));
                           }});
}

}  // namespace stepwise
