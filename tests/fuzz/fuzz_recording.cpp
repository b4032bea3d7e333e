// Fuzz target: the recording reader (chapter 9), fed any bytes. A recording file is untrusted
// input like a scene: reading it must end in a Recording or in one SceneError naming a JSON path,
// never a crash, a hang or another exception. A small recording that reads must replay without a
// crash (its hashes may well not be met: the fuzzer made them up).
#include "09_debug/recording.h"

#include "app/registry.h"
#include "world/scene.h"

#include <cstddef>
#include <cstdint>
#include <string>

using namespace stepwise;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    Recording recording;
    try {
        recording = recordingFromJson(text, "fuzz.json");
    } catch (const SceneError&) {
        return 0;  // rejected with a message: what bad input should get
    }
    const World start = startingWorld(chapterRegistry(), recording);
    if (recording.frameHashes.size() > 20 || start.bodies.size() > 8) return 0;
    try {
        replay(chapterRegistry(), recording);
    } catch (const SceneError&) {
        // An edit the scene cannot take at its frame (a body made static by the fuzzer): named.
    } catch (const std::invalid_argument&) {
        // An edit refused by validateEdit when applied: the reader already validated it against
        // the scene, so this can only be a mutated world state, and it is refused by name.
    }
    return 0;
}
