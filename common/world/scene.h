#pragma once
// Scene files (docs/scene-format.md): JSON in, a validated World out. Every rejection names
// the JSON path of the offending value, e.g. "bodies[3].shape.box.half_extents[1]: must be > 0".

#include "world/world.h"

#include <stdexcept>
#include <string>

namespace stepwise {

class SceneError : public std::runtime_error {
public:
    SceneError(std::string path, const std::string& message)
        : std::runtime_error(path.empty() ? message : path + ": " + message), path_(std::move(path)) {}
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

/// Parses and validates a scene from JSON text. `source` names the file in messages.
World loadSceneFromString(const std::string& jsonText, const std::string& source = "scene");

/// Reads a scene file. Throws SceneError on unreadable files, malformed JSON or invalid values.
World loadSceneFile(const std::string& path);

/// Writes a world back out as a scene (the inverse of loading, up to float round-off).
std::string saveSceneToString(const World& world);

}  // namespace stepwise
