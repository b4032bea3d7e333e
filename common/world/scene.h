#pragma once
// Scene files (docs/scene-format.md): JSON in, a validated World out. Every rejection names
// the JSON path of the offending value, e.g. "bodies[3].shape.box.half_extents[1]: must be > 0".

#include "world/world.h"

#include <functional>
#include <map>
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

class JsonCursor;

/// A generator a scene file can name instead of listing bodies one by one:
/// "generator": { "<name>": { parameters } } (docs/scene-format.md). It adds its bodies to the
/// world read from the rest of the file, and throws SceneError naming the JSON path of a bad
/// parameter. Chapters provide them (chapter 5's stress scene); the loader only dispatches.
using SceneGenerator = std::function<void(World& world, const JsonCursor& parameters)>;
using SceneGenerators = std::map<std::string, SceneGenerator>;

/// Parses and validates a scene from JSON text. `source` names the file in messages.
World loadSceneFromString(const std::string& jsonText, const std::string& source = "scene",
                          const SceneGenerators& generators = {});

/// Reads a scene file. Throws SceneError on unreadable files, malformed JSON or invalid values.
World loadSceneFile(const std::string& path, const SceneGenerators& generators = {});

/// Writes a world back out as a scene (the inverse of loading, up to float round-off).
std::string saveSceneToString(const World& world);

}  // namespace stepwise
