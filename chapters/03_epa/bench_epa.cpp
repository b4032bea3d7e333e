// The EPA bench. Two sets of seeded overlapping pairs with exact answers:
//   boxes       random boxes; exact depth from the separating-axis oracle (the same one the
//               tests use), where EPA's polytope can reach A - B exactly;
//   sphere-box  spheres against boxes forced through GJK + EPA; exact depth from the closed form
//               in double. A - B is curved here, so EPA can only approach it: this is where the
//               tolerance and the iteration cap trade time for accuracy.
// Each configuration runs the whole query (GJK, then EPA) over its set once for the relative
// depth error, then all configurations are timed in turns, round after round, and report the
// median ns per query with its quartiles.
#include "03_epa/bench_epa.h"

#include "03_epa/narrowphase.h"
#include "app/bench_util.h"
#include "math/random.h"

// The exact box-box oracle is shared with the test suites (header-only, double precision).
#include "02_gjk/box_oracle.h"
#include "02_gjk/random_pairs.h"
#include "math/random.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#if __has_include(<ccd/ccd.h>)
#define STEPWISE_LIBCCD_HEADER 1
#else
#define STEPWISE_LIBCCD_HEADER 0
#endif
#if __has_include(<btBulletCollisionCommon.h>) || __has_include(<bullet/btBulletCollisionCommon.h>)
#define STEPWISE_BULLET_HEADER 1
#else
#define STEPWISE_BULLET_HEADER 0
#endif

namespace stepwise {

namespace {

struct BenchPair {
    Shape a, b;
    Transform poseA, poseB;
    double exactDepth = 0;
};

struct PairSet {
    std::string name;
    std::vector<BenchPair> pairs;
};

PairSet makeBoxPairs(int count) {
    Random random(20240605u);
    PairSet set{"boxes", {}};
    while (static_cast<int>(set.pairs.size()) < count) {
        const BoxPair drawn = overlappingBoxPair(random, 0.02);
        set.pairs.push_back(BenchPair{Shape::box(drawn.halfExtentsA), Shape::box(drawn.halfExtentsB), drawn.poseA,
                                      drawn.poseB, -drawn.exactGap});
    }
    return set;
}

PairSet makeSphereBoxPairs(int count) {
    Random random(20240606u);
    PairSet set{"sphere-box", {}};
    while (static_cast<int>(set.pairs.size()) < count) {
        BenchPair pair;
        pair.a = Shape::sphere(Real(random.uniform(0.1, 1)));
        // One draw per statement (z, y, x): a call's arguments are evaluated in an unspecified
        // order, so draws inside one expression would give GCC and Clang different pairs.
        const double halfZ = random.uniform(0.1, 1);
        const double halfY = random.uniform(0.1, 1);
        const double halfX = random.uniform(0.1, 1);
        pair.b = Shape::box(Vec3(Real(halfX), Real(halfY), Real(halfZ)));
        pair.poseB.rotation = random.rotation();
        const double reach = pair.a.radius + pair.b.halfExtents.norm();
        const Real distance = Real(random.uniform(0, reach));  // one draw per statement
        pair.poseB.position = distance * random.unitVector();
        // Exact depth in double: a centre outside the box loses its distance to the box from the
        // radius, a centre inside adds its distance to the nearest face.
        const oracle::OracleBox box = oracle::makeOracleBox(pair.b.halfExtents, pair.poseB);
        const Eigen::Vector3d local = box.axes.transpose() * (pair.poseA.position.cast<double>() - box.center);
        const double outside = oracle::pointBoxDistance(pair.poseA.position.cast<double>(), box);
        const double depth = outside > 0 ? pair.a.radius - outside
                                         : pair.a.radius + (box.halfExtents - local.cwiseAbs()).minCoeff();
        if (depth < 0.02 * pair.a.radius) continue;
        pair.exactDepth = depth;
        set.pairs.push_back(pair);
    }
    return set;
}

// One configuration of the sweep: a pair set, the query's options, and what it measured.
struct Row {
    const PairSet* set = nullptr;
    CollideOptions options;
    std::string support;
    std::string sweep;
    std::vector<double> nsSamples;  // ns per query, one per timed round
    double depthChecksum = 0;       // keeps the timed queries' results in use for the optimiser
    double medianError = 0, p95Error = 0, maxError = 0;
    double meanEpaIterations = 0;
    int failures = 0;
};

Row makeRow(const PairSet& set, const CollideOptions& options, const std::string& sweep) {
    Row row;
    row.set = &set;
    row.options = options;
    row.support = options.supportMode == SupportMode::Extents ? "extents" : "vertices";
    row.sweep = sweep;
    return row;
}

// Accuracy: one pass over the whole set against the exact depths.
void measureErrors(Row& row) {
    std::vector<double> errors;
    double iterations = 0;
    for (const BenchPair& pair : row.set->pairs) {
        const ContactQuery query = collideShapes(pair.a, pair.poseA, pair.b, pair.poseB, row.options);
        if (!query.intersect || !std::isfinite(double(query.depth))) {
            ++row.failures;
            continue;
        }
        errors.push_back(std::abs(double(query.depth) - pair.exactDepth) / pair.exactDepth);
        iterations += query.epaIterations;
    }
    row.medianError = percentile(errors, 0.5);
    row.p95Error = percentile(errors, 0.95);
    row.maxError = percentile(errors, 1.0);
    row.meanEpaIterations = iterations / double(row.set->pairs.size());
}

// [ch03-bench]
// Speed: one round times every configuration once on the same chunk of pairs; the next round
// takes the next chunk, so over all rounds every pair is timed about equally often. A chunk
// takes well under a millisecond, so most escape the moments when the machine (shared with
// other processes) runs something else; the configurations take turns, starting one further
// along each round, so those moments land on a different one each time. The median over the
// rounds ignores them; the quartiles show the scatter that is left.
void timeRound(std::vector<Row>& rows, std::size_t chunkSize, std::size_t round) {
    for (std::size_t k = 0; k < rows.size(); ++k) {
        Row& row = rows[(k + round) % rows.size()];
        const std::size_t setSize = row.set->pairs.size();
        Real depthSum = 0;
        const Stopwatch clock;
        for (std::size_t i = 0; i < chunkSize; ++i) {
            const BenchPair& pair = row.set->pairs[(round * chunkSize + i) % setSize];
            depthSum += collideShapes(pair.a, pair.poseA, pair.b, pair.poseB, row.options).depth;
        }
        row.nsSamples.push_back(clock.seconds() * 1e9 / double(chunkSize));
        row.depthChecksum += double(depthSum);
    }
}
// [ch03-bench]

std::string peerStatus() {
    std::string status = "peers: ";
#if STEPWISE_LIBCCD_HEADER
    status += "libccd headers found, but this build does not link libccd; ";
#else
    status += "libccd not installed (<ccd/ccd.h> not found); ";
#endif
#if STEPWISE_BULLET_HEADER
    status += "Bullet headers found, but this build does not link Bullet";
#else
    status += "Bullet not installed (<btBulletCollisionCommon.h> not found)";
#endif
    return status + ". Only Stepwise is measured.\n";
}

/// One line of the plot: a set and support map's rows as one setting varies.
struct Sweep {
    std::string label;
    std::size_t first = 0, end = 0;   // its rows
};

/// The sweeps: per set and support map, the tolerance, then (extents only) the iteration cap; and
/// the closed form the sphere-box pairs normally take, for scale.
void buildSweeps(const PairSet (&sets)[2], std::vector<Row>& rows, std::vector<Sweep>& sweeps) {
    const std::vector<double> tolerances = {1e-1, 3e-2, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7};
    const std::vector<int> caps = {1, 2, 4, 8, 16, 32, 50, 100};
    for (const PairSet& set : sets) {
        const std::vector<SupportMode> modes = set.name == "boxes" ? std::vector<SupportMode>{SupportMode::Extents, SupportMode::Vertices}
                                                                   : std::vector<SupportMode>{SupportMode::Extents};
        for (SupportMode mode : modes) {
            CollideOptions base;
            base.closedForms = false;  // the point is EPA, even for spheres
            base.supportMode = mode;
            const std::string label = set.name + (mode == SupportMode::Vertices ? ", vertices" : "");
            sweeps.push_back({label + ": tolerance", rows.size(), 0});
            for (double tolerance : tolerances) {
                CollideOptions options = base;
                options.epa.relativeTolerance = Real(tolerance);
                rows.push_back(makeRow(set, options, "tolerance"));
            }
            sweeps.back().end = rows.size();
            if (mode == SupportMode::Vertices) continue;
            sweeps.push_back({label + ": iteration cap", rows.size(), 0});
            for (int cap : caps) {
                CollideOptions options = base;
                options.epa.maxIterations = cap;
                rows.push_back(makeRow(set, options, "iteration_cap"));
            }
            sweeps.back().end = rows.size();
        }
    }
    sweeps.push_back({"sphere-box: closed form", rows.size(), rows.size() + 1});
    rows.push_back(makeRow(sets[1], CollideOptions{}, "closed_form"));
    rows.back().support = "closed_form";
}

/// Each sweep a line: the 95th percentile error against the median time, quartiles as whiskers.
void plotSweeps(const std::vector<Row>& rows, const std::vector<Sweep>& sweeps, PlotSpec& plot) {
    for (const Sweep& sweep : sweeps) {
        PlotSeries series(sweep.label, sweep.end - sweep.first == 1);
        for (std::size_t i = sweep.first; i < sweep.end; ++i) {
            const Spread ns = spreadOf(rows[i].nsSamples);
            series.x.push_back(ns.median);
            series.xLow.push_back(ns.lower);
            series.xHigh.push_back(ns.upper);
            series.y.push_back(rows[i].p95Error);
        }
        plot.series.push_back(series);
    }
}

CsvTable epaTable(const std::vector<Row>& rows) {
    CsvTable table({"pairs", "support", "sweep", "relative_tolerance", "max_iterations", "ns_per_query",
                    "median_rel_error", "p95_rel_error", "max_rel_error", "mean_epa_iterations", "failures",
                    "ns_q1", "ns_q3"});
    for (const Row& row : rows) {
        const Spread ns = spreadOf(row.nsSamples);
        table.addRow({row.set->name, row.support, row.sweep, formatNumber(double(row.options.epa.relativeTolerance)),
                      std::to_string(row.options.epa.maxIterations), formatNumber(ns.median),
                      formatNumber(row.medianError), formatNumber(row.p95Error), formatNumber(row.maxError),
                      formatNumber(row.meanEpaIterations, 3), std::to_string(row.failures), formatNumber(ns.lower),
                      formatNumber(ns.upper)});
    }
    return table;
}

void measureEpa(BenchRun& run) {
    const int pairCount = run.quick() ? 1000 : 5000;
    const std::size_t chunkSize = 100;
    const int rounds = run.quick() ? 60 : 200;  // every pair timed 6 (quick) or 4 times
    run.progress().stage("drawing pairs with exact depths", 1);
    const PairSet sets[2] = {makeBoxPairs(pairCount), makeSphereBoxPairs(pairCount)};
    std::vector<Row> rows;
    std::vector<Sweep> sweeps;
    buildSweeps(sets, rows, sweeps);

    run.progress().stage("depth errors of " + std::to_string(rows.size()) + " configurations", long(rows.size()));
    for (Row& row : rows) {
        measureErrors(row);
        run.progress().advance();
    }
    run.progress().stage("timing them in turns", rounds);
    for (int round = 0; round < rounds; ++round) {
        timeRound(rows, chunkSize, std::size_t(round));
        run.progress().advance();
    }
    run.progress().endStage();

    const std::string precision = realTypeName();
    PlotSpec plot("EPA work-precision, Real = " + precision, "ns per query (GJK + EPA)",
                  "95th percentile relative depth error");
    plot.caption = "Each point is one setting of EPA's relative tolerance or iteration cap: the 95th percentile "
                   "of the relative depth error over " + std::to_string(pairCount) + " overlapping pairs against "
                   "the time per query (median of " + std::to_string(rounds) + " rounds of " +
                   std::to_string(chunkSize) + " pairs, all settings timed in turns on the same pairs; whiskers "
                   "span the middle half of the rounds). Lower left is better.";
    plotSweeps(rows, sweeps, plot);
    const CsvTable table = epaTable(rows);
    run.out() << "EPA bench: " << pairCount << " overlapping pairs per set, Real = " << precision
              << ", default tolerance " << formatNumber(double(kEpaDefaultRelativeTolerance)) << ", cap "
              << EpaSettings{}.maxIterations << "; ns: median of " << rounds << " rounds (ns_q1, ns_q3: quartiles)\n"
              << table.toText() << peerStatus();
    run.writeCsv(table);
    run.writePlot(plot);
}

}  // namespace

// [foundation-bench-card]
BenchEntry epaBench() {
    return benchEntry(3, measureEpa, R"(
        epa: EPA depth error against run time as tolerance and iteration cap vary; extents
            against vertex support (work-precision)
        epa.csv  per setting: ns per query (median, quartiles), depth errors, iterations
        epa.svg  work-precision plot: depth error against ns per query)");
}
// [foundation-bench-card]

}  // namespace stepwise
