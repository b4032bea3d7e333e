// stepwise_goldens: checks (or rewrites) the golden state hashes of tests/reliability/golden/.
//   stepwise_goldens --check FILE --scenes DIR     exit 0 when every hash matches, 1 otherwise
//   stepwise_goldens --write FILE --scenes DIR     rewrite FILE from this build
//   --unchecked SCENE (repeatable, with --check)   run SCENE and print its hash, but do not count a
//                                                  difference (a known gap, docs/reliability.md)
//   --max-bodies N (with --check)                  skip the scenes of more than N bodies
//   --from-chapter C (with --check)                skip the built-in scenes of chapters before C
//   --shard K/N (with --check)                     only the Kth (0-based) of N shards, balanced by
//                                                  each scene's cost (golden_shards.cpp): N
//                                                  processes check the table in parallel
//   --max-seconds S (with --check)                 skip the scenes whose sanitizer run took more
//                                                  than S seconds (golden_shards.cpp's table); the
//                                                  shards are dealt from the others
// The build runs --check as the ctest reliability.golden_hashes; the target `golden-hashes`
// runs --write for the build's precision (docs/reliability.md).
#include "golden_runs.h"
#include "11_wide_solve/lanes.h"
#include "world/state_hash.h"

#include "app/runner.h"

#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>

using namespace stepwise;
using namespace stepwise::reliability;

namespace {

const char* precisionName() { return sizeof(Real) == sizeof(double) ? "double" : "float"; }

std::string goldenText(const std::vector<GoldenRun>& runs) {
    std::ostringstream text;
    text << "# Golden state hashes, " << precisionName() << " build: every built-in scene and scenes/*.json after "
         << kGoldenFrames << " frames\n# through their own chapter's engine, the files through the latest (common/world/state_hash.h). "
         << "Regenerate with the target golden-hashes\n# (docs/reliability.md) after a change that is meant to "
         << "change results.\n";
    for (const GoldenRun& run : runs) text << run.scene << " " << hexHash(run.hash) << "\n";
    return text.str();
}

std::map<std::string, std::string> readGolden(const std::string& path) {
    std::map<std::string, std::string> hashes;
    std::ifstream file(path);
    std::string line;
    while (std::getline(file, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        std::string scene, hash;
        fields >> scene >> hash;
        hashes[scene] = hash;
    }
    return hashes;
}

}  // namespace

int main(int argc, char** argv) {
    std::string mode, path, scenes;
    std::set<std::string> unchecked;
    GoldenSelection selection;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string option = argv[i];
        if (option == "--check" || option == "--write") mode = option, path = argv[i + 1];
        if (option == "--scenes") scenes = argv[i + 1];
        if (option == "--unchecked") unchecked.insert(argv[i + 1]);
        if (option == "--max-bodies") selection.maxBodies = std::size_t(std::stoul(argv[i + 1]));
        if (option == "--from-chapter") selection.fromChapter = std::stoi(argv[i + 1]);
        if (option == "--max-seconds") selection.maxSeconds = std::stod(argv[i + 1]);
        if (option == "--shard") {
            const std::string shard = argv[i + 1];
            const auto slash = shard.find('/');
            if (slash != std::string::npos) selection.shard = std::stoi(shard.substr(0, slash)), selection.shards = std::stoi(shard.substr(slash + 1));
        }
    }
    const bool everyScene = selection.maxBodies == std::size_t(-1) && selection.fromChapter == 0 && selection.shards == 1 &&
                            selection.maxSeconds < 0;
    if (mode.empty() || scenes.empty() || (mode == "--write" && !everyScene) || selection.shards < 1 ||
        selection.shard < 0 || selection.shard >= selection.shards) {
        std::cerr << "usage: stepwise_goldens --check|--write FILE --scenes DIR [--max-bodies N] [--from-chapter C] "
                     "[--shard K/N] [--max-seconds S] (the last four with --check)\n";
        return 2;
    }
    Registry registry;
    registerChapters(registry);
    const std::vector<GoldenRun> runs = runGoldenScenes(registry, scenes, selection);
    if (mode == "--write") {
        std::ofstream(path) << goldenText(runs);
        std::cout << "golden hashes: wrote " << runs.size() << " scenes to " << path << "\n";
        return 0;
    }
    std::map<std::string, std::string> golden = readGolden(path);
    int failures = 0;
    for (const GoldenRun& run : runs) {
        const auto known = golden.find(run.scene);
        if (!run.skipped.empty()) {
            std::cout << "SKIPPED  " << run.scene << " (" << run.skipped << ")\n";
        } else if (known == golden.end()) {
            std::cout << "NEW      " << run.scene << " " << hexHash(run.hash) << " (no golden hash yet)\n";
            ++failures;
        } else if (known->second != hexHash(run.hash) && unchecked.count(run.scene)) {
            std::cout << "OTHER    " << run.scene << " " << known->second << " -> " << hexHash(run.hash)
                      << " (unchecked in this build)\n";
        } else if (known->second != hexHash(run.hash)) {
            std::cout << "CHANGED  " << run.scene << " " << known->second << " -> " << hexHash(run.hash) << "\n";
            ++failures;
        } else {
            std::cout << "same     " << run.scene << " " << known->second << "\n";
        }
        if (known != golden.end()) golden.erase(known);
    }
    for (const auto& [scene, hash] : golden) {
        std::cout << "GONE     " << scene << " " << hash << " (in the golden file, not in this build)\n";
        ++failures;
    }
    std::cout << runs.size() << " scenes, " << failures
              << " differ from " << path << " (" << engineVersion() << "; the wide solve at " << kWideLanes
              << " lanes)\n";
    if (failures > 0)
        std::cout << "A change meant to alter results? Rewrite the goldens of both precisions:\n"
                     "  cmake --build build/linux --target golden-hashes\n"
                     "  cmake --build build/linux-double --target golden-hashes\n"
                     "and say in the commit why the results changed. Otherwise the change broke determinism.\n";
    return failures == 0 ? 0 : 1;
}
