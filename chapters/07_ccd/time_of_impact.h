#pragma once
// Time of impact by conservative advancement (Mirtich, "Impulse-based Dynamic Simulation of
// Rigid Body Systems", PhD thesis, UC Berkeley, 1996; the same bound per link in Zhang, Redon,
// Lee, Kim, "Continuous Collision Detection for Articulated Models using Taylor Models and
// Temporal Culling", SIGGRAPH 2007). From a time where the two bodies are a distance d apart, no
// point of one can close on the other faster than a bound mu, so they cannot touch before
// d / mu: advance by that much, measure the distance again with chapter 2's GJK, repeat until
// the distance is within a tolerance of the target.

#include "07_ccd/sweep.h"

namespace stepwise {

// [ch07-toi-tolerances]
/// The bodies stop this far apart (as a fraction of Settings::slop): close enough that the next
/// step's speculative contact holds them, far enough that they do not overlap at the stop.
constexpr Real kToiTargetSlops = Real(1);
/// Conservative advancement stops once the distance is within this (fraction of the slop) of
/// the target. Box2D's b2TimeOfImpact uses a quarter of its linear slop too.
constexpr Real kToiToleranceSlops = Real(0.25);
/// Distance queries before conservative advancement gives up and reports the time reached,
/// which is still before the impact (every advance is safe).
constexpr int kToiMaxIterations = 30;
// [ch07-toi-tolerances]

struct ToiOptions {
    Real target = 0;        // m: stop at this distance
    Real tolerance = 0;     // m: converged within target + tolerance
    int maxIterations = kToiMaxIterations;
};

/// The target and tolerance for a world's slop.
ToiOptions toiOptionsFor(const Settings& settings);

enum class ToiState {
    Separated,   // no impact before the end of the step
    Hit,         // an impact at `time`
    Touching,    // already within target + tolerance where the sweeps start: the solver's job
    Stalled,     // maxIterations spent; `time` is safe (before the impact) but not converged
};

const char* toString(ToiState state);

struct ToiResult {
    ToiState state = ToiState::Separated;
    Real time = 1;                    // fraction of the step
    Real distance = 0;                // m, at `time`
    Vec3 normal = Vec3::UnitY();      // from A towards B at `time`
    Vec3 pointA = Vec3::Zero();       // closest points at `time`, world
    Vec3 pointB = Vec3::Zero();
    int iterations = 0;               // distance queries
};

/// The bound on how fast the gap between the bodies can close, per unit of step fraction, for
/// the direction `normal` (A towards B): the relative centre motion along it (it only counts
/// when it closes) plus each body's turn rate times its lever arm.
Real closingSpeedBound(const Sweep& a, const Shape& shapeA, const Sweep& b, const Shape& shapeB, const Vec3& normal);

/// The first time in [max(alpha0s), 1] at which the two swept shapes come within the target.
ToiResult timeOfImpact(const Shape& shapeA, const Sweep& a, const Shape& shapeB, const Sweep& b,
                       const ToiOptions& options);

}  // namespace stepwise
