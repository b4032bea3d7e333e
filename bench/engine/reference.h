#pragma once
// The reference suite's sidecars and their metrics (docs/engine_bench.md). A reference scene
// NAME.json has a sidecar NAME.expect.json saying how long to run it and what to compare:
//   { "format": "stepwise-expect", "version": 1, "group": "contact", "seconds": 1.5,
//     "checks": [ { "metric": "bounce_apex", "body": "ball", "expected": 0.74,
//                   "tolerance": 0.032, "why": "5% of the rebound height: ..." } ] }
// Each metric turns a recorded run (a Trajectory) into an error in the check's units; the
// check's score is error / tolerance, and a run meets the reference when every score is <= 1.

#include "world/world.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace stepwise::engine_bench {

/// A sidecar that cannot be used: what() names the file and the JSON path, e.g.
/// "scenes/reference/ramp.expect.json: checks[1].metric: unknown metric \"slide\" (known: ...)".
struct SidecarError : std::runtime_error {
    explicit SidecarError(const std::string& message) : std::runtime_error(message) {}
};

/// One comparison with the known answer. Which fields a metric reads is listed in metricNames().
struct Check {
    std::string metric;
    std::string body;                 // the body it looks at, for per-body metrics
    double expected = 0;              // the known answer, in the metric's units
    double tolerance = 0;             // > 0, same units: the error a user would not notice
    std::string why;                  // the tolerance's physical reason (required)
    Vec3 point = Vec3::Zero();        // max_distance: a point in the body's frame, m
    Vec3 to = Vec3::Zero();           // max_distance: a world point, m
    double center = 0;                // period: the x the body swings about, m
    int axis = 0;                     // max_coordinate: 0, 1 or 2
    double limit = 0;                 // max_coordinate: m
    double kineticFraction = 0.001;   // time_to_rest: of the starting energy
};

struct Sidecar {
    std::string group;                // which plot the scene belongs to: closed-form, contact, joint, stack, pile
    double seconds = 0;               // simulated time of every run
    std::vector<Check> checks;
};

/// The metrics a sidecar may name, in the order docs/engine_bench.md lists them.
const std::vector<std::string>& metricNames();
/// The groups a sidecar may name (one plot each).
const std::vector<std::string>& groupNames();

/// Parses a sidecar; `source` names it in messages. Throws SidecarError.
Sidecar parseSidecar(const std::string& jsonText, const std::string& source);
/// Reads NAME.expect.json. Throws SidecarError ("PATH: no such file", malformed JSON, ...).
Sidecar loadSidecar(const std::string& path);

/// A run as the metrics see it: every body's pose at every frame (frame 0: the start), the
/// start and end worlds (velocities, masses, energy) and the overlap left at the end.
struct Trajectory {
    double dt = 0;                                  // s between recorded frames
    std::vector<std::vector<Transform>> poses;      // per recorded frame, every body's pose
    World start;
    World end;                                      // final poses and velocities
    double finalPenetration = -1;                   // m; < 0: not measured
};

/// Throws SidecarError (naming `source`) when a check names a body `world` does not have.
void checkBodiesExist(const Sidecar& sidecar, const World& world, const std::string& source);

/// The check's error on `run`, in its units (>= 0; NaN when the run did not measure it, as the
/// penetration without a probe). The check's body must exist (checkBodiesExist).
double measureError(const Check& check, const Trajectory& run);

/// A run scored against its sidecar: each check's error, and the worst error / tolerance.
struct Score {
    std::vector<double> errors;       // per check, in its units (NaN: not measured)
    double worst = 0;                 // largest error / tolerance; infinity when a check was not measured
    std::size_t worstCheck = 0;
    bool meets() const { return worst <= 1; }
};

Score scoreRun(const Sidecar& sidecar, const Trajectory& run);

}  // namespace stepwise::engine_bench
