// Fuzz target: the scene loader, fed any bytes. A scene file is untrusted input, so loading it
// must end in a World or in one SceneError: never a crash, a hang, another exception or an
// allocation that exhausts memory. A scene that loads must save and load again (the saver
// writes only what the loader accepts), and a small one must step without a crash.
#include "fuzz_input.h"

#include "app/registry.h"
#include "app/runner.h"
#include "world/scene.h"

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstdint>
#include <string>

using namespace stepwise;

namespace {

/// Few bodies and cheap settings: the fuzzer's time goes to the loader, and a valid scene is
/// still stepped so the loaded values reach the engine.
bool smallEnoughToStep(const World& world) {
    return world.bodies.size() <= 8 && world.settings.substeps * (world.settings.solverIterations + 1) <= 2000;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    World world;
    try {
        world = loadSceneFromString(text, "fuzz.json");
    } catch (const SceneError&) {
        return 0;  // rejected with a message: what bad input should get
    }
    std::string saved = saveSceneToString(world);
    try {
        World reloaded = loadSceneFromString(saved, "saved.json");
        STEPWISE_FUZZ_CHECK("fuzz_scene", reloaded.bodies.size() == world.bodies.size(), reloaded.bodies.size(),
                            world.bodies.size());
    } catch (const SceneError& error) {
        std::fprintf(stderr, "fuzz_scene: a loaded scene saved as a file the loader rejects: %s\n%s\n", error.what(),
                     saved.c_str());
        std::abort();
    }
    if (!smallEnoughToStep(world)) return 0;
    const Registry& registry = chapterRegistry();
    Pipeline pipeline = registry.makePipeline(world);
    RunOptions options;
    options.frames = 10;
    runHeadless(world, pipeline, registry, options);  // may stop early on an unstable scene: allowed
    return 0;
}
