// The reference suite on disk and the sweep of configurations (suite.h).
#include "engine/suite.h"

#include "app/registry.h"
#include "world/scene.h"

#include <algorithm>
#include <filesystem>

namespace stepwise::engine_bench {

namespace fs = std::filesystem;

namespace {
const std::string kSidecarSuffix = ".expect.json";

bool endsWith(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}
}  // namespace

std::vector<ReferenceScene> loadReferenceScenes(const std::string& directory) {
    std::error_code error;
    if (!fs::is_directory(directory, error)) throw SidecarError(directory + ": no such directory of reference scenes");
    std::vector<std::string> scenes, sidecars;
    for (const fs::directory_entry& entry : fs::directory_iterator(directory)) {
        const std::string file = entry.path().filename().string();
        if (endsWith(file, kSidecarSuffix)) sidecars.push_back(file.substr(0, file.size() - kSidecarSuffix.size()));
        else if (endsWith(file, ".json")) scenes.push_back(file.substr(0, file.size() - 5));
    }
    std::sort(scenes.begin(), scenes.end());
    for (const std::string& orphan : sidecars)
        if (std::find(scenes.begin(), scenes.end(), orphan) == scenes.end())
            throw SidecarError((fs::path(directory) / (orphan + kSidecarSuffix)).string() + ": no scene " + orphan + ".json beside it");
    if (scenes.empty()) throw SidecarError(directory + ": no reference scenes (NAME.json with NAME.expect.json)");
    std::vector<ReferenceScene> list;
    for (const std::string& name : scenes) {
        ReferenceScene scene;
        scene.name = name;
        scene.path = (fs::path(directory) / (name + ".json")).string();
        try {
            scene.world = loadSceneFile(scene.path, chapterRegistry().sceneGenerators());
        } catch (const SceneError& bad) {
            throw SidecarError(scene.path + ": " + bad.what());  // the loader's messages name the JSON path, not the file
        }
        const std::string sidecarPath = (fs::path(directory) / (name + kSidecarSuffix)).string();
        scene.sidecar = loadSidecar(sidecarPath);
        checkBodiesExist(scene.sidecar, scene.world, sidecarPath);
        list.push_back(std::move(scene));
    }
    // Closed forms first, the pile last: the tables read from the simplest answer to the hardest.
    const auto rank = [](const ReferenceScene& scene) {
        return std::find(groupNames().begin(), groupNames().end(), scene.sidecar.group) - groupNames().begin();
    };
    std::stable_sort(list.begin(), list.end(), [&](const ReferenceScene& a, const ReferenceScene& b) { return rank(a) < rank(b); });
    return list;
}

// [engine-bench-sweep]
std::vector<Configuration> sweep(bool quick, bool withPeer) {
    std::vector<Configuration> list;
    list.push_back({"default", "default", false, {}, {}});
    const auto add = [&](const std::string& family, const std::string& name, const EngineKnobs& knobs) {
        list.push_back({family, name, false, knobs, {}});
    };
    if (!quick)
        for (int stepsPerSecond : {30, 60, 120, 240}) {
            EngineKnobs knobs;
            knobs.dt = Real(1) / Real(stepsPerSecond);
            add("dt", "dt 1/" + std::to_string(stepsPerSecond), knobs);
        }
    for (int substeps : quick ? std::vector<int>{2} : std::vector<int>{1, 2, 4, 8}) {
        EngineKnobs knobs;
        knobs.substeps = substeps;
        add("substeps", "substeps " + std::to_string(substeps), knobs);
    }
    for (int iterations : quick ? std::vector<int>{4} : std::vector<int>{2, 4, 10, 20, 40}) {
        EngineKnobs knobs;
        knobs.iterations = iterations;
        add("iterations", "iterations " + std::to_string(iterations), knobs);
    }
    if (!quick) {
        for (Stabilisation stabilisation : {Stabilisation::Baumgarte, Stabilisation::Relax, Stabilisation::SplitImpulse,
                                            Stabilisation::SoftStep}) {
            EngineKnobs knobs;
            knobs.stabilisation = stabilisation;
            add("stabilisation", toString(stabilisation), knobs);
        }
        EngineKnobs jacobi, cold;
        jacobi.solver = SolverKind::Jacobi;
        cold.warmStarting = false;
        add("other", "jacobi", jacobi);
        add("other", "no warm start", cold);
    }
    if (!quick)
        for (CcdMode ccd : {CcdMode::Off, CcdMode::On}) {
            EngineKnobs knobs;
            knobs.ccd = ccd;
            add("other", std::string("ccd ") + toString(ccd), knobs);
        }
    if (withPeer) {
        list.push_back({"bullet default", "bullet default", true, {}, {}});
        if (!quick) {
            for (int iterations : {2, 4, 10, 20, 40})
                list.push_back({"bullet iterations", "bullet iterations " + std::to_string(iterations), true, {}, {iterations, 0}});
            for (int substeps : {1, 2, 4, 8})
                list.push_back({"bullet substeps", "bullet substeps " + std::to_string(substeps), true, {}, {0, substeps}});
        }
    }
    return list;
}
// [engine-bench-sweep]

}  // namespace stepwise::engine_bench
