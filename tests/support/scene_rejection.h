#pragma once
// The error a scene (or a recording) is rejected with, for the tests of bad input.

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

/// What reading with `read` is rejected with: the SceneError's lines, `whenRead` when it reads.
template <class Read>
std::string rejectionMessage(Read read, const std::string& whenRead = "") {
    try {
        read();
    } catch (const SceneError& error) {
        return error.what();
    }
    return whenRead;
}

}  // namespace stepwise::test
