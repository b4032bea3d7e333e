#pragma once
// The sorted time-of-impact loop. For the bodies that need it (fast_bodies.h) it finds the times
// of impact against what they can hit in the step, takes the earliest, moves the bodies of that
// event to their poses at that time, resolves the contact with one impulse along its normal, and
// looks again at whatever that changed, until no impact is left in the step or an event bound
// is hit. A body stays at its time-of-impact pose for the rest of the step: that time is lost,
// and the next step's contacts (chapters 3 and 6) carry on from a pose that did not tunnel.
// Contacts the step began with (TOI = 0) stay with the sequential-impulse solver.

#include "07_ccd/time_of_impact.h"

#include <vector>

namespace stepwise {

// [ch07-event-bounds]
/// Impacts one body may take in one step; past it the body waits where its last impact left it.
constexpr int kMaxToiEventsPerBody = 4;
/// Impacts resolved in one step, all bodies together: a pathological scene (a hundred bullets
/// in a box) stops here instead of stalling the frame; the rest wait at their next impact.
constexpr int kMaxToiEventsPerStep = 64;
// [ch07-event-bounds]

/// One impact found in the step: `mover` (the body being checked) meets `other` at toi.time.
struct ToiEvent {
    int mover = -1;
    int other = -1;
    ToiResult toi;
};

/// Whether the loop checks `mover` against `other`: dynamic against static always; dynamic
/// against dynamic when one of them is a bullet. Kinematic bodies are left to the solver.
bool mayHit(const World& world, int mover, int other);

/// The impact of a pair over their sweeps, if one happens after both sweeps start: closed form
/// for two spheres, conservative advancement otherwise. A pair that starts touching but still
/// closes (a spinning rod's far end) is advanced to half its starting gap instead.
bool findImpact(const World& world, int mover, int other, const std::vector<Sweep>& sweeps, const ToiOptions& options,
                ToiEvent& event);

/// The normal impulse of an impact at its time-of-impact poses: the pair's restitution (above
/// Settings::restitutionThreshold) reverses the approach speed at the contact point; no friction.
/// Returns the impulse applied, N s.
Real resolveImpact(World& world, const ToiEvent& event, const std::vector<Sweep>& sweeps);

/// What one run of the loop works on: every body's sweep, which bodies it checks, the impacts
/// found and not yet resolved, and how many each body took. Working memory only: the pipeline
/// keeps one from step to step so that the loop allocates nothing once it has run.
struct ToiLoopScratch {
    std::vector<Sweep> sweeps;
    std::vector<char> checked;     // 1: a body whose sweep the loop looks at
    std::vector<char> stopped;     // 1: a body waiting at its time-of-impact pose
    std::vector<int> eventsOf;
    std::vector<ToiEvent> pending;
    int resolved = 0;
    int queries = 0;               // distance queries of the impacts found
};

/// The whole loop for one step of dt: reads World::step.ccd.sweepStart and the bodies' poses
/// now (the end of the step), writes the corrected poses and velocities and what it did.
void resolveTimesOfImpact(World& world, Real dt);
/// The same, in working memory kept by the caller.
void resolveTimesOfImpact(World& world, Real dt, ToiLoopScratch& scratch);

}  // namespace stepwise
