// Chapter 11's pieces (turn_pieces.h).
#include "11_wide_solve/turn_pieces.h"

#include "11_wide_solve/solve_steps.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

int substepsForTurns(const World& world, Real dt, int substeps) {
    // The fastest turn, over the frame, of an awake dynamic body some contact touches, at no more
    // than the spin a solve of the frame allows in substeps short enough (kMostTurnPerSolve).
    const Real most = kMostTurnPerSolve / dt;
    Real fastestSquared = 0;
    for (const Contact& contact : world.contacts) {
        if (contact.pointCount <= 0) continue;
        for (const int body : {contact.bodyA, contact.bodyB}) {
            if (body < 0 || static_cast<std::size_t>(body) >= world.bodies.size()) continue;
            const Body& shape = world.bodies[static_cast<std::size_t>(body)];
            // A ball's rows stand at any turn: its arms reach its centre, its inertia is the same every way.
            if (shape.type != BodyType::Dynamic || shape.shape.type == ShapeType::Sphere) continue;
            const Motion* motion = world.motionOf(body);
            if (!motion || motion->asleep) continue;
            const Real spinSquared = motion->angularVelocity.squaredNorm();  // the root once, below
            if (std::isfinite(spinSquared)) fastestSquared = std::max(fastestSquared, spinSquared);
        }
    }
    const Real turn = std::min(std::sqrt(fastestSquared), most) * dt;
    if (!(turn > kMostTurnPerPiece * static_cast<Real>(substeps))) return substeps;
    return static_cast<int>(std::ceil(turn / kMostTurnPerPiece - Real(1e-3)));
}

/// The dynamic slots the contacts touch, each once (the bodies whose turn ends a piece).
void findTouched(ContactSolverScratch& scratch) {
    const int firstDynamic = scratch.bodies.firstDynamic;
    scratch.touchedFlag.assign(scratch.bodies.states.size(), 0);
    scratch.touched.clear();
    for (const std::vector<int>* slots : {&scratch.slotA, &scratch.slotB})
        for (const int slot : *slots) {
            if (slot < firstDynamic || scratch.touchedFlag[static_cast<std::size_t>(slot)]) continue;
            scratch.touchedFlag[static_cast<std::size_t>(slot)] = 1;
            scratch.touched.push_back(slot);
        }
}

// [ch11-turned-far-rule]
/// Whether a touched body has turned since the piece began, or would after one more substep of h
/// at its spin now, further than kMostTurnPerPiece: the turn 2 |v| of its quaternion v + w, and
/// |w| h more.
bool turnedFar(const SolverBodyState* states, const std::vector<int>& touched, Real h) {
    const Real most = kMostTurnPerPiece * kMostTurnPerPiece;
    for (const int slot : touched) {
        const SolverBodyState& s = states[slot];
        const Real turned = 4 * (s.deltaRotation[0] * s.deltaRotation[0] + s.deltaRotation[1] * s.deltaRotation[1] +
                                 s.deltaRotation[2] * s.deltaRotation[2]);
        const Real next = h * h * (s.angularVelocity[0] * s.angularVelocity[0] + s.angularVelocity[1] * s.angularVelocity[1] +
                                   s.angularVelocity[2] * s.angularVelocity[2]);
        if (2 * (turned + next) <= most) continue;  // (a + b)^2 <= 2 (a^2 + b^2): far within
        if (turned + next + 2 * std::sqrt(turned * next) > most) return true;
    }
    return false;
}
// [ch11-turned-far-rule]

}  // namespace stepwise
