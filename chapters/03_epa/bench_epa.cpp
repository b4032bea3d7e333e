// The EPA bench. Two sets of seeded overlapping pairs with exact answers:
//   boxes       random boxes; exact depth from the separating-axis oracle (the same one the
//               tests use), where EPA's polytope can reach A - B exactly;
//   sphere-box  spheres against boxes forced through GJK + EPA; exact depth from the closed form
//               in double. A - B is curved here, so EPA can only approach it: this is where the
//               tolerance and the iteration cap trade time for accuracy.
// Each configuration runs the whole query (GJK, then EPA) over its set until enough time has
// passed to measure, and reports ns per query and the relative depth error.
#include "03_epa/bench_epa.h"

#include "03_epa/narrowphase.h"
#include "app/bench_util.h"

// The exact box-box oracle is shared with the test suites (header-only, double precision).
#include "02_gjk/box_oracle.h"
#include "02_gjk/random_pairs.h"
#include "math/random.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <iostream>
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
        pair.poseB.position = Real(random.uniform(0, reach)) * random.unitVector();
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

struct Row {
    std::string set;
    std::string support;
    std::string sweep;
    double tolerance = 0;
    int cap = 0;
    double nsPerQuery = 0;
    double medianError = 0, p95Error = 0, maxError = 0;
    double meanEpaIterations = 0;
    int failures = 0;
};

double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const std::size_t rank = static_cast<std::size_t>(std::ceil(p * double(values.size())));
    return values[std::min(values.size() - 1, rank > 0 ? rank - 1 : 0)];
}

// [ch03-bench]
Row measure(const PairSet& set, const CollideOptions& options, const std::string& sweep, double minimumSeconds) {
    Row row{set.name, options.supportMode == SupportMode::Extents ? "extents" : "vertices", sweep,
            double(options.epa.relativeTolerance), options.epa.maxIterations};
    // Rounds over the whole set until enough time has passed; the fastest round counts, since
    // other processes on the machine can only ever add time to a round.
    std::vector<ContactQuery> results(set.pairs.size());
    double fastestRound = 0;
    int rounds = 0;
    const Stopwatch total;
    do {
        const Stopwatch round;
        for (std::size_t i = 0; i < set.pairs.size(); ++i) {
            const BenchPair& pair = set.pairs[i];
            results[i] = collideShapes(pair.a, pair.poseA, pair.b, pair.poseB, options);
        }
        const double seconds = round.seconds();
        fastestRound = rounds++ == 0 ? seconds : std::min(fastestRound, seconds);
    } while (rounds < 3 || total.seconds() < minimumSeconds);
    row.nsPerQuery = fastestRound * 1e9 / double(set.pairs.size());

    std::vector<double> errors;
    double iterations = 0;
    for (std::size_t i = 0; i < set.pairs.size(); ++i) {
        const ContactQuery& query = results[i];
        if (!query.intersect || !std::isfinite(double(query.depth))) {
            ++row.failures;
            continue;
        }
        errors.push_back(std::abs(double(query.depth) - set.pairs[i].exactDepth) / set.pairs[i].exactDepth);
        iterations += query.epaIterations;
    }
    row.medianError = percentile(errors, 0.5);
    row.p95Error = percentile(errors, 0.95);
    row.maxError = percentile(errors, 1.0);
    row.meanEpaIterations = iterations / double(set.pairs.size());
    return row;
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

}  // namespace

int runEpaBench(const BenchOptions& options) {
    std::ostream& out = options.out ? *options.out : std::cout;
    const int pairCount = options.quick ? 1000 : 5000;
    const double minimumSeconds = options.quick ? 0.01 : 0.2;
    const std::vector<double> tolerances = {1e-1, 3e-2, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7};
    const std::vector<int> caps = {1, 2, 4, 8, 16, 32, 50, 100};
    const PairSet sets[2] = {makeBoxPairs(pairCount), makeSphereBoxPairs(pairCount)};

    std::vector<Row> rows;
    PlotSpec plot{std::string("EPA work-precision, Real = ") + (sizeof(Real) == 4 ? "float" : "double"),
                  "ns per query (GJK + EPA, fastest round)", "95th percentile relative depth error", true, true, {}};
    const auto addSeries = [&](const std::string& title, std::size_t first, bool markersOnly) {
        PlotSeries series{title, {}, {}, markersOnly};
        for (std::size_t i = first; i < rows.size(); ++i) {
            series.x.push_back(rows[i].nsPerQuery);
            series.y.push_back(rows[i].p95Error);
        }
        plot.series.push_back(series);
    };
    for (const PairSet& set : sets) {
        const std::vector<SupportMode> modes = set.name == "boxes" ? std::vector<SupportMode>{SupportMode::Extents, SupportMode::Vertices}
                                                                   : std::vector<SupportMode>{SupportMode::Extents};
        for (SupportMode mode : modes) {
            CollideOptions base;
            base.closedForms = false;  // the point is EPA, even for spheres
            base.supportMode = mode;
            const std::string label = set.name + (mode == SupportMode::Vertices ? ", vertices" : "");
            std::size_t first = rows.size();
            for (double tolerance : tolerances) {
                CollideOptions run = base;
                run.epa.relativeTolerance = Real(tolerance);
                rows.push_back(measure(set, run, "tolerance", minimumSeconds));
            }
            addSeries(label + ": tolerance", first, false);
            if (mode == SupportMode::Vertices) continue;
            first = rows.size();
            for (int cap : caps) {
                CollideOptions run = base;
                run.epa.maxIterations = cap;
                rows.push_back(measure(set, run, "iteration_cap", minimumSeconds));
            }
            addSeries(label + ": iteration cap", first, false);
        }
    }
    // The closed form the sphere-box pairs normally take, for scale.
    const std::size_t closedFormRow = rows.size();
    rows.push_back(measure(sets[1], CollideOptions{}, "closed_form", minimumSeconds));
    rows.back().support = "closed_form";
    addSeries("sphere-box: closed form", closedFormRow, true);

    CsvTable table({"pairs", "support", "sweep", "relative_tolerance", "max_iterations", "ns_per_query",
                    "median_rel_error", "p95_rel_error", "max_rel_error", "mean_epa_iterations", "failures"});
    for (const Row& row : rows) {
        table.addRow({row.set, row.support, row.sweep, formatNumber(row.tolerance), std::to_string(row.cap),
                      formatNumber(row.nsPerQuery), formatNumber(row.medianError), formatNumber(row.p95Error),
                      formatNumber(row.maxError), formatNumber(row.meanEpaIterations, 3), std::to_string(row.failures)});
    }
    out << "EPA bench: " << pairCount << " overlapping pairs per set, Real = " << (sizeof(Real) == 4 ? "float" : "double")
        << ", default tolerance " << formatNumber(double(kEpaDefaultRelativeTolerance)) << ", cap "
        << EpaSettings{}.maxIterations << "\n"
        << table.toText() << peerStatus();
    try {
        if (!options.csvPath.empty()) table.write(options.csvPath);
        if (!options.plotPath.empty()) writeSvgPlot(options.plotPath, plot);
    } catch (const std::exception& error) {
        std::cerr << "error: bench epa: " << error.what() << "\n";
        return 2;
    }
    return 0;
}

}  // namespace stepwise
