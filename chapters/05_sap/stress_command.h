#pragma once
// `stepwise stress`: the stress scene from the command line, with its generator's parameters
// as options, run headless through chapter 5's engine (summary, report), or saved as a scene
// file that names the generator.

#include "05_sap/stress_scene.h"

#include <iosfwd>
#include <string>

namespace CLI {
class App;
}

namespace stepwise {

struct StressArgs {
    StressParams params;
    std::string broadphase = "auto";  // auto, sap, brute
    long frames = 600;
    std::string reportPath;
    std::string savePath;             // write the generator scene file here (and run nothing)
};

/// Runs the command: 0 when every frame ran, 1 when the run stopped early, 2 on a file that
/// cannot be written.
int runStressCommand(const StressArgs& args, std::ostream& out, std::ostream& err);

/// Adds the `stress` subcommand; its callback runs the command and stores the exit code.
void installStressCommand(CLI::App& app, int& exitCode);

}  // namespace stepwise
