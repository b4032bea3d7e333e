#include "app/cli.h"

#include "app/bench_util.h"
#include "app/runner.h"
#include "world/report.h"
#include "world/scene.h"

#include <CLI/CLI.hpp>

#include <iostream>

namespace stepwise {

namespace {

// Exit codes (docs/scene-format.md, "Exit codes"): 0 done, 1 an internal error, 2 bad input
// (the message names the JSON path), 3 a run stopped because the step became unstable.
constexpr int kExitUnstable = 3;

struct RunArgs {
    std::string scene;
    long frames = 600;
    std::string reportPath;
    int chapter = 99;
    bool quiet = false;
};

int commandRun(const Registry& registry, const RunArgs& args) {
    World world = loadSceneOrBuiltin(registry, args.scene);
    Pipeline pipeline = registry.makePipeline(world, args.chapter);
    RunOptions options;
    options.frames = args.frames;
    options.maxChapter = args.chapter;
    options.progress = !args.quiet;
    const RunStats stats = runHeadless(world, pipeline, registry, options);
    if (!args.quiet) {
        // A built-in scene says what it is for, so the numbers below can be read against it.
        if (const SceneEntry* entry = registry.findScene(args.scene)) std::cout << "observe    " << entry->observe << "\n";
        printSummary(std::cout, world, stats);
    }
    if (!args.reportPath.empty()) {
        writeReport(args.reportPath, world, stats, engineVersion());
        if (!args.quiet) std::cout << "report     " << args.reportPath << "\n";
    }
    if (stats.frames == args.frames) return 0;
    // The runner stopped early: its last warning names the body and the frame.
    std::cerr << "error: " << (stats.warnings.empty() ? "the run stopped early" : stats.warnings.back()) << "\n";
    return kExitUnstable;
}

int commandScenes(const Registry& registry) {
    size_t width = 0;
    for (const SceneEntry& entry : registry.scenes()) width = std::max(width, entry.name.size());
    for (const SceneEntry& entry : registry.scenes()) {
        std::cout << "ch" << (entry.chapter < 10 ? "0" : "") << entry.chapter << "  " << entry.name
                  << std::string(width + 2 - entry.name.size(), ' ') << entry.observe << "\n";
    }
    return 0;
}

int commandBench(const Registry& registry, const std::string& suite, BenchOptions options, bool list) {
    if (list || suite.empty()) {
        for (const BenchEntry& entry : registry.benches()) std::cout << entry.name << "  " << entry.description << "\n";
        return suite.empty() && !list ? kExitBadInput : 0;
    }
    const BenchEntry* entry = registry.findBench(suite);
    if (!entry) {
        std::cerr << "error: unknown bench suite '" << suite << "'; known suites:";
        for (const BenchEntry& known : registry.benches()) std::cerr << " " << known.name;
        std::cerr << "\n";
        return kExitBadInput;
    }
    options.out = &std::cout;
    return runBench(*entry, options);
}

}  // namespace

int runReportingErrors(const std::function<int()>& command, int otherErrorExit) {
    try {
        return command();
    } catch (const SceneError& error) {
        printSceneError(std::cerr, error);
        return kExitBadInput;
    } catch (const std::exception& error) {
        std::cerr << "error: " << error.what() << "\n";
        return otherErrorExit;
    }
}

int runCli(int argc, char** argv, const Registry& registry) {
    CLI::App app{"Stepwise: a rigid-body physics engine built one chapter at a time", "stepwise"};
    app.set_version_flag("--version", engineVersion());
    app.require_subcommand(1);

    int exitCode = 0;
    RunArgs runArgs;
    CLI::App* run = app.add_subcommand("run", "Run a scene headless and print a summary");
    run->add_option("scene", runArgs.scene, "Scene file (.json) or built-in scene name")->required();
    run->add_option("--frames", runArgs.frames, "Frames to simulate")->check(CLI::Range(0L, 100000000L));
    run->add_option("--report", runArgs.reportPath, "Write the run report (JSON) here");
    run->add_option("--chapter", runArgs.chapter, "Use the engine as of this chapter")->check(CLI::Range(1, 99));
    run->add_flag("--quiet", runArgs.quiet, "Print nothing but errors");

    CLI::App* scenes = app.add_subcommand("scenes", "List the built-in scenes");

    std::string suite;
    BenchOptions benchOptions;
    bool listBenches = false;
    CLI::App* bench = app.add_subcommand("bench", "Run a benchmark suite");
    bench->add_option("suite", suite, "Suite name (see --list)");
    bench->add_option("--csv", benchOptions.csvPath, "Write the measurements as CSV");
    bench->add_option("--plot", benchOptions.plotPath, "Write the plot as SVG");
    bench->add_flag("--quick", benchOptions.quick, "Smaller sizes (docs build, smoke tests)");
    bench->add_flag("--quiet", benchOptions.quiet, "No progress bar and no list of the files written");
    bench->add_flag("--list", listBenches, "List the suites");
    bench->add_option("--scenes", benchOptions.scenesDir, "bench engine: the reference scenes' folder (default scenes/reference)");
    bench->add_option("--peer", benchOptions.peer, "bench engine: run this peer too (bullet)");
    bench->add_option("--only", benchOptions.only,
                      "bench speed: only the scenes whose name contains this text (and none of the other tables)");
    bench->footer(benchFilesHelp(registry.benches()));

    for (const CommandEntry& command : registry.commands()) {
        if (command.install) command.install(app, exitCode);
        if (command.installWithRegistry) command.installWithRegistry(app, exitCode, registry);
    }

    const auto known = app.get_subcommands([&](CLI::App* command) { return argc > 1 && command->check_name(argv[1]); });
    if (argc > 1 && argv[1][0] != '-' && known.empty()) {
        std::cerr << "error: unknown command '" << argv[1] << "'\n\n" << app.help();
        return kExitBadInput;
    }
    try {
        app.parse(argc, argv);  // a chapter's command runs here, from its callback
        if (run->parsed()) return commandRun(registry, runArgs);
        if (scenes->parsed()) return commandScenes(registry);
        if (bench->parsed()) return commandBench(registry, suite, benchOptions, listBenches);
        return exitCode;
    } catch (const CLI::CallForHelp& help) {
        return app.exit(help);
    } catch (const CLI::CallForAllHelp& help) {
        return app.exit(help);
    } catch (const CLI::CallForVersion& version) {
        return app.exit(version);
    } catch (const CLI::ParseError& error) {
        std::cerr << "error: " << error.what() << "\n\n" << app.help();
        return kExitBadInput;
    } catch (const SceneError& error) {
        printSceneError(std::cerr, error);
        return kExitBadInput;
    } catch (const std::exception& error) {
        std::cerr << "error: " << error.what() << "\n";
        return 1;
    }
}

}  // namespace stepwise
