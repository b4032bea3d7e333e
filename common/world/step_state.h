#pragma once
// What one step hands from stage to stage, and what the last step measured. It lives in the
// World (never in a stage's closure) so that copying the World is a complete snapshot: a copy
// stepped on gives exactly the states the original does (the rewind of chapter 9, to come, relies on it).

#include "math/math.h"

#include <vector>

namespace stepwise {

struct BodyVelocity {
    Vec3 linear = Vec3::Zero();
    Vec3 angular = Vec3::Zero();
};

/// What the last call of the contact solver did, for tests, benches and the demo panel.
struct SolverStats {
    int contactPoints = 0;       // points in World::contacts when the solve started
    int rows = 0;                // constraint rows built from them
    int invalidSkipped = 0;      // points with non-finite data, skipped (a defined result, not a crash)
    Real residualRms = 0;        // velocity residual after the last iteration, m/s
    Real residualMax = 0;        // m/s
};

struct StepState {
    int substep = 0;             // of the frame being stepped, 0 .. substepCount - 1
    int substepCount = 1;
    /// One per body, taken before this substep's forces: restitution reverses the approach speed
    /// they give (Box2D's "relax" velocity). Empty when no stage took them this substep.
    std::vector<BodyVelocity> velocitiesBeforeForces;
    int contactsFoundAtSubstep = 0;  // when World::contacts were last searched; later substeps
                                     // move their points with the bodies before solving
    SolverStats solver;          // of the last solve (the last substep of the last frame)
    int contactPointsDropped = 0;  // by the last cache upkeep: points that carried no load
};

}  // namespace stepwise
