#include "hit_tree_panel.h"

#include <imgui.h>

#include <algorithm>

namespace stepwise::render {

namespace {

/// Pairs listed at most: a stress scene's thousands of pairs would make the panel useless and slow.
constexpr int kMaxPairs = 200;

/// One tree node; true when it is open. Clicking its label (not its arrow) selects it.
bool node(DemoState& state, const HitSelection& self, const std::string& label, bool leaf) {
    const HitSelection& selected = state.hitSelection();
    const bool onPath = selected.pair == self.pair && (self.manifold < 0 || selected.manifold == self.manifold);
    if (state.revealSelection && onPath && !leaf) ImGui::SetNextItemOpen(true);
    ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_OpenOnDoubleClick | ImGuiTreeNodeFlags_SpanAvailWidth;
    if (leaf) flags |= ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
    if (selected == self) flags |= ImGuiTreeNodeFlags_Selected;
    const bool open = ImGui::TreeNodeEx(label.c_str(), flags);
    if (ImGui::IsItemClicked() && !ImGui::IsItemToggledOpen()) state.selectHit(self);
    if (state.revealSelection && selected == self) ImGui::SetScrollHereY(0.5f);
    return open && !leaf;
}

}  // namespace

void hitTreeSection(DemoState& state) {
    const HitTree& tree = state.hitTree();
    if (tree.pairs.empty()) {
        ImGui::TextDisabled("no contacts this frame");
        state.revealSelection = false;
        return;
    }
    ImGui::Text("%d pairs touching, %d points", static_cast<int>(tree.pairs.size()), tree.pointCount());
    if (!state.hitSelection().empty()) {
        ImGui::SameLine();
        if (ImGui::SmallButton("clear selection")) state.selectHit(HitSelection());
    }
    // The tree scrolls inside its own child window, so a long list does not push the other
    // sections off the screen.
    const float rows = static_cast<float>(std::min(12, 2 + tree.pointCount() + static_cast<int>(tree.pairs.size())));
    ImGui::BeginChild("##hit-tree", ImVec2(0, rows * ImGui::GetTextLineHeightWithSpacing()), true);
    const int shown = std::min(static_cast<int>(tree.pairs.size()), kMaxPairs);
    for (int p = 0; p < shown; ++p) {
        const HitPair& pair = tree.pairs[static_cast<std::size_t>(p)];
        ImGui::PushID(p);
        if (node(state, HitSelection{p, -1, -1}, describePair(pair), false)) {
            for (int m = 0; m < static_cast<int>(pair.manifolds.size()); ++m) {
                const HitManifold& manifold = pair.manifolds[static_cast<std::size_t>(m)];
                ImGui::PushID(m);
                if (node(state, HitSelection{p, m, -1}, describeManifold(manifold), false)) {
                    for (int i = 0; i < static_cast<int>(manifold.points.size()); ++i) {
                        ImGui::PushID(i);
                        node(state, HitSelection{p, m, i}, describePoint(i, manifold.points[static_cast<std::size_t>(i)]), true);
                        ImGui::PopID();
                    }
                    ImGui::TreePop();
                }
                ImGui::PopID();
            }
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    if (shown < static_cast<int>(tree.pairs.size()))
        ImGui::TextDisabled("... and %d more pairs", static_cast<int>(tree.pairs.size()) - shown);
    ImGui::EndChild();
    state.revealSelection = false;
}

}  // namespace stepwise::render
