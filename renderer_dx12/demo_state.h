#pragma once
// What the demo shell simulates and shows, without any Direct3D: the chosen scene, its world
// and pipeline, run/pause/step and time scale, per-stage timing history, and view options.

#include "app/registry.h"
#include "draw_list.h"

#include <deque>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace stepwise::render {

struct ViewOptions {
    bool wireframe = false;
    float lineWidth = 2.0f;       // pixels
    bool showGrid = true;
    bool showContacts = true;
    bool showImpulses = true;     // the solver's impulses as arrows, once a chapter has a solver
    bool showLabels = true;
    bool showHelp = false;        // F1 overlay
    bool showPanel = true;        // F2 hides the whole ImGui shell
};

/// What the camera must show: a box, and the text labels whose anchors lie in it (a label
/// runs to the right of its anchor, so the shell keeps room for it).
struct Framing {
    Aabb bounds;
    std::vector<TextLabel> labels;
};

class DemoState {
public:
    static constexpr int kHistory = 180;  // frames of stage timings kept for the graph

    DemoState(const Registry& registry, int chapter);

    /// Scenes this demo offers: those of chapters <= chapter, in registration order.
    const std::vector<const SceneEntry*>& scenes() const { return scenes_; }
    int sceneIndex() const { return sceneIndex_; }
    const SceneEntry* scene() const { return sceneIndex_ >= 0 ? scenes_[sceneIndex_] : nullptr; }
    void loadScene(int index);
    /// A built-in scene name or a scene JSON file. Throws (SceneError, runtime_error) when neither.
    void loadByName(const std::string& nameOrPath);
    void reload();
    /// The loaded scene's view (made afresh at every load), or nullptr: scene files have none.
    SceneView* view() { return view_.get(); }
    const SceneView* view() const { return view_.get(); }

    /// Advances by wall-clock time (scaled), in whole fixed steps of settings.dt.
    void advance(double wallSeconds);
    /// One fixed step, whatever the pause state; records stage timings.
    void step();

    /// Bodies, the scene's own drawing, contacts, and the ground grid.
    void buildDrawList(DrawList& list, const ViewOptions& options) const;
    /// The moving bodies when there are any (a huge ground would dwarf them), else all bodies.
    Aabb bodyBounds() const;
    /// What to frame now: bodyBounds() plus everything the scene's draw hook emits (overlays
    /// beside or above the bodies), extended down to the ground so the ground stays in view.
    Framing framing() const;
    /// framing() when the scene was loaded (frame 0): what a new scene is framed from.
    const Framing& initialFraming() const { return initialFraming_; }
    /// Height of the ground: top of the widest static body, else the lowest body bottom, else 0.
    Real groundLevel() const;

    World world;
    Pipeline pipeline;
    bool paused = false;
    float timeScale = 1.0f;
    std::string pipelineError;     // when no chapter provides a pipeline
    std::string loadError;
    std::map<std::string, std::deque<float>> stageHistory;  // stage name -> ms per frame
    std::deque<float> frameHistory;                          // whole step, ms

    const Registry& registry() const { return registry_; }
    int chapter() const { return chapter_; }

private:
    void setWorld(World next);
    const Registry& registry_;
    int chapter_;
    std::vector<const SceneEntry*> scenes_;
    int sceneIndex_ = -1;
    std::unique_ptr<SceneView> view_;
    std::string loadedFile_;
    double accumulator_ = 0;
    Framing initialFraming_;
};

}  // namespace stepwise::render
