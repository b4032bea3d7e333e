#include "04_pgs/contact_draw.h"

#include <algorithm>

namespace stepwise {

void drawContactImpulses(const World& world, DebugDraw& draw, Real metresPerNewton) {
    const Real substepDt = world.settings.dt / static_cast<Real>(std::max(1, world.settings.substeps));
    if (!(substepDt > 0)) return;
    const Real scale = metresPerNewton / substepDt;  // metres per (N s) of impulse
    for (const Contact& contact : world.contacts) {
        // The stored friction impulse is in the fixed basis u1 = anyPerpendicular(n), u2 = n x u1.
        const Vec3 fixed1 = anyPerpendicular(contact.normal);
        const Vec3 fixed2 = contact.normal.cross(fixed1);
        for (int i = 0; i < contact.pointCount; ++i) {
            const ContactPoint& point = contact.points[i];
            const Vec3 at = Real(0.5) * (point.pointA + point.pointB);
            draw.point(at, 6, colors::kRed);
            // The impulse acts on B along +normal; draw it where B feels it.
            if (point.normalImpulse > 0)
                draw.arrow(at, at + scale * point.normalImpulse * contact.normal, colors::kYellow);
            const Vec3 friction = point.tangentImpulse[0] * fixed1 + point.tangentImpulse[1] * fixed2;
            if (friction.squaredNorm() > 0) draw.arrow(at, at + scale * friction, colors::kOrange);
        }
    }
}

}  // namespace stepwise
