#include "06_manifolds/warm_start.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

// [ch06-warm-start]
void loadCarriedImpulses(const World& world, ContactRows& contactRows, bool clampToCone) {
    for (const ContactRowRef& ref : contactRows.points) {
        const Contact& contact = world.contacts[ref.contactIndex];
        const ContactPoint& point = contact.points[ref.pointIndex];
        ConstraintRow& normalRow = contactRows.rows[ref.normalRow];
        normalRow.impulse = std::max(Real(0), point.normalImpulse);
        // The friction impulse is a vector in the contact plane; this step's rows may run along
        // other directions (they follow the sliding velocity), so it is projected onto them.
        Vec3 basis1, basis2;
        tangentBasis(contact.normal, basis1, basis2);
        Vec3 friction = point.tangentImpulse[0] * basis1 + point.tangentImpulse[1] * basis2;
        // Inside the cone of this step's normal impulse, as the iterations would keep it.
        const Real limit = contactRows.rows[ref.tangentRow[0]].boundScale * normalRow.impulse;
        const Real size = friction.norm();
        if (clampToCone && size > limit) friction *= size > 0 ? limit / size : Real(0);
        for (int k = 0; k < 2; ++k) contactRows.rows[ref.tangentRow[k]].impulse = friction.dot(ref.tangent[k]);
    }
}

void warmStart(const World& world, ContactRows& contactRows, std::vector<SolverBody>& bodies) {
    loadCarriedImpulses(world, contactRows);
    applyRowImpulses(contactRows.rows, bodies);
}
// [ch06-warm-start]

}  // namespace stepwise
