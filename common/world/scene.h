#pragma once
// Scene files (docs/scene-format.md): JSON in, a validated World out. Every rejection names
// the JSON path of the offending value, e.g. "bodies[3].shape.box.half_extents[1]: must be > 0".

#include "world/world.h"

#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

namespace stepwise {

/// One rejected value: its JSON path ("" for the whole file) and what is wrong with it.
struct SceneIssue {
    std::string path;
    std::string message;
    std::string text() const { return path.empty() ? message : path + ": " + message; }
};

/// A rejected file. It carries every issue found (a loader reports all of a file's errors at
/// once, up to a limit); what() is one "path: message" line per issue, path() the first path.
class SceneError : public std::runtime_error {
public:
    SceneError(std::string path, const std::string& message)
        : SceneError(std::vector<SceneIssue>{SceneIssue{std::move(path), message}}) {}
    explicit SceneError(std::vector<SceneIssue> issues, bool truncated = false)
        : std::runtime_error(joined(issues, truncated)), issues_(std::move(issues)), truncated_(truncated) {}
    const std::string& path() const { return issues_.front().path; }
    const std::vector<SceneIssue>& issues() const { return issues_; }
    /// True when the loader stopped at its limit and the file may hold more errors.
    bool truncated() const { return truncated_; }

private:
    static std::string joined(const std::vector<SceneIssue>& issues, bool truncated) {
        std::string text;
        for (const SceneIssue& issue : issues) text += (text.empty() ? "" : "\n") + issue.text();
        if (truncated) text += "\nstopped after " + std::to_string(issues.size()) + " errors";
        return text;
    }
    std::vector<SceneIssue> issues_;
    bool truncated_ = false;
};

/// Prints every issue of `error` as its own "error: path: message" line.
void printSceneError(std::ostream& out, const SceneError& error);

/// Parses and validates a scene from JSON text. `source` names the file in messages.
World loadSceneFromString(const std::string& jsonText, const std::string& source = "scene");

/// Reads a scene file. Throws SceneError on unreadable files, malformed JSON or invalid values.
World loadSceneFile(const std::string& path);

/// Writes a world back out as a scene (the inverse of loading, up to float round-off).
std::string saveSceneToString(const World& world);

}  // namespace stepwise
