#include "golden_runs.h"

#include "world/state_hash.h"
#include "world/scene.h"

#include <algorithm>
#include <filesystem>

namespace stepwise::reliability {

std::uint64_t finalHash(const Registry& registry, World world, long frames, int maxChapter) {
    Pipeline pipeline = registry.makePipeline(world, maxChapter);
    for (long frame = 0; frame < frames; ++frame) pipeline.step(world);
    return stateHash(world);
}

std::vector<GoldenRun> runGoldenScenes(const Registry& registry, const std::string& sceneFolder) {
    std::vector<GoldenRun> runs;
    for (const SceneEntry& entry : registry.scenes()) runs.push_back({entry.name, finalHash(registry, entry.build(), kGoldenFrames, entry.chapter)});
    std::vector<std::filesystem::path> files;
    for (const auto& item : std::filesystem::directory_iterator(sceneFolder))
        if (item.path().extension() == ".json") files.push_back(item.path());
    std::sort(files.begin(), files.end());
    for (const auto& file : files)
        runs.push_back({"scenes/" + file.filename().string(), finalHash(registry, loadSceneFile(file.string()), kGoldenFrames)});
    return runs;
}

}  // namespace stepwise::reliability
