#include "scripted.h"

#include <sstream>
#include <algorithm>
#include <stdexcept>
#include <vector>

namespace stepwise::render {

namespace {

std::vector<std::string> splitCommas(const std::string& list) {
    std::vector<std::string> items;
    std::stringstream in(list);
    std::string item;
    while (std::getline(in, item, ','))
        if (!item.empty()) items.push_back(item);
    return items;
}

/// The chapters' own views, by name: "mesh-tree" (level 0) or "mesh-tree:4". False when the
/// demo has no view of that name.
bool applyOverlay(const std::string& item, DemoState& state) {
    const size_t colon = item.find(':');
    DemoState::OverlayView* overlay = state.findOverlay(item.substr(0, colon));
    if (!overlay) return false;
    overlay->on = true;
    if (colon != std::string::npos) {
        const std::string text = item.substr(colon + 1);
        std::istringstream in(text);
        int level = -1;
        if (!(in >> level) || !in.eof() || level < 0 || level >= std::max(overlay->overlay->levels, 1))
            throw std::invalid_argument("view '" + item + "': the level must be a whole number from 0 to " +
                                        std::to_string(std::max(overlay->overlay->levels - 1, 0)));
        overlay->level = level;
    }
    return true;
}

std::string overlayNames(const DemoState& state) {
    std::string names;
    for (const DemoState::OverlayView& overlay : state.chapterViews)
        names += ", " + overlay.overlay->name + (overlay.overlay->levels > 0 ? "[:level]" : "");
    return names;
}

}  // namespace

const char* viewListNames() {
    return "colliders, contacts, normals, epa, simplex, minkowski, bounds, joints, wireframe (the selection's), "
           "impulses, wireframe-all";
}

void applyViewList(const std::string& list, DemoState& state, ViewOptions& view) {
    DebugViews views;
    views.colliders = views.wireframeSelection = views.contactPoints = views.contactNormals = false;
    view.showImpulses = view.wireframe = false;
    for (DemoState::OverlayView& overlay : state.chapterViews) overlay.on = false;
    for (const std::string& name : splitCommas(list)) {
        if (name == "colliders") views.colliders = true;
        else if (name == "contacts") views.contactPoints = true;
        else if (name == "normals") views.contactNormals = true;
        else if (name == "epa") views.epaFace = true;
        else if (name == "simplex") views.gjkSimplex = true;
        else if (name == "minkowski") views.minkowski = true;
        else if (name == "bounds") views.bounds = true;
        else if (name == "joints") views.joints = true;
        else if (name == "wireframe") views.wireframeSelection = true;
        else if (name == "impulses") view.showImpulses = true;
        else if (name == "wireframe-all") view.wireframe = true;
        else if (!applyOverlay(name, state)) throw std::invalid_argument("unknown view '" + name + "' (views: " + viewListNames() + overlayNames(state) + ")");
    }
    state.views = views;
}

void openSections(const std::string& list, DebugTools& tools) {
    for (const std::string& name : splitCommas(list)) {
        const int section = sectionByName(name);
        if (section < 0) throw std::invalid_argument("unknown section '" + name + "' (session, views, hits, inspector, perf)");
        tools.openRequest[section] = true;
    }
}

void parsePixel(const std::string& text, float& x, float& y) {
    std::istringstream in(text);
    char comma = 0;
    if (!(in >> x >> comma >> y) || comma != ',' || !in.eof())
        throw std::invalid_argument("'" + text + "' is not a pixel X,Y");
}

int findBody(const World& world, const std::string& nameOrIndex) {
    for (size_t i = 0; i < world.bodies.size(); ++i)
        if (world.bodies[i].name == nameOrIndex) return static_cast<int>(i);
    std::istringstream in(nameOrIndex);
    int index = -1;
    if (in >> index && in.eof() && index >= 0 && index < static_cast<int>(world.bodies.size())) return index;
    return -1;
}

}  // namespace stepwise::render
