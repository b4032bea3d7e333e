#include "app/registry.h"

#include <algorithm>
#include <stdexcept>

namespace stepwise {

void SceneView::draw(const World&, DebugDraw&) const {}
void SceneView::panel(World&, Panel&) {}

namespace {

class HookView : public SceneView {
public:
    HookView(SceneDrawHook draw, ScenePanelHook panel) : draw_(std::move(draw)), panel_(std::move(panel)) {}
    void draw(const World& world, DebugDraw& draw) const override {
        if (draw_) draw_(world, draw);
    }
    bool hasPanel() const override { return bool(panel_); }
    void panel(World& world, Panel& panel) override {
        if (panel_) panel_(world, panel);
    }

private:
    SceneDrawHook draw_;
    ScenePanelHook panel_;
};

}  // namespace

SceneViewFactory statelessView(SceneDrawHook draw, ScenePanelHook panel) {
    return [draw = std::move(draw), panel = std::move(panel)] {
        return std::unique_ptr<SceneView>(std::make_unique<HookView>(draw, panel));
    };
}

void Registry::addChapter(ChapterEntry entry) {
    if (entry.addScenes) entry.addScenes(*this);
    addPipeline(PipelineEntry{entry.chapter, std::move(entry.makePipeline)});
    for (BenchEntry& bench : entry.benches) addBench(std::move(bench));
}

void Registry::addScene(SceneEntry entry) {
    if (findScene(entry.name)) throw std::logic_error("scene registered twice: " + entry.name);
    scenes_.push_back(std::move(entry));
}

void Registry::addPipeline(PipelineEntry entry) { pipelines_.push_back(std::move(entry)); }

void Registry::addBench(BenchEntry entry) {
    if (findBench(entry.name)) throw std::logic_error("bench registered twice: " + entry.name);
    benches_.push_back(std::move(entry));
}

void Registry::addCommand(CommandEntry entry) { commands_.push_back(std::move(entry)); }

void Registry::addGenerator(GeneratorEntry entry) {
    if (!generators_.emplace(entry.name, entry.generate).second)
        throw std::logic_error("generator registered twice: " + entry.name);
}

void Registry::addPenetrationProbe(PenetrationProbe probe) { probes_.push_back(std::move(probe)); }

const SceneEntry* Registry::findScene(const std::string& name) const {
    for (const SceneEntry& entry : scenes_)
        if (entry.name == name) return &entry;
    return nullptr;
}

const BenchEntry* Registry::findBench(const std::string& name) const {
    for (const BenchEntry& entry : benches_)
        if (entry.name == name) return &entry;
    return nullptr;
}

// Later chapters register later, but a program may ask for an earlier chapter's engine
// (`stepwise run --chapter 2`), so pick by chapter number rather than registration order.
// [foundation-make-pipeline]
Pipeline Registry::makePipeline(const World& world, int maxChapter) const {
    const PipelineEntry* best = nullptr;
    for (const PipelineEntry& entry : pipelines_)
        if (entry.chapter <= maxChapter && (!best || entry.chapter >= best->chapter)) best = &entry;
    if (!best) throw std::runtime_error("no chapter up to " + std::to_string(maxChapter) + " provides a pipeline");
    return best->make(world);
}
// [foundation-make-pipeline]

const PenetrationProbe* Registry::penetrationProbe(int maxChapter) const {
    const PenetrationProbe* best = nullptr;
    for (const PenetrationProbe& probe : probes_)
        if (probe.chapter <= maxChapter && (!best || probe.chapter >= best->chapter)) best = &probe;
    return best;
}

int Registry::lastChapter() const {
    int last = 0;
    for (const PipelineEntry& entry : pipelines_) last = std::max(last, entry.chapter);
    for (const SceneEntry& entry : scenes_) last = std::max(last, entry.chapter);
    return last;
}

}  // namespace stepwise
