#pragma once
// The demo's view of chapter 7's scenes: the gun, the bodies' poses at each time of impact
// (ghosts, kept for a second), the swept bounds of the last step's fast bodies; a CCD toggle, the
// bullets' speed and two triggers. Drawing only through DebugDraw, controls only through Panel.

#include "app/registry.h"
#include "world/world.h"

#include <deque>

namespace stepwise {

class GunView : public SceneView {
public:
    void draw(const World& world, DebugDraw& draw) const override;
    bool hasPanel() const override { return true; }
    void panel(World& world, Panel& panel) override;

private:
    struct Ghost {
        int body = -1;
        Transform pose;
        long frame = 0;
    };
    void record(const World& world) const;

    static constexpr long kGhostFrames = 60;  // a ghost stays a second at 60 Hz
    float speed_ = 150;                       // m/s of the next bullet fired
    mutable std::deque<Ghost> ghosts_;
    mutable long lastFrame_ = -1;
};

}  // namespace stepwise
