#pragma once
// The programs' registry for tests: every chapter of this build, registered once per suite,
// and scenes looked up by name with a failure that names the scene.

#include "app/registry.h"

#include <catch2/catch.hpp>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace stepwise::test {

using stepwise::chapterRegistry;  // every chapter of this build, registered once

/// The registered scene `name`; throws (the test fails with the name) when there is none.
inline const SceneEntry& sceneNamed(const std::string& name) {
    const SceneEntry* entry = chapterRegistry().findScene(name);
    if (!entry) throw std::runtime_error("no registered scene \"" + name + "\"");
    return *entry;
}

/// The most bodies a scene may have to be run by the tests that go through every scene: the
/// stress scenes and the big pyramid are larger, and the golden hashes cover them.
constexpr std::size_t kMostBodiesPerSceneTest = 60;

/// Runs `check(scene, world)` on every registered scene of chapters up to `lastChapter` with at
/// most kMostBodiesPerSceneTest bodies, `world` freshly built and the scene's name in every
/// failure. `check` returns whether it compared anything (false: a scene it had to skip); the
/// result counts those that did, so a test can insist that enough scenes were covered.
template <class Check>
int forEachSmallScene(int lastChapter, Check check) {
    int compared = 0;
    for (const SceneEntry& scene : chapterRegistry().scenes()) {
        if (scene.chapter > lastChapter) continue;
        World world = scene.build();
        if (world.bodies.size() > kMostBodiesPerSceneTest) continue;
        INFO(scene.name);
        if (check(scene, std::move(world))) ++compared;
    }
    return compared;
}

}  // namespace stepwise::test
