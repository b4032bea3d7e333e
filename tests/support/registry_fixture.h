#pragma once
// The programs' registry for tests: every chapter of this build, registered once per suite,
// and scenes looked up by name with a failure that names the scene.

#include "app/registry.h"

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

}  // namespace stepwise::test
