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

const Registry& registryOnce(void (*registerAll)(Registry&)) {
    static const Registry registry = [registerAll] {
        Registry all;
        registerAll(all);
        return all;
    }();
    return registry;
}

std::string prose(const std::string& paragraph) {
    std::string joined;
    std::size_t start = 0;
    while (start <= paragraph.size()) {
        std::size_t end = paragraph.find('\n', start);
        if (end == std::string::npos) end = paragraph.size();
        const std::size_t first = paragraph.find_first_not_of(" \t\r", start);
        if (first != std::string::npos && first < end) {
            const std::size_t last = paragraph.find_last_not_of(" \t\r", end - 1);
            if (!joined.empty()) joined += ' ';
            joined.append(paragraph, first, last + 1 - first);
        }
        start = end + 1;
    }
    return joined;
}

namespace {

/// The file a card line starts, if it starts one: "epa-dt.svg" -> a plot with suffix "-dt".
bool parseCardFile(const std::string& bench, const std::string& word, BenchFile& file) {
    const bool csv = word.size() > 4 && word.compare(word.size() - 4, 4, ".csv") == 0;
    const bool svg = word.size() > 4 && word.compare(word.size() - 4, 4, ".svg") == 0;
    if (!(csv || svg) || word.compare(0, bench.size(), bench) != 0) return false;
    file.kind = csv ? BenchFile::Kind::Csv : BenchFile::Kind::Plot;
    file.suffix = word.substr(bench.size(), word.size() - 4 - bench.size());
    file.oneEach = file.suffix.size() >= 2 && file.suffix.compare(file.suffix.size() - 2, 2, "-*") == 0;
    if (file.oneEach) file.suffix.resize(file.suffix.size() - 2);
    return file.suffix.empty() || (file.suffix[0] == '-' && file.suffix.find('*') == std::string::npos);
}

}  // namespace

BenchEntry benchEntry(int chapter, std::function<void(BenchRun&)> measure, const std::string& card) {
    BenchEntry entry;
    entry.chapter = chapter;
    entry.measure = std::move(measure);
    std::string* paragraph = nullptr;  // the text a continuation line adds to
    std::size_t start = 0;
    for (int lineNumber = 1; start < card.size(); ++lineNumber) {
        std::size_t end = card.find('\n', start);
        if (end == std::string::npos) end = card.size();
        const std::string line = prose(card.substr(start, end - start));
        start = end + 1;
        if (line.empty()) continue;
        const auto fail = [&](const std::string& why) {
            throw std::logic_error("bench card (chapter " + std::to_string(chapter) + "), line " +
                                   std::to_string(lineNumber) + " \"" + line + "\": " + why);
        };
        if (entry.name.empty()) {
            const std::size_t colon = line.find(": ");
            if (colon == std::string::npos || colon == 0 || line.find(' ') < colon)
                fail("the card starts with the bench's name and a colon");
            entry.name = line.substr(0, colon);
            entry.description = line.substr(colon + 2);
            paragraph = &entry.description;
            continue;
        }
        const std::string word = line.substr(0, line.find(' '));
        BenchFile file;
        if (parseCardFile(entry.name, word, file)) {
            if (word.size() == line.size()) fail("a file needs a line saying what it holds");
            file.what = prose(line.substr(word.size()));
            entry.files.push_back(std::move(file));
            paragraph = &entry.files.back().what;
        } else if (word.find(".csv") != std::string::npos || word.find(".svg") != std::string::npos) {
            fail("a file's name is the bench's, a suffix starting with '-' and .csv or .svg");
        } else {
            *paragraph += ' ' + line;
        }
    }
    if (entry.name.empty()) throw std::logic_error("bench card (chapter " + std::to_string(chapter) + ") is empty");
    for (std::size_t i = 0; i < entry.files.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (entry.files[i].kind == entry.files[j].kind && entry.files[i].suffix == entry.files[j].suffix)
                throw std::logic_error("bench card of " + entry.name + " names a file twice");
    return entry;
}

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
void Registry::addDebugOverlay(DebugOverlay overlay) { overlays_.push_back(std::move(overlay)); }

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
