// stepwise_bullet: a Stepwise scene stepped by Bullet 3 (docs/peers.md), with the report of
// `stepwise run` (docs/scene-format.md, "Run report"), so the two can be read side by side.
//
//   stepwise_bullet run scenes/ball-on-box.json --frames 600 --report out/bullet.json

#include "app/cli.h"
#include "app/registry.h"
#include "app/runner.h"
#include "peers/bullet_peer.h"
#include "world/report.h"
#include "world/scene.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iomanip>
#include <iostream>

namespace {

using namespace stepwise;

// The exit codes of `stepwise` (docs/scene-format.md, "Exit codes"): kExitBadInput (app/cli.h) is
// bad input, which here includes a scene feature Bullet cannot take.
constexpr int kExitInternal = 1;

struct Args {
    std::string scene;
    long frames = 600;
    int iterations = 0;
    int substeps = 0;
    std::string reportPath;
    bool quiet = false;
};

void printSummary(std::ostream& out, const World& before, const RunStats& stats,
                  const peers::BulletRun& run) {
    out << "scene      " << before.name << " (" << before.bodies.size() << " bodies, " << before.dynamicBodyCount()
        << " dynamic)\n";
    out << "engine     " << peers::bulletVersion() << ": " << run.solverIterations << " iterations, " << run.substeps
        << " substep(s) per frame\n";
    out << "frames     " << stats.frames << " at dt " << before.settings.dt << " s\n";
    out << std::fixed << std::setprecision(4);
    out << "step       " << median(stats.stepMs) << " ms median, "
        << (stats.stepMs.empty() ? 0.0 : *std::max_element(stats.stepMs.begin(), stats.stepMs.end())) << " ms max\n";
    out << std::setprecision(6);
    out << "energy     " << stats.initialEnergy.total() << " J -> " << stats.finalEnergy.total() << " J\n";
    out.unsetf(std::ios::floatfield);
}

int run(const Args& args) {
    const World world = loadSceneOrBuiltin(chapterRegistry(), args.scene);
    peers::BulletOptions options;
    options.solverIterations = args.iterations;
    options.substeps = args.substeps;
    const peers::BulletRun bullet = peers::runBullet(world, args.frames, options);
    const World after = peers::worldAfterRun(world, bullet);

    RunStats stats;
    stats.frames = bullet.frames;
    stats.pipeline = {"bullet:stepSimulation"};
    stats.stepMs = bullet.stepMs;
    stats.initialEnergy = computeEnergy(world);
    stats.finalEnergy = computeEnergy(after);
    stats.warnings.push_back("bullet: max_penetration and max_contacts are not measured");
    if (!args.quiet) printSummary(std::cout, world, stats, bullet);
    if (!args.reportPath.empty()) {
        writeReport(args.reportPath, after, stats, peers::bulletVersion());
        if (!args.quiet) std::cout << "report     " << args.reportPath << "\n";
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"A Stepwise scene stepped by Bullet 3, as a yardstick (docs/peers.md)", "stepwise_bullet"};
    app.require_subcommand(1);
    Args args;
    CLI::App* runCommand = app.add_subcommand("run", "Run a scene in Bullet headless and print a summary");
    runCommand->add_option("scene", args.scene, "Scene file (.json) or built-in scene name")->required();
    runCommand->add_option("--frames", args.frames, "Frames to simulate")->check(CLI::Range(0L, 100000000L));
    runCommand->add_option("--iterations", args.iterations, "Solver iterations per step (default: the scene's)")
        ->check(CLI::Range(1, 10000));
    runCommand->add_option("--substeps", args.substeps, "Substeps per frame (default: the scene's)")->check(CLI::Range(1, 1000));
    runCommand->add_option("--report", args.reportPath, "Write the run report (JSON) here");
    runCommand->add_flag("--quiet", args.quiet, "Print nothing but errors");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        return app.exit(error) == 0 ? 0 : kExitBadInput;
    }
    return runReportingErrors(
        [&] {
            try {
                return run(args);
            } catch (const peers::BulletUnsupported& error) {
                std::cerr << "error: " << error.what() << "\n";
                return kExitBadInput;
            }
        },
        kExitInternal);
}
