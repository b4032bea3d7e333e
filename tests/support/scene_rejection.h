#pragma once
// The error a scene is rejected with, for the tests of bad input (tests/common, tests/ch08).

#include "world/scene.h"

#include <catch2/catch.hpp>

#include <string>

namespace stepwise::test {

/// Loads `text` and returns the SceneError it is rejected with; fails the test if it loads.
inline SceneError rejectionOf(const std::string& text) {
    try {
        loadSceneFromString(text);
    } catch (const SceneError& error) {
        return error;
    }
    FAIL("the scene loaded: " << text);
    return SceneError("", "");
}

}  // namespace stepwise::test
