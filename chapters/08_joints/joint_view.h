#pragma once
// The demo's view of chapter 8's scenes: every joint drawn where it is now, with what it allows.
// Anchors are points; a hinge shows its axis, its limits as an arc and the angle it is at; a
// cone-twist its cone and its twist limits; a slider its travel as a segment with end ticks; a
// distance joint the line between its anchors, coloured by how far it is stretched. A joint more
// than 1 cm from what it asks (measureJointError) turns red. Kinematic paths show as lines.
// Drawing only through DebugDraw: the physics never sees the renderer.

#include "app/registry.h"
#include "world/debug_draw.h"
#include "world/world.h"

namespace stepwise {

/// Position error (m) from which a joint is drawn red: a centimetre is visible at demo scale.
constexpr Real kJointErrorShown = Real(0.01);

/// A distance joint's colour for its stretch, (length now - rest) / rest: green at rest, through
/// yellow to orange at 25% longer (a spring at full swing), cyan when shorter (only a spring can be).
Color stretchColor(Real stretch);

/// One line naming a joint and its settings, for labels: "hinge [-45, 45] deg".
std::string describeJoint(const JointDesc& joint);

/// Draws one joint (nothing when its body indices are not valid); with a label height above 0,
/// its describeJoint label that far (m) above its first anchor.
void drawJoint(DebugDraw& draw, const World& world, const JointDesc& joint, Real labelHeight = 0);

class JointView : public SceneView {
public:
    JointView() = default;
    /// With labels, each joint is named above its first anchor (the gallery's captions).
    explicit JointView(bool labels) : labels_(labels) {}
    void draw(const World& world, DebugDraw& draw) const override;

private:
    bool labels_ = false;
};

/// The factory the chapter's scenes register: a fresh JointView per load.
SceneViewFactory jointView(bool labels = false);

}  // namespace stepwise
