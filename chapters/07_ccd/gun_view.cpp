#include "07_ccd/gun_view.h"

#include "07_ccd/scenes.h"
#include "app/panel.h"
#include "world/debug_draw.h"

#include <cstdio>

namespace stepwise {

// [ch07-view]
void GunView::record(const World& world) const {
    if (world.frame == lastFrame_) return;  // drawn twice in a frame: recorded once
    if (world.frame < lastFrame_) ghosts_.clear();  // the scene started over
    lastFrame_ = world.frame;
    const CcdState& ccd = world.step.ccd;
    for (std::size_t i = 0; i < ccd.ghostBodies.size() && i < ccd.ghostPoses.size(); ++i)
        ghosts_.push_back({ccd.ghostBodies[i], ccd.ghostPoses[i], world.frame});
    while (!ghosts_.empty() && world.frame - ghosts_.front().frame > kGhostFrames) ghosts_.pop_front();
}

void GunView::draw(const World& world, DebugDraw& draw) const {
    record(world);
    // The gun: a barrel at the muzzle, pointing along +x.
    const Vec3 muzzle(kGunX, Real(1.2), 0);
    draw.box(Transform{muzzle - Vec3(Real(0.4), 0, 0), Quat::Identity()}, Vec3(Real(0.4), Real(0.06), Real(0.06)),
             colors::kGrey, Fill::Solid);
    // Where each impact stopped a body, as a wire ghost of its shape at that pose.
    for (const Ghost& ghost : ghosts_) {
        if (ghost.body < 0 || ghost.body >= int(world.bodies.size())) continue;
        Body posed = world.bodies[std::size_t(ghost.body)];
        posed.transform = ghost.pose;
        drawBody(draw, posed, colors::kYellow, Fill::Wire);
    }
    // The last step's swept bounds: everything the fast bodies could have hit.
    for (const Aabb& bounds : world.step.ccd.sweptBounds) {
        draw.box(Transform{bounds.center(), Quat::Identity()}, Real(0.5) * (bounds.max - bounds.min), colors::kCyan, Fill::Wire);
    }
    char line[96];
    std::snprintf(line, sizeof line, "%s: %d fast, %d impacts this step, %ld in all", toString(world.settings.ccd),
                  world.step.ccd.fastBodies, world.step.ccd.toiEvents, world.step.ccd.totalToiEvents);
    draw.text(muzzle + Vec3(0, Real(0.5), 0), std::string("ccd ") + line, colors::kWhite);
}

void GunView::panel(World& world, Panel& panel) {
    bool ccdOn = world.settings.ccd != CcdMode::Off;
    if (panel.checkbox("continuous collision (CCD)", ccdOn)) world.settings.ccd = ccdOn ? CcdMode::Auto : CcdMode::Off;
    panel.sliderFloat("bullet speed (m/s)", speed_, 20, 500);
    if (panel.button("fire at the wall")) fireBullet(world, 0, Real(1.5), Real(speed_));
    if (panel.button("fire at the stack")) fireBullet(world, 1, Real(0.9), Real(speed_));
    char line[128];
    std::snprintf(line, sizeof line, "last step: %d fast bodies, %d times of impact, %d distance queries%s",
                  world.step.ccd.fastBodies, world.step.ccd.toiEvents, world.step.ccd.rootIterations,
                  world.step.ccd.boundHit ? " (event bound hit)" : "");
    panel.text(line);
}
// [ch07-view]

}  // namespace stepwise
