#pragma once
// `stepwise stress`: the stress scene from the command line, with its generator's parameters
// as options, run headless through the engine of a chapter (the latest by default, `--chapter N`
// another: summary, report), or saved as a scene file that names the generator.

#include "05_sap/stress_scene.h"
#include "app/command.h"

#include <iosfwd>
#include <optional>
#include <string>

namespace stepwise {

class Registry;

struct StressArgs {
    StressParams params;
    std::string broadphase = "auto";  // auto, sap, brute
    long frames = 600;
    std::optional<int> chapter;       // run the engine of this chapter; none: the latest registered
    std::string reportPath;
    std::string savePath;             // write the generator scene file here (and run nothing)
};

/// Runs the command with the pipeline `registry` has for the chapter: 0 when every frame ran, 1
/// when the run stopped early, 2 on a chapter the registry does not have or a file that cannot be
/// written.
int runStressCommand(const StressArgs& args, const Registry& registry, std::ostream& out, std::ostream& err);

/// Adds the `stress` subcommand; its callback runs the command on the program's registry and
/// stores the exit code.
void installStressCommand(Command program, int& exitCode, const Registry& registry);

}  // namespace stepwise
