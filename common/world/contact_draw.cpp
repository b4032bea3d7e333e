#include "world/contact_draw.h"

#include <algorithm>

namespace stepwise {

namespace {

void drawMarkers(DebugDraw& draw, const Vec3& pointA, const Vec3& pointB, const ContactDrawOptions& options) {
    Transform marker;
    for (const Vec3& at : {pointA, pointB}) {
        marker.position = at;
        draw.box(marker, Vec3::Constant(options.markerHalfSize), colors::kRed, Fill::Solid);
    }
}

}  // namespace

void drawContact(DebugDraw& draw, const Vec3& pointA, const Vec3& pointB, const Vec3& normal,
                 const ContactDrawOptions& options) {
    if (options.points) drawMarkers(draw, pointA, pointB, options);
    if (options.normals) draw.arrow(pointB, pointB + options.normalLength * normal, colors::kYellow);
}

void drawContacts(DebugDraw& draw, const World& world, const ContactDrawOptions& options) {
    const Real substepDt = world.settings.dt / static_cast<Real>(std::max(1, world.settings.substeps));
    // Impulse over a substep is a mean force; the arrow shows that force.
    const Real metresPerImpulse = substepDt > 0 ? options.metresPerNewton / substepDt : Real(0);
    for (const Contact& contact : world.contacts) {
        Vec3 tangent1, tangent2;
        tangentBasis(contact.normal, tangent1, tangent2);
        for (int i = 0; i < std::clamp(contact.pointCount, 0, 4); ++i) {
            const ContactPoint& point = contact.points[i];
            if (options.points) drawMarkers(draw, point.pointA, point.pointB, options);
            if (!options.impulses) {
                if (options.normals)
                    draw.arrow(point.pointB, point.pointB + options.normalLength * contact.normal, colors::kYellow);
                continue;
            }
            // The impulse acts on B along +normal; draw it where B feels it.
            if (point.normalImpulse > 0)
                draw.arrow(point.pointB, point.pointB + metresPerImpulse * point.normalImpulse * contact.normal,
                           colors::kYellow);
            const Vec3 friction = point.tangentImpulse[0] * tangent1 + point.tangentImpulse[1] * tangent2;
            if (friction.squaredNorm() > 0)
                draw.arrow(point.pointB, point.pointB + metresPerImpulse * friction, colors::kOrange);
        }
    }
}

}  // namespace stepwise
