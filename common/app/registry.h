#pragma once
// What each chapter adds to the programs: demo scenes, pipelines, benchmarks, CLI commands,
// demo panels. Each chapter has one `void registerChapterNN(Registry&)`; the chapter list in
// CMake generates the function that calls them all in order (cmake/StepwiseChapters.cmake).

#include "app/command.h"
#include "app/registry_fwd.h"  // registerChapters, chapterRegistry
#include "world/pipeline.h"
#include "world/scene.h"
#include "world/world.h"

#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace stepwise {

class DebugDraw;
class BenchRun;
class Panel;

/// A scene's demo-side companion (Jolt's Samples keep one test class per scene): extra
/// drawing on top of the bodies and the scene's own controls. The demo makes a fresh view
/// every time it loads the scene, so whatever a view remembers (the support map chosen, how
/// many EPA expansions to show) starts over with the scene and never outlives it: no demo
/// state hides in statics or in closures shared between loads.
class SceneView {
public:
    virtual ~SceneView() = default;
    /// Extra drawing (simplices, contacts, labels...). Const: drawing never changes the view,
    /// so the demo may draw twice a frame (once to frame the camera, once to show).
    virtual void draw(const World& world, DebugDraw& draw) const;
    virtual bool hasPanel() const { return false; }
    /// Per-scene controls in the demo panel; may change the world (sliders) and the view.
    virtual void panel(World& world, Panel& panel);
};

using SceneDrawHook = std::function<void(const World&, DebugDraw&)>;
using ScenePanelHook = std::function<void(World&, Panel&)>;
using SceneViewFactory = std::function<std::unique_ptr<SceneView>()>;

/// The factory for a view without memory: a draw hook and, optionally, a panel hook.
SceneViewFactory statelessView(SceneDrawHook draw, ScenePanelHook panel = {});

/// The factory for a view class with memory: `entry.makeView = viewOfType<EpaStepperView>();`
template <class View>
SceneViewFactory viewOfType() {
    return [] { return std::unique_ptr<SceneView>(std::make_unique<View>()); };
}

/// One demo scene (Jolt Samples style): a builder, what the viewer should observe, and
/// optionally the view the demo draws and controls it with.
struct SceneEntry {
    std::string name;          // unique, kebab-case: "integrators-side-by-side"
    int chapter = 0;
    std::string category;      // groups scenes in the demo's picker
    std::string observe;       // one line: what to look for
    std::function<World()> build;
    SceneViewFactory makeView; // empty: the bodies alone
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
    std::string scenesDir;     // `bench engine --scenes DIR`; empty: the suite's own scenes
    std::string peer;          // `bench engine --peer bullet`; empty: no peer run
    std::string only;          // `bench speed --only pile`: the scenes whose name holds this; empty: all
};

/// One file a bench writes: the --csv or --plot path itself (suffix ""), or a file next to it
/// with a suffix before the extension (`--plot out/x.svg` and suffix "-dt": out/x-dt.svg).
struct BenchFile {
    enum class Kind { Csv, Plot };
    Kind kind = Kind::Csv;
    std::string suffix;
    std::string what;          // one line for `--help` and the list printed at the end
    /// One file per item of the run (a scene, ...): the suffix is followed by "-ITEM", so the
    /// files are known only once the suite runs (`--plot out/x.svg`, "-scene": out/x-scene-ramp.svg).
    bool oneEach = false;
};

struct BenchEntry {
    std::string name;          // `stepwise bench <name>`
    int chapter = 0;
    std::string description;
    std::function<void(BenchRun&)> measure;     // what it measures and writes; runBench() runs it
    std::vector<BenchFile> files;                 // every file it can write, named in --help
};

/// Text written as a paragraph in a raw string literal, as one line: its lines trimmed and
/// joined by single spaces. Scene notes and bench cards are prose; written as paragraphs they
/// read as prose in the code, not as strings cut at the margin.
std::string prose(const std::string& paragraph);

/// A bench from its card: the card is what `stepwise bench --help` shows of it, a paragraph
/// that starts `NAME: what it measures`, then one paragraph per file, each starting with the
/// file's name given `--csv out/NAME.csv --plot out/NAME.svg` (without `out/`; a `*` before the
/// extension: one file per item of the run, `NAME-scene-*.svg`):
///
///     epa: EPA depth error against run time ...
///     epa.csv     per setting: ns per query, depth errors, iterations
///     epa.svg     work-precision plot: depth error against ns per query
///
/// A line that does not start a file continues the paragraph above it. A card that does not
/// parse is a programming error (std::logic_error naming the line); the registry tests read
/// every bench's card.
BenchEntry benchEntry(int chapter, std::function<void(BenchRun&)> measure, const std::string& card);

class Registry;

/// A CLI subcommand a chapter adds (e.g. `collide` in chapter 3). A command that runs a chapter's
/// engine (`stress --chapter N`) installs with the program's registry, which knows them all.
struct CommandEntry {
    int chapter = 0;
    std::function<void(Command program, int& exitCode)> install;
    std::function<void(Command program, int& exitCode, const Registry& registry)> installWithRegistry = nullptr;
};

/// A scene generator scene files can name ("generator": { "<name>": { ... } }).
struct GeneratorEntry {
    std::string name;          // the key in the scene file: "stress"
    SceneGenerator generate;
};

/// Measures the deepest overlap in a world; chapters that can answer register one.
struct PenetrationProbe {
    int chapter = 0;
    std::function<Real(const World&)> measure;
};

/// A debug view a chapter adds to the demo's Views section, drawn over chapter 9's views while it
/// is on (chapter 13's mesh tree). A view with levels shows one level at a time, chosen by a
/// slider from 0 to levels - 1 (a tree's depth). Like a SceneView, the drawing function is made
/// afresh for every scene the demo loads, so what it builds and keeps (a mesh's tree) belongs to
/// one load and never outlives it.
using OverlayDraw = std::function<void(DebugDraw& draw, const World& world, int level)>;
struct DebugOverlay {
    int chapter = 0;
    std::string name;  // the checkbox's label and the demo's --views name: "mesh-tree"
    std::string help;  // one line under the checkbox: what the colours mean
    int levels = 0;
    std::function<OverlayDraw()> make;
};

/// What every chapter adds, in one declaration: its demo scenes, its pipeline and its benches.
/// Commands, scene generators and penetration probes, which few chapters have, are added one
/// by one after it.
struct ChapterEntry {
    int chapter = 0;
    std::function<void(Registry&)> addScenes;           // calls addScene for each demo scene
    std::function<Pipeline(const World&)> makePipeline;
    std::vector<BenchEntry> benches;
};

class Registry {
public:
    void addChapter(ChapterEntry entry);
    void addScene(SceneEntry entry);
    void addPipeline(PipelineEntry entry);
    void addBench(BenchEntry entry);
    void addCommand(CommandEntry entry);
    void addGenerator(GeneratorEntry entry);
    void addPenetrationProbe(PenetrationProbe probe);
    void addDebugOverlay(DebugOverlay overlay);

    const std::vector<SceneEntry>& scenes() const { return scenes_; }
    const std::vector<BenchEntry>& benches() const { return benches_; }
    const std::vector<CommandEntry>& commands() const { return commands_; }
    const std::vector<DebugOverlay>& debugOverlays() const { return overlays_; }
    /// The generators scene files may name, for loadSceneFile.
    const SceneGenerators& sceneGenerators() const { return generators_; }
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
    SceneGenerators generators_;
    std::vector<PenetrationProbe> probes_;
    std::vector<DebugOverlay> overlays_;
};

}  // namespace stepwise
