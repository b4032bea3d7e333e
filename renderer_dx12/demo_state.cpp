#include "demo_state.h"

#include "app/runner.h"
#include "bounds_draw.h"
#include "world/contact_draw.h"
#include "world/shape.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stepwise::render {

DemoState::DemoState(const Registry& registry, int chapter) : registry_(registry), chapter_(chapter) {
    for (const SceneEntry& entry : registry.scenes()) {
        if (entry.chapter <= chapter && entry.build) scenes_.push_back(&entry);
    }
}

void DemoState::setWorld(World next) {
    world = std::move(next);
    accumulator_ = 0;
    stageHistory.clear();
    frameHistory.clear();
    pipelineError.clear();
    try {
        pipeline = registry_.makePipeline(world, chapter_);
    } catch (const std::exception& error) {
        pipeline = Pipeline();
        pipelineError = error.what();
    }
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
    if (paused) return;
    const double dt = world.settings.dt > 0 ? static_cast<double>(world.settings.dt) : 1.0 / 60.0;
    accumulator_ += std::clamp(wallSeconds, 0.0, 0.25) * static_cast<double>(timeScale);
    // At most 4 steps per displayed frame: a slow machine runs in slow motion instead of
    // falling further and further behind (Gaffer on Games, "Fix your timestep").
    for (int steps = 0; accumulator_ >= dt && steps < 4; ++steps) {
        step();
        accumulator_ -= dt;
    }
    accumulator_ = std::min(accumulator_, dt);
}

void DemoState::step() {
    pipeline.step(world);
    for (const Stage& stage : pipeline.stages()) {
        auto& history = stageHistory[stage.name];
        history.push_back(static_cast<float>(stage.enabled ? stage.lastMs : 0.0));
        if (history.size() > kHistory) history.pop_front();
    }
    frameHistory.push_back(static_cast<float>(pipeline.lastStepMs()));
    if (frameHistory.size() > kHistory) frameHistory.pop_front();
}

Real DemoState::groundLevel() const {
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
    Framing framing;
    Aabb& result = framing.bounds;
    result = bodyBounds();
    // The scene's overlay counts as content: chapter 2 draws A - B above its bodies, chapter 3
    // the EPA polytope beside them. Drawing changes neither world nor view, so measuring is harmless.
    if (view_) {
        BoundsDraw measure;
        try {
            view_->draw(world, measure);
        } catch (const std::exception&) {
            // A hook that throws draws nothing here either; the bodies alone are framed.
        }
        if (!measure.empty()) result.grow(measure.bounds());
        framing.labels = std::move(measure.labels);
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
    drawWorld(list, world);
    if (options.showContacts || options.showImpulses) {
        ContactDrawOptions contactOptions;
        contactOptions.points = contactOptions.normals = options.showContacts;
        contactOptions.impulses = options.showImpulses && chapterReading("solver") <= chapter_;
        drawContacts(list, world, contactOptions);
    }
    if (view_) view_->draw(world, list);
    if (!options.showLabels) list.labels.clear();
}

}  // namespace stepwise::render
