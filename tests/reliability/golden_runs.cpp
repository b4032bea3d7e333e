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

std::vector<GoldenRun> runGoldenScenes(const Registry& registry, const std::string& sceneFolder, const GoldenSelection& selection) {
    std::vector<std::filesystem::path> files;
    for (const auto& item : std::filesystem::directory_iterator(sceneFolder))
        if (item.path().extension() == ".json") files.push_back(item.path());
    std::sort(files.begin(), files.end());
    // The shards are dealt from the names alone, before any run, so every process agrees. A scene
    // over the time cap is in none (-1), and the others are dealt evenly among the shards.
    std::vector<std::string> names, dealt;
    for (const SceneEntry& entry : registry.scenes()) names.push_back(entry.name);
    for (const auto& file : files) names.push_back("scenes/" + file.filename().string());
    const auto overCap = [&](const std::string& name) {
        return selection.maxSeconds >= 0 && goldenSceneSeconds(name) > selection.maxSeconds;
    };
    for (const std::string& name : names)
        if (!overCap(name)) dealt.push_back(name);
    const std::vector<int> dealtShard = goldenShards(dealt, selection.shards);
    std::vector<int> shardOf;
    std::size_t next = 0;
    for (const std::string& name : names) shardOf.push_back(overCap(name) ? -1 : dealtShard[next++]);

    std::vector<GoldenRun> runs;
    const auto run = [&](const std::string& name, World world, int chapter) {
        const int shard = shardOf[runs.size()];
        if (shard < 0) runs.push_back({name, 0, "over " + std::to_string(int(selection.maxSeconds)) + " s under the sanitizers"});
        else if (shard != selection.shard) runs.push_back({name, 0, "in another shard"});
        else if (chapter < selection.fromChapter) runs.push_back({name, 0, "a chapter before " + std::to_string(selection.fromChapter)});
        else if (world.bodies.size() > selection.maxBodies) runs.push_back({name, 0, "more than " + std::to_string(selection.maxBodies) + " bodies"});
        else runs.push_back({name, finalHash(registry, std::move(world), kGoldenFrames, chapter), ""});
    };
    for (const SceneEntry& entry : registry.scenes()) run(entry.name, entry.build(), entry.chapter);
    for (const auto& file : files) run("scenes/" + file.filename().string(), loadSceneFile(file.string()), 99);
    return runs;
}

}  // namespace stepwise::reliability
