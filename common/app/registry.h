#pragma once
// What each chapter adds to the programs: demo scenes, pipelines, benchmarks, CLI commands,
// demo panels. Each chapter has one `void registerChapterNN(Registry&)`; the chapter list in
// CMake generates the function that calls them all in order (cmake/StepwiseChapters.cmake).

#include "world/pipeline.h"
#include "world/world.h"

#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace stepwise {

class DebugDraw;
class Panel;

/// One demo scene (Jolt Samples style): a builder plus what the viewer should observe.
struct SceneEntry {
    std::string name;          // unique, kebab-case: "integrators-side-by-side"
    int chapter = 0;
    std::string category;      // groups scenes in the demo's picker
    std::string observe;       // one line: what to look for
    std::function<World()> build;
    /// Optional extra drawing on top of the bodies (simplices, contacts, labels...).
    std::function<void(const World&, DebugDraw&)> draw;
    /// Optional per-scene controls in the demo panel.
    std::function<void(World&, Panel&)> panel;
};

/// The stages a chapter contributes, given the world they will run on (plan from the scene).
struct PipelineEntry {
    int chapter = 0;
    std::function<Pipeline(const World&)> make;
};

struct BenchOptions {
    std::string csvPath;       // empty: no CSV
    std::string plotPath;      // empty: no plot
    bool quick = false;        // smaller sizes, for the docs build and smoke tests
    bool quiet = false;        // no progress and no list of files written
    std::ostream* out = nullptr;  // the results; standard output when null
};

/// One file a bench writes: the --csv or --plot path itself (suffix ""), or a file next to it
/// with a suffix before the extension (`--plot out/x.svg` and suffix "-dt": out/x-dt.svg).
struct BenchFile {
    enum class Kind { Csv, Plot };
    Kind kind = Kind::Csv;
    std::string suffix;
    std::string what;          // one line for `--help` and the list printed at the end
};

struct BenchEntry {
    std::string name;          // `stepwise bench <name>`
    int chapter = 0;
    std::string description;
    std::function<int(const BenchOptions&)> run;  // exit code
    std::vector<BenchFile> files;                 // every file it can write, named in --help
};

/// A CLI subcommand a chapter adds (e.g. `collide` in chapter 3).
struct CommandEntry {
    int chapter = 0;
    std::function<void(CLI::App& app, int& exitCode)> install;
};

/// Measures the deepest overlap in a world; chapters that can answer register one.
struct PenetrationProbe {
    int chapter = 0;
    std::function<Real(const World&)> measure;
};

class Registry {
public:
    void addScene(SceneEntry entry);
    void addPipeline(PipelineEntry entry);
    void addBench(BenchEntry entry);
    void addCommand(CommandEntry entry);
    void setPenetrationProbe(PenetrationProbe probe);

    const std::vector<SceneEntry>& scenes() const { return scenes_; }
    const std::vector<BenchEntry>& benches() const { return benches_; }
    const std::vector<CommandEntry>& commands() const { return commands_; }
    const SceneEntry* findScene(const std::string& name) const;
    const BenchEntry* findBench(const std::string& name) const;

    /// The pipeline of the latest registered chapter <= maxChapter (all chapters by default).
    Pipeline makePipeline(const World& world, int maxChapter = 99) const;
    /// The probe of the latest chapter <= maxChapter, or nullptr.
    const PenetrationProbe* penetrationProbe(int maxChapter = 99) const;
    int lastChapter() const;

private:
    std::vector<SceneEntry> scenes_;
    std::vector<PipelineEntry> pipelines_;
    std::vector<BenchEntry> benches_;
    std::vector<CommandEntry> commands_;
    std::vector<PenetrationProbe> probes_;
};

/// Generated from the chapter list: calls registerChapter01..NN for the program's chapters.
void registerChapters(Registry& registry);

}  // namespace stepwise
