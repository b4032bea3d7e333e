#include "09_debug/commands.h"

#include "09_debug/recording.h"
#include "app/cli.h"
#include "app/registry.h"
#include "world/report.h"
#include "world/scene.h"
#include "world/state_hash.h"

#include <fstream>
#include <iostream>
#include <memory>

namespace stepwise {

namespace {

struct RecordArgs {
    std::string scene;
    long frames = 600;
    int chapter = 99;
    std::string output;
};

struct ReplayArgs {
    std::string input;
    std::string reportPath;
};

int runRecord(const RecordArgs& args) {
    return runReportingErrors(
        [&] {
            const Registry& registry = chapterRegistry();
            const int chapter = std::min(args.chapter, registry.lastChapter());
            const Recording recording = recordRun(registry, args.scene, chapter, args.frames);
            writeRecordingFile(args.output, recording);
            std::cout << "recorded " << recording.frameHashes.size() << " frames of '" << args.scene << "' (chapter "
                      << chapter << ") to " << args.output << "\n";
            return 0;
        },
        kExitBadInput);
}

int runReplay(const ReplayArgs& args) {
    ReplayResult result;
    Recording recording;
    try {
        recording = readRecordingFile(args.input);
        result = replay(chapterRegistry(), recording);
        if (!args.reportPath.empty()) {
            std::ofstream out(args.reportPath);
            out << result.reportJson;
            if (!out) throw std::runtime_error("cannot write report '" + args.reportPath + "'");
        }
    } catch (const SceneError& error) {
        printSceneError(std::cerr, error);
        return 2;
    } catch (const std::exception& error) {
        std::cerr << "error: " << args.input << ": " << error.what() << "\n";
        return 2;
    }
    if (result.firstMismatch >= 0) {
        std::cout << "replay of " << args.input << " parts from the recording at frame " << result.firstMismatch;
        if (result.firstBody >= 0) {
            const World scene = startingWorld(chapterRegistry(), recording);
            std::cout << ", first at body " << scene.bodies[static_cast<std::size_t>(result.firstBody)].name;
        }
        std::cout << ": state hash " << hexHash(result.actualHash) << ", recorded " << hexHash(result.expectedHash) << "\n";
        return 1;
    }
    if (!recording.reportJson.empty() && !result.reportMatches) {
        std::cout << "replay of " << args.input << " met every frame's hash but its report differs from the recording's\n";
        return 1;
    }
    std::cout << "replayed " << result.frames << " frames of " << args.input << ": every state hash "
              << (recording.reportJson.empty() ? "matches" : "and the report match") << " the recording\n";
    return 0;
}

}  // namespace

void installRecordCommand(Command program, int& exitCode) {
    auto args = std::make_shared<RecordArgs>();
    Command command =
        program.addSubcommand("record", "Run a scene and record it (scene, state hash per frame, report) for replay");
    command.addOption("scene", args->scene, "Built-in scene name or scene JSON file").required();
    command.addOption("--frames", args->frames, "Frames to run").range(0L, 10000000L);
    command.addOption("--chapter", args->chapter, "Use this chapter's pipeline (default: the latest)").range(1, 99);
    command.addOption("--output", args->output, "The recording file to write").required();
    command.onParsed([args, &exitCode] { exitCode = runRecord(*args); });
}

void installReplayCommand(Command program, int& exitCode) {
    auto args = std::make_shared<ReplayArgs>();
    Command command = program.addSubcommand("replay", "Replay a recording and check every frame against it");
    command.addOption("recording", args->input, "A file written by `stepwise record` or the demo's Save recording").required();
    command.addOption("--report", args->reportPath, "Write the replay's run report here");
    command.onParsed([args, &exitCode] { exitCode = runReplay(*args); });
}

}  // namespace stepwise
