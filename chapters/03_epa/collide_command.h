#pragma once
// `stepwise collide --input pairs.json [--output results.json] [--time]`: the narrow-phase
// query of the scene contract (docs/scene-format.md, "Narrow-phase query"), so outside test
// suites and other engines can drive chapter 3's narrowphase through a file.

#include "03_epa/narrowphase.h"
#include "app/command.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace stepwise {

struct CollidePair {
    Shape shapeA, shapeB;
    Transform poseA, poseB;
};

/// Reads { "pairs": [ { "a": BODY, "b": BODY }, ... ] }. BODY objects go through the scene
/// loader, so they are validated exactly like scene bodies. Throws SceneError whose path names
/// the offending value, e.g. "pairs[2].b.shape.box.half_extents[0]".
std::vector<CollidePair> parseCollidePairs(const std::string& jsonText, const std::string& source);

/// The results document, one entry per query in order (numbers as short as round-trips allow).
std::string collideResultsToJson(const std::vector<ContactQuery>& results);

struct CollideArgs {
    std::string inputPath;
    std::string outputPath;   // empty: results on `out`
    bool time = false;
};

/// Runs the command. Returns 0, or 2 with "error: <path>: <message>" on `err` for bad input.
int runCollideCommand(const CollideArgs& args, std::ostream& out, std::ostream& err);

/// Adds the `collide` subcommand; its callback runs the command and stores the exit code.
void installCollideCommand(Command program, int& exitCode);

}  // namespace stepwise
