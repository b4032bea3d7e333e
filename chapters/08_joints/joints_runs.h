#pragma once
// The runs behind `stepwise bench joints` (bench_joints.cpp): one case, a chain or a ragdoll pile,
// through one configuration of the solver and the joints' feedback, timed and measured.

#include "08_joints/joint_rows.h"
#include "08_joints/joint_solver.h"
#include "08_joints/builders.h"
#include "world/world.h"

#include <cmath>

namespace stepwise::joints_bench {

enum class Case { Hanging, Swinging, HeavyEnd, HeavyEndSwinging, RagdollPile };

const char* caseName(Case which);

constexpr Case kChains[] = {Case::Hanging, Case::Swinging, Case::HeavyEnd, Case::HeavyEndSwinging};

struct Config {
    JointOrder order = kDefaultJointOrder;
    JointFeedback::Kind feedback = JointFeedback::Kind::Soft;
    bool warm = true;                            // Settings::warmStarting
    int iterations = Settings{}.solverIterations;
    int substeps = 1;
    int sweeps = 1;                              // joint sweeps per solver iteration
    Real hertzPerRate = kJointHertzPerStepRate;  // the soft rows' stiffness
};

const char* feedbackName(const Config& config);

struct Outcome {
    double seconds = 0;       // simulated; less than asked when the run stopped
    double stepMs = 0;
    double largestStretch = std::nan("");  // chains only
    double finalStretch = std::nan("");
    double restingSag = std::nan("");      // chains hanging at rest only
    JointErrorSummary error;  // chains: over the run; ragdolls: over the last second
};

/// One case through one configuration for `seconds` of 60 Hz frames.
Outcome run(Case which, const Config& config, double seconds, int ragdolls);

}  // namespace stepwise::joints_bench
