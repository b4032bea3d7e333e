#pragma once
// What the demo shell simulates and shows, without any Direct3D: the chosen scene run through
// chapter 9's DebugSession (its world, pipeline, history, stop rules and edits), time scale,
// per-stage timing history, the debugger's selection, and view options.

#include "09_debug/debug_session.h"
#include "09_debug/debug_views.h"
#include "09_debug/hit_tree.h"
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
    bool showImpulses = true;     // the solver's impulses as arrows, once a chapter has a solver
    bool showLabels = true;
    bool showHelp = false;        // F1 overlay
    bool showPanel = true;        // F2 hides the whole ImGui shell
    bool debuggerOpen = true;     // the debugger window on the right is expanded (not just its title)
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

    /// Advances by wall-clock time (scaled), in whole fixed steps of settings.dt; nothing while
    /// paused, and a step that meets a stop rule pauses the session there.
    void advance(double wallSeconds);
    /// One fixed step through the session, whatever the pause state (live, or speculative while
    /// rewound); records stage timings.
    void step();

    // The session's clock, through the state so the cached hit tree and selection follow.
    bool paused() const { return session_->paused; }
    void setPaused(bool value) { session_->paused = value; }
    /// Shows a kept frame (pausing: stepping on from there is speculative). False when not kept.
    bool rewindTo(long frame);
    /// Back to the live run, discarding the speculative frames.
    void resume();
    /// Speculative steps taken since the last rewind (0 while live or on a kept frame).
    int speculativeSteps() const { return speculativeSteps_; }
    /// Applies a body edit through the session; throws std::invalid_argument with the reason.
    void edit(const BodyEdit& change);

    DebugSession& session() { return *session_; }
    const DebugSession& session() const { return *session_; }
    World& world() { return session_->world(); }
    const World& world() const { return session_->world(); }
    Pipeline& pipeline() { return session_->pipeline(); }

    // The debugger's selection: one body (the inspector and gizmo) and one node of the hit tree.
    // Both are cleared when a scene loads; the tree node follows its pair of bodies from frame
    // to frame and is cleared when the pair stops touching.
    int selectedBody = -1;
    /// Chapter 9's views (colliders, contacts, EPA face, A - B, bounds...). Kept here, not in
    /// ViewOptions, because the A - B overlay is part of what the camera frames.
    DebugViews views;
    /// The chapters' own views (chapter 13's mesh tree), each on or off at a level; its drawing
    /// function is made afresh at every load.
    struct OverlayView {
        const DebugOverlay* overlay = nullptr;
        bool on = false;
        int level = 0;
        OverlayDraw draw;
    };
    std::vector<OverlayView> chapterViews;
    /// The overlay called `name`, or nullptr.
    OverlayView* findOverlay(const std::string& name);
    const HitTree& hitTree() const;
    const HitSelection& hitSelection() const;
    void selectHit(const HitSelection& selection);
    /// Set when the selection came from the scene (a click): the tree panel opens and scrolls to it.
    bool revealSelection = false;

    /// The ground grid, chapter 9's views (bodies, contacts, highlights), the solver's impulse
    /// arrows, and the scene's own drawing.
    void buildDrawList(DrawList& list, const ViewOptions& options) const;
    /// The moving bodies when there are any (a huge ground would dwarf them), else all bodies.
    Aabb bodyBounds() const;
    /// What to frame now: bodyBounds() plus everything the scene's draw hook emits and the
    /// debugger's A - B overlay (beside or above the bodies), extended down to the ground so the
    /// ground stays in view.
    Framing framing() const;
    /// framing() when the scene was loaded (frame 0): what a new scene is framed from.
    const Framing& initialFraming() const { return initialFraming_; }
    /// Height of the ground: top of the widest static body, else the lowest body bottom, else 0.
    Real groundLevel() const;

    float timeScale = 1.0f;
    std::string pipelineError;     // when no chapter provides a pipeline
    std::string loadError;
    std::map<std::string, std::deque<float>> stageHistory;  // stage name -> ms per frame
    std::deque<float> frameHistory;                          // whole step, ms

    const Registry& registry() const { return registry_; }
    int chapter() const { return chapter_; }

private:
    void setWorld(World next);
    void worldChanged() { treeStale_ = true; }
    const Registry& registry_;
    int chapter_;
    std::vector<const SceneEntry*> scenes_;
    int sceneIndex_ = -1;
    std::unique_ptr<SceneView> view_;
    std::string loadedFile_;
    double accumulator_ = 0;
    Framing initialFraming_;
    std::unique_ptr<DebugSession> session_;
    int speculativeSteps_ = 0;
    // The hit tree is rebuilt lazily after the world changes; the selection is kept as its pair
    // of bodies so it survives the rebuild.
    mutable HitTree tree_;
    mutable HitSelection selection_;
    mutable bool treeStale_ = true;
    int selectedA_ = -1, selectedB_ = -1;
};

}  // namespace stepwise::render
