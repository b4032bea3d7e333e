#include "demo_state.h"

#include "app/runner.h"
#include "world/contact_draw.h"
#include "world/shape.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stepwise::render {

DemoState::DemoState(const Registry& registry, int chapter)
    : registry_(registry), chapter_(chapter), session_(std::make_unique<DebugSession>(World(), Pipeline())) {
    for (const SceneEntry& entry : registry.scenes()) {
        if (entry.chapter <= chapter && entry.build) scenes_.push_back(&entry);
    }
    for (const DebugOverlay& overlay : registry.debugOverlays())
        if (overlay.chapter <= chapter) chapterViews.push_back({&overlay, false, 0, nullptr});
}

DemoState::OverlayView* DemoState::findOverlay(const std::string& name) {
    for (OverlayView& view : chapterViews)
        if (view.overlay->name == name) return &view;
    return nullptr;
}

void DemoState::setWorld(World next) {
    accumulator_ = 0;
    stageHistory.clear();
    frameHistory.clear();
    pipelineError.clear();
    Pipeline pipeline;
    try {
        pipeline = registry_.makePipeline(next, chapter_);
    } catch (const std::exception& error) {
        pipelineError = error.what();
    }
    for (OverlayView& overlay : chapterViews) overlay.draw = overlay.overlay->make();
    pipeline.timeStagesEvery(1);  // the per-stage graph draws every frame
    // A new session per load: the history, edits and frame hashes belong to one run. The
    // switches a learner set (pause, simulation off, stop rules) carry over, as the pause
    // always did across a restart.
    auto session = std::make_unique<DebugSession>(std::move(next), std::move(pipeline));
    session->paused = session_->paused;
    session->simulationEnabled = session_->simulationEnabled;
    session->rules = session_->rules;
    session_ = std::move(session);
    speculativeSteps_ = 0;
    selectedBody = -1;
    selectedA_ = selectedB_ = -1;
    selection_ = HitSelection();
    revealSelection = false;
    worldChanged();
    initialFraming_ = framing();
}

void DemoState::loadScene(int index) {
    if (index < 0 || index >= static_cast<int>(scenes_.size())) return;
    loadError.clear();
    try {
        World next = scenes_[index]->build();
        sceneIndex_ = index;
        loadedFile_.clear();
        view_ = scenes_[index]->makeView ? scenes_[index]->makeView() : nullptr;
        setWorld(std::move(next));
    } catch (const std::exception& error) {
        loadError = "scene '" + scenes_[index]->name + "' failed to build: " + error.what();
    }
}

void DemoState::loadByName(const std::string& nameOrPath) {
    for (size_t i = 0; i < scenes_.size(); ++i) {
        if (scenes_[i]->name == nameOrPath) {
            loadScene(static_cast<int>(i));
            if (!loadError.empty()) throw std::runtime_error(loadError);
            return;
        }
    }
    World next = loadSceneOrBuiltin(registry_, nameOrPath);  // throws SceneError with the reason
    sceneIndex_ = -1;
    loadedFile_ = nameOrPath;
    view_.reset();
    setWorld(std::move(next));
}

void DemoState::reload() {
    if (sceneIndex_ >= 0) loadScene(sceneIndex_);
    else if (!loadedFile_.empty()) loadByName(loadedFile_);
}

void DemoState::advance(double wallSeconds) {
    if (session_->paused) return;
    const World& world = session_->world();
    const double dt = world.settings.dt > 0 ? static_cast<double>(world.settings.dt) : 1.0 / 60.0;
    accumulator_ += std::clamp(wallSeconds, 0.0, 0.25) * static_cast<double>(timeScale);
    // At most 4 steps per displayed frame: a slow machine runs in slow motion instead of
    // falling further and further behind (Gaffer on Games, "Fix your timestep").
    for (int steps = 0; accumulator_ >= dt && steps < 4 && !session_->paused; ++steps) {
        step();
        accumulator_ -= dt;
    }
    accumulator_ = std::min(accumulator_, dt);
}

void DemoState::step() {
    if (session_->step() == StopReason::Disabled) return;
    if (session_->rewound()) ++speculativeSteps_;
    worldChanged();
    for (const Stage& stage : session_->pipeline().stages()) {
        auto& history = stageHistory[stage.name];
        history.push_back(static_cast<float>(stage.enabled ? stage.lastMs : 0.0));
        if (history.size() > kHistory) history.pop_front();
    }
    frameHistory.push_back(static_cast<float>(session_->pipeline().lastStepMs()));
    if (frameHistory.size() > kHistory) frameHistory.pop_front();
}

bool DemoState::rewindTo(long frame) {
    if (!session_->rewindTo(frame)) return false;
    session_->paused = true;
    speculativeSteps_ = 0;
    worldChanged();
    return true;
}

void DemoState::resume() {
    session_->resume();
    speculativeSteps_ = 0;
    worldChanged();
}

void DemoState::edit(const BodyEdit& change) {
    session_->edit(change);
    worldChanged();
}

const HitTree& DemoState::hitTree() const {
    if (treeStale_) {
        tree_ = buildHitTree(session_->world());
        treeStale_ = false;
        // The selected node follows its pair; its manifold and point only while they still exist.
        HitSelection kept = selectedA_ >= 0 ? findPair(tree_, selectedA_, selectedB_) : HitSelection();
        if (!kept.empty() && selection_.manifold >= 0) {
            const HitPair& pair = tree_.pairs[static_cast<std::size_t>(kept.pair)];
            if (selection_.manifold < static_cast<int>(pair.manifolds.size())) {
                kept.manifold = selection_.manifold;
                const auto& points = pair.manifolds[static_cast<std::size_t>(kept.manifold)].points;
                if (selection_.point < static_cast<int>(points.size())) kept.point = selection_.point;
            }
        }
        selection_ = kept;
    }
    return tree_;
}

const HitSelection& DemoState::hitSelection() const {
    hitTree();
    return selection_;
}

void DemoState::selectHit(const HitSelection& selection) {
    const HitTree& tree = hitTree();
    if (selection.empty() || selection.pair >= static_cast<int>(tree.pairs.size())) {
        selection_ = HitSelection();
        selectedA_ = selectedB_ = -1;
        return;
    }
    selection_ = selection;
    selectedA_ = tree.pairs[static_cast<std::size_t>(selection.pair)].bodyA;
    selectedB_ = tree.pairs[static_cast<std::size_t>(selection.pair)].bodyB;
}

Real DemoState::groundLevel() const {
    const World& world = session_->world();
    const Body* widest = nullptr;
    Real widestArea = 0;
    Real lowest = kRealMax;
    for (const Body& body : world.bodies) {
        const Aabb box = computeAabb(body.shape, body.transform);
        if (!box.min.allFinite() || !box.max.allFinite()) continue;
        lowest = std::min(lowest, box.min.y());
        const Vec3 size = box.max - box.min;
        const Real area = size.x() * size.z();
        if (body.type == BodyType::Static && area > widestArea && size.y() < Real(0.5) * std::max(size.x(), size.z())) {
            widest = &body;
            widestArea = area;
        }
    }
    if (widest) return computeAabb(widest->shape, widest->transform).max.y();
    return lowest < kRealMax ? std::min(lowest, Real(0)) : Real(0);
}

Aabb DemoState::bodyBounds() const {
    const World& world = session_->world();
    Aabb moving, all;
    for (const Body& body : world.bodies) {
        const Aabb box = computeAabb(body.shape, body.transform);
        if (!box.min.allFinite() || !box.max.allFinite()) continue;
        all.grow(box);
        if (body.type != BodyType::Static) moving.grow(box);
    }
    Aabb result = (moving.min.array() <= moving.max.array()).all() ? moving : all;
    if (!(result.min.array() <= result.max.array()).all()) {
        result.min = Vec3(-2, 0, -2);
        result.max = Vec3(2, 2, 2);
    }
    return result;
}

Framing DemoState::framing() const {
    const World& world = session_->world();
    Framing framing;
    Aabb& result = framing.bounds;
    result = bodyBounds();
    // The scene's overlay counts as content: chapter 2 draws A - B above its bodies, chapter 3
    // the EPA polytope beside them. Drawing changes neither world nor view, so measuring is harmless.
    // Labels count by their anchors; their on-screen width is only known to the shell
    // (ui_shell.cpp, frameScene), so they go along.
    const auto measured = [&](const RecordingDraw& measure) {
        if (!measure.empty()) result.grow(measure.bounds());
        for (const RecordingDraw::Command& command : measure.commands())
            if (command.kind == RecordingDraw::Kind::Text && command.a.allFinite())
                framing.labels.push_back({command.a, command.message, command.color});
    };
    if (view_) {
        RecordingDraw measure;
        try {
            view_->draw(world, measure);
        } catch (const std::exception&) {
            // A hook that throws stops drawing here too; what it drew before still counts.
        }
        measured(measure);
    }
    // So is the debugger's A - B overlay beside the bodies; only the overlays are measured (the
    // views that draw the bodies would bring in the whole ground).
    if (views.gjkSimplex || views.minkowski) {
        DebugViews overlays;
        overlays.colliders = overlays.wireframeSelection = overlays.contactPoints = overlays.contactNormals = false;
        overlays.gjkSimplex = views.gjkSimplex;
        overlays.minkowski = views.minkowski;
        RecordingDraw measure;
        drawDebugViews(measure, world, overlays, selectedBody, hitTree(), hitSelection());
        measured(measure);
    }
    // Keep the ground (a static slab, or the grid at groundLevel()) in the picture: always when
    // there is a static body; for bodies in free space only when the ground is near them, so a
    // scene far up in the air is not shrunk to a dot.
    bool hasStatic = false;
    for (const Body& body : world.bodies) hasStatic = hasStatic || body.type == BodyType::Static;
    const Real ground = groundLevel();
    const Real size = std::max(Real(1), (result.max - result.min).maxCoeff());
    if (hasStatic || result.min.y() - ground <= 2 * size) result.min.y() = std::min(result.min.y(), ground);
    return framing;
}

void DemoState::buildDrawList(DrawList& list, const ViewOptions& options) const {
    list.clear();
    list.wireframe = options.wireframe;
    if (options.showGrid) {
        // A 1 m grid around the scene, 1 mm above the ground so it does not z-fight with it.
        const Aabb bounds = bodyBounds();
        const Real y = groundLevel() + Real(0.001);
        const int extent = std::clamp(static_cast<int>(std::ceil(std::max(bounds.extents().x(), bounds.extents().z()))) + 6, 8, 200);
        const int cx = static_cast<int>(std::round(bounds.center().x())), cz = static_cast<int>(std::round(bounds.center().z()));
        const Color minor{0.38f, 0.40f, 0.44f, 1}, major{0.50f, 0.52f, 0.56f, 1};
        for (int i = -extent; i <= extent; ++i) {
            const Color colorX = (cz + i) % 5 == 0 ? major : minor;
            const Color colorZ = (cx + i) % 5 == 0 ? major : minor;
            list.lineWidth(Vec3(Real(cx - extent), y, Real(cz + i)), Vec3(Real(cx + extent), y, Real(cz + i)), colorX, 1);
            list.lineWidth(Vec3(Real(cx + i), y, Real(cz - extent)), Vec3(Real(cx + i), y, Real(cz + extent)), colorZ, 1);
        }
        list.lineWidth(Vec3(0, y, 0), Vec3(1, y, 0), colors::kRed, 3);
        list.lineWidth(Vec3(0, y, 0), Vec3(0, y, 1), colors::kBlue, 3);
    }
    const World& world = session_->world();
    // Chapter 9's views draw the bodies, the contacts (cubes and normals) and whatever the
    // debugger highlights. The solver chapters' impulse arrows take the place of the fixed-length
    // normals when shown: both are yellow arrows from the same point.
    const bool impulses = options.showImpulses && chapterReading("solver") <= chapter_;
    DebugViews shown = views;
    if (impulses) shown.contactNormals = false;
    drawDebugViews(list, world, shown, selectedBody, hitTree(), hitSelection());
    for (const OverlayView& overlay : chapterViews)
        if (overlay.on && overlay.draw) overlay.draw(list, world, overlay.level);
    if (impulses) {
        ContactDrawOptions arrows;
        arrows.points = arrows.normals = false;
        arrows.impulses = true;
        drawContacts(list, world, arrows);
    }
    if (view_) view_->draw(world, list);
    if (!options.showLabels) list.labels.clear();
}

}  // namespace stepwise::render
