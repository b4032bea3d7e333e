// A chapter's demo without a window: runs one of the chapter's scenes headless, prints the
// summary and writes the report. The DirectX 12 build of the same demo lives in renderer_dx12.
#include "app/headless_demo.h"

#include "app/cli.h"
#include "app/runner.h"
#include "world/scene.h"

#include <CLI/CLI.hpp>

#include <iostream>

#include <string>

namespace stepwise {

int runHeadlessDemo(int chapter, int argc, char** argv) {
    const std::string program = std::string(chapter < 10 ? "ch0" : "ch") + std::to_string(chapter) + "_demo";
    Registry registry;
    registerChapters(registry);

    std::string sceneName;
    long frames = 600;
    std::string reportPath;
    bool list = false;
    CLI::App app{"Chapter " + std::to_string(chapter) + " demo (headless: no window on this build)", program};
    app.add_option("--scene", sceneName, "Scene to run (default: the chapter's first scene)");
    app.add_option("--frames", frames, "Frames to simulate")->check(CLI::Range(1L, 10000000L));
    app.add_option("--report", reportPath, "Report file (default: " + program + "-<scene>.json)");
    app.add_flag("--list", list, "List this chapter's scenes");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0) return app.exit(error);
        std::cerr << "error: " << error.what() << "\n\n" << app.help();
        return kExitBadInput;
    }

    std::vector<const SceneEntry*> chapterScenes;
    for (const SceneEntry& entry : registry.scenes())
        if (entry.chapter == chapter) chapterScenes.push_back(&entry);
    if (list || chapterScenes.empty()) {
        for (const SceneEntry* entry : chapterScenes) std::cout << entry->name << "  " << entry->observe << "\n";
        if (chapterScenes.empty()) std::cerr << "error: chapter " << chapter << " registers no scenes\n";
        return chapterScenes.empty() ? 1 : 0;
    }
    if (sceneName.empty()) sceneName = chapterScenes.front()->name;
    return runReportingErrors(
        [&] {
            const SceneEntry* entry = registry.findScene(sceneName);
            World world = loadSceneOrBuiltin(registry, sceneName);
            Pipeline pipeline = registry.makePipeline(world, chapter);
            RunOptions options;
            options.frames = frames;
            options.maxChapter = chapter;
            options.progress = true;
            std::cout << program << ": no display on this build, running headless\n";
            if (entry) std::cout << "observe    " << entry->observe << "\n";
            const RunStats stats = runHeadless(world, pipeline, registry, options);
            printSummary(std::cout, world, stats);
            if (reportPath.empty()) reportPath = program + "-" + world.name + ".json";
            writeReport(reportPath, world, stats, engineVersion());
            std::cout << "report     " << reportPath << "\n";
            return stats.frames == frames ? 0 : 1;
        },
        1);
}

}  // namespace stepwise
