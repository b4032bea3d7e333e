#pragma once
// The runs behind `stepwise bench speed` (bench_speed.cpp): chapter 12's step on a copy of a scene,
// frame by frame, measuring as it goes, alone or taking turns with the peer.

#include "12_planner/chapter.h"
#include "08_joints/builders.h"
#include "app/bench_util.h"
#include "world/world.h"

#include <map>
#include <string>
#include <utility>

namespace stepwise::speed_bench {

/// What one run measured.
struct Measurement {
    Spread stepMs;
    std::map<std::string, double> stageMs;   // mean per frame
    long frames = 0;
    Real maxSideways = 0;   // m, largest horizontal move of a dynamic body from its start
    Real lowest = 0;        // m, lowest centre of a dynamic body (below the ground: tunnelled)
    Real maxPenetration = 0;   // m, deepest contact point from kSettledFrom on
    Real beyondTrue = -1;      // m, most a contact read deeper than its shapes overlap (contact_truth.h); -1: not checked
    Real shortOfTrue = -1;     // m, most a pair's shapes overlapped beyond its contact's deepest point; -1: not checked
    JointErrorSummary jointError;  // largest over the last second (scenes with joints)
    Real jointGapMean = -1;        // m, each second's largest anchor gap, averaged over the run; -1: no joints
    int sleeping = 0;
    FastSolveStats solvePhases;  // ms per timed frame in each phase of the fast solve
    long jointsBuilt = 0, jointsKept = 0;  // timed frames' substeps: joints whose rows were built, kept
};

/// `frames` frames of chapter 12's step on a copy of `start`, timed from `timedFrom`; `profile`
/// times the fast solve's phases too (which costs a small scene's frame several percent).
Measurement runEngine(const World& start, const SpeedOptions& options, long frames, long timedFrom, bool profile = false);

/// Frames until every dynamic body of `start` sleeps, stepped by chapter 12 with sleeping on; at
/// most `most`.
long framesUntilAsleep(const World& start, long most);

/// Chapter 12 and the peer on the same scene, taking turns (kFramesATurn): the engine's
/// measurement and the peer's.
std::pair<Measurement, Measurement> runBeside(const World& start, const SpeedOptions& options, long frames, long timedFrom);

}  // namespace stepwise::speed_bench
