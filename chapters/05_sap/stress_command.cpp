// `stepwise stress` (stress_command.h).
#include "05_sap/stress_command.h"

#include "05_sap/chapter.h"
#include "app/runner.h"
#include "world/report.h"

#include <fstream>
#include <iostream>
#include <memory>

namespace stepwise {

int runStressCommand(const StressArgs& args, const Registry& registry, std::ostream& out, std::ostream& err) {
    // The chapter's engine must be one the program has; by default the latest, as for `run`.
    const int latest = registry.lastChapter();
    const int chapter = args.chapter.value_or(latest);
    if (chapter < 1 || chapter > latest) {
        err << "error: --chapter " << chapter << ": no such chapter (this program has chapters 1 to " << latest << ")\n";
        return 2;
    }
    Settings settings;
    settings.broadphase = args.broadphase == "sap" ? BroadphaseMode::Sap
                          : args.broadphase == "brute" ? BroadphaseMode::Brute
                                                       : BroadphaseMode::Auto;
    if (!args.savePath.empty()) {
        std::ofstream file(args.savePath, std::ios::binary);
        file << stressSceneFile(args.params, settings, "sap-stress");
        if (!file) {
            err << "error: " << args.savePath << ": cannot write the file\n";
            return 2;
        }
        out << "scene      " << args.savePath << " (run it with: stepwise run " << args.savePath << ")\n";
        return 0;
    }
    if (!args.reportPath.empty() && !std::ofstream(args.reportPath, std::ios::binary | std::ios::app)) {
        err << "error: " << args.reportPath << ": cannot write the file\n";
        return 2;
    }
    World world = buildStressScene(args.params);
    world.settings = settings;
    // The chapter's pipeline, its probe of the deepest overlap and its list of the settings it
    // does not read yet, all as `stepwise run --chapter` has them.
    Pipeline pipeline = registry.makePipeline(world, chapter);
    RunOptions options;
    options.frames = args.frames;
    options.maxChapter = chapter;
    options.progress = true;
    const RunStats stats = runHeadless(world, pipeline, registry, options);
    out << "engine     chapter " << chapter << (chapter == latest ? " (the latest)" : "") << "\n";
    printSummary(out, world, stats);
    if (!args.reportPath.empty()) {
        writeReport(args.reportPath, world, stats, engineVersion());
        out << "report     " << args.reportPath << "\n";
    }
    return stats.frames == args.frames ? 0 : 1;
}

void installStressCommand(Command program, int& exitCode, const Registry& registry) {
    auto args = std::make_shared<StressArgs>();
    Command stress = program.addSubcommand(
        "stress", "The stress scene (chapter 5): many bodies dropped dense or sparse, run headless or saved as a scene");
    const Names<StressDensity> densities = {{"sparse", StressDensity::Sparse}, {"dense", StressDensity::Dense}};
    stress.addOption("--count", args->params.count, "Dynamic bodies").range(1, kStressMaxCount);
    stress.addChoice("--density", args->params.density, densities, "sparse (3 m apart) or dense (5 cm apart)");
    stress.addChoice("--shape", args->params.shape, stressShapeNames(),
                     "sphere, diamond (convex hull), box, capsule, cylinder, mixed (the first three) or all");
    stress.addOption("--height", args->params.dropHeight, "Drop height of the lowest bodies, m")
        .range(Real(0), kStressMaxDropHeight);
    stress.addOption("--seed", args->params.seed, "Seed of the positions' jitter and the orientations");
    stress.addOption("--broadphase", args->broadphase, "auto, sap or brute").oneOf({"auto", "sap", "brute"});
    stress.addOption("--frames", args->frames, "Frames to simulate").range(0L, 100000000L);
    // Checked by the command, which names the chapters there are.
    auto chapter = std::make_shared<int>(0);
    CommandOption chapterOption =
        stress.addOption("--chapter", *chapter, "Use the engine as of this chapter (default: the latest)");
    stress.addOption("--report", args->reportPath, "Write the run report (JSON) here");
    stress.addOption("--save", args->savePath, "Write a scene file naming the generator instead of running");
    stress.onParsed([args, chapter, chapterOption, &exitCode, &registry] {
        if (chapterOption.given()) args->chapter = *chapter;
        exitCode = runStressCommand(*args, registry, std::cout, std::cerr);
    });
}

}  // namespace stepwise
