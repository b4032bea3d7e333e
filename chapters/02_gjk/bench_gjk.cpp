// `stepwise bench gjk`: what a GJK query costs with each box support map and for hulls, how many
// iterations it takes, and how often each box support map misjudges near-contact pairs.
// The files it writes are listed in gjkBench() (and by `stepwise bench --help`).

#include "02_gjk/bench_gjk.h"

#include "02_gjk/random_pairs.h"
#include "02_gjk/study.h"
#include "app/bench_util.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace stepwise {
namespace {

// One kind of query: shapes and poses for many pairs (shapes are kept so proxies can point at them).
struct QueryCase {
    std::string name;
    std::string support;
    SupportMode mode = SupportMode::Extents;
    std::vector<Shape> shapesA, shapesB;
    std::vector<Transform> posesA, posesB;
};

Shape boxAsHull(const Vec3& halfExtents) {
    std::vector<Vec3> corners;
    for (int corner = 0; corner < 8; ++corner)
        corners.emplace_back((corner & 1) ? halfExtents.x() : -halfExtents.x(), (corner & 2) ? halfExtents.y() : -halfExtents.y(),
                             (corner & 4) ? halfExtents.z() : -halfExtents.z());
    return Shape::convex(corners);
}

// 64 random points on the ellipsoid inscribed in the box: a rounder hull of the same size.
Shape roundHull(Random& random, const Vec3& halfExtents) {
    std::vector<Vec3> points;
    for (int i = 0; i < 64; ++i) points.push_back(random.unitVector().cwiseProduct(halfExtents));
    return Shape::convex(points);
}

std::vector<QueryCase> makeCases(int pairCount) {
    Random random(0x6A6B02u);
    std::vector<BoxPair> pairs;
    for (int i = 0; i < pairCount; ++i) pairs.push_back(randomBoxPair(random, 0.05, 2.0));
    std::vector<Shape> roundHulls;  // hull building is slow-ish; 64 shapes, reused
    for (int i = 0; i < 64; ++i) roundHulls.push_back(roundHull(random, pairs[size_t(i)].halfExtentsA));

    std::vector<QueryCase> cases(5);
    cases[0].name = "box-box", cases[0].support = "extents", cases[0].mode = SupportMode::Extents;
    cases[1].name = "box-box", cases[1].support = "vertices", cases[1].mode = SupportMode::Vertices;
    cases[2].name = "hull8-hull8", cases[2].support = "vertices (hull)";
    cases[3].name = "hull64-hull64", cases[3].support = "vertices (hull)";
    cases[4].name = "sphere-box", cases[4].support = "extents";
    for (size_t i = 0; i < pairs.size(); ++i) {
        const BoxPair& pair = pairs[i];
        for (QueryCase& queryCase : cases) {
            queryCase.posesA.push_back(pair.poseA);
            queryCase.posesB.push_back(pair.poseB);
        }
        for (int c = 0; c < 2; ++c) {
            cases[size_t(c)].shapesA.push_back(Shape::box(pair.halfExtentsA));
            cases[size_t(c)].shapesB.push_back(Shape::box(pair.halfExtentsB));
        }
        cases[2].shapesA.push_back(boxAsHull(pair.halfExtentsA));
        cases[2].shapesB.push_back(boxAsHull(pair.halfExtentsB));
        cases[3].shapesA.push_back(roundHulls[i % 64]);
        cases[3].shapesB.push_back(roundHulls[(i + 17) % 64]);
        cases[4].shapesA.push_back(Shape::sphere(pair.halfExtentsA.mean()));
        cases[4].shapesB.push_back(Shape::box(pair.halfExtentsB));
    }
    return cases;
}

struct CaseMeasurement {
    std::vector<double> intersectNs;      // ns per query, one sample per timed pass
    std::vector<double> distanceNs;
    double meanIterations = 0;
    int maxIterations = 0;
    double meanDistanceIterations = 0;
    double intersectingFraction = 0;
    std::map<int, int> iterationCounts;   // boolean query iterations -> how many queries
    std::map<int, int> distanceIterationCounts;
};

struct CaseProxies {
    std::vector<ConvexProxy> a, b;
};

CaseProxies makeProxies(const QueryCase& queryCase) {
    CaseProxies proxies;
    for (size_t i = 0; i < queryCase.shapesA.size(); ++i) {
        proxies.a.push_back(ConvexProxy{&queryCase.shapesA[i], queryCase.posesA[i], queryCase.mode});
        proxies.b.push_back(ConvexProxy{&queryCase.shapesB[i], queryCase.posesB[i], queryCase.mode});
    }
    return proxies;
}

// Iteration statistics: one pass of each query over the pairs.
void countIterations(const CaseProxies& proxies, CaseMeasurement& measurement) {
    const double count = double(proxies.a.size());
    long iterationSum = 0, distanceIterationSum = 0;
    int intersecting = 0;
    for (size_t i = 0; i < proxies.a.size(); ++i) {
        const GjkResult result = gjkIntersect(proxies.a[i], proxies.b[i]);
        ++measurement.iterationCounts[result.iterations];
        iterationSum += result.iterations;
        measurement.maxIterations = std::max(measurement.maxIterations, result.iterations);
        intersecting += result.intersect ? 1 : 0;
        const int distanceIterations = gjkDistance(proxies.a[i], proxies.b[i]).iterations;
        ++measurement.distanceIterationCounts[distanceIterations];
        distanceIterationSum += distanceIterations;
    }
    measurement.meanIterations = double(iterationSum) / count;
    measurement.meanDistanceIterations = double(distanceIterationSum) / count;
    measurement.intersectingFraction = double(intersecting) / count;
}

// [ch02-bench-timing]
// One timed pass per query kind, recording ns per query. The cases take turns within each
// repetition (measureGjk), so a burst of load elsewhere on a shared machine hits all alike; the
// table reports the median pass with its quartiles, which such bursts cannot move far.
long timeOnce(const CaseProxies& proxies, CaseMeasurement& measurement) {
    const double count = double(proxies.a.size());
    long sink = 0;
    Stopwatch clock;
    for (size_t i = 0; i < proxies.a.size(); ++i) sink += gjkIntersect(proxies.a[i], proxies.b[i]).iterations;
    measurement.intersectNs.push_back(clock.seconds() * 1e9 / count);
    clock.restart();
    for (size_t i = 0; i < proxies.a.size(); ++i) sink += gjkDistance(proxies.a[i], proxies.b[i]).iterations;
    measurement.distanceNs.push_back(clock.seconds() * 1e9 / count);
    return sink;
}
// [ch02-bench-timing]

// "412 (405-420)": a median with its quartiles in whole nanoseconds, for the table figure.
std::string withQuartiles(const Spread& spread) {
    const auto ns = [](double value) { return std::to_string(std::lround(value)); };
    return ns(spread.median) + " (" + ns(spread.lower) + "-" + ns(spread.upper) + ")";
}

/// One query kind's rows: its timing (CSV and figure), its iteration histogram and plot series.
void addCaseRows(const QueryCase& queryCase, const CaseMeasurement& m, int pairCount, CsvTable& timing,
                 CsvTable& timingFigure, CsvTable& iterations, PlotSpec& plot) {
    const Spread intersect = spreadOf(m.intersectNs), distance = spreadOf(m.distanceNs);
    timing.addRow({queryCase.name, queryCase.support, formatNumber(intersect.median, 3), formatNumber(distance.median, 3),
                   formatNumber(m.meanIterations, 3), std::to_string(m.maxIterations),
                   formatNumber(m.meanDistanceIterations, 3), formatNumber(m.intersectingFraction, 3),
                   formatNumber(intersect.lower, 3), formatNumber(intersect.upper, 3),
                   formatNumber(distance.lower, 3), formatNumber(distance.upper, 3)});
    timingFigure.addRow({queryCase.name, queryCase.support, withQuartiles(intersect), withQuartiles(distance),
                         formatNumber(m.meanIterations, 3), std::to_string(m.maxIterations),
                         formatNumber(m.meanDistanceIterations, 3), formatNumber(m.intersectingFraction, 3)});
    PlotSeries series(queryCase.name + " " + queryCase.support);
    for (const auto& [count, queries] : m.iterationCounts) {
        const double fraction = double(queries) / double(pairCount);
        iterations.addRow({queryCase.name, queryCase.support, std::to_string(count), formatNumber(fraction, 4)});
        series.x.push_back(count);
        series.y.push_back(fraction);
    }
    plot.series.push_back(series);
}

/// Near-contact pairs at known gaps. Columns per variant: wrong answers, exits other than
/// intersect/separated, and queries in which the newest support point was dropped (a region the
/// "skip" shortcut never tests).
CsvTable classifyTable(int pairsPerGap) {
    std::vector<std::string> columns = {"gap_m", "pairs", "touching_m"};
    for (const char* what : {"wrong", "unclean", "dropped"})
        for (const char* variant : {"ext", "vert", "ext_sum"}) columns.push_back(std::string(what) + "_" + variant);
    CsvTable classification(columns);
    for (const GapClassification& row : classifyNearContact(0x5EED02u, nearContactGaps(), pairsPerGap)) {
        std::vector<std::string> cells = {formatNumber(row.gap, 2), std::to_string(row.pairs),
                                          formatNumber(row.touchingTolerance, 2)};
        for (const int* counts : {row.wrong, row.nonCleanExits, row.newestDropped})
            for (int variant = 0; variant < kVariantCount; ++variant) cells.push_back(std::to_string(counts[variant]));
        classification.addRow(cells);
    }
    return classification;
}

void measureGjk(BenchRun& run) {
    const int pairCount = run.quick() ? 2000 : 20000;
    const int repetitions = run.quick() ? 15 : 41;
    const int pairsPerGap = run.quick() ? 300 : 3000;

    CsvTable timing({"pair", "support", "ns_intersect", "ns_distance", "mean_iterations", "max_iterations",
                     "mean_distance_iterations", "intersecting", "ns_intersect_q1", "ns_intersect_q3",
                     "ns_distance_q1", "ns_distance_q3"});
    CsvTable timingFigure({"pair", "support", "ns intersect (quartiles)", "ns distance (quartiles)", "mean it",
                           "max it", "mean distance it", "intersecting"});
    CsvTable iterations({"pair", "support", "iterations", "fraction"});
    PlotSpec plot("GJK: support points per query", "support points evaluated (GJK iterations)", "fraction of queries",
                  false, false);
    plot.integerX = true;
    plot.caption = "How many support points GJK evaluates before it answers, over " + std::to_string(pairCount) +
                   " random box-sized pairs per kind: the boolean query of each kind, and for comparison the "
                   "distance query on the box pairs, which cannot stop at the first separating plane.";
    run.progress().stage("building pairs, counting iterations", 1);
    const std::vector<QueryCase> cases = makeCases(pairCount);
    std::vector<CaseProxies> proxies;
    std::vector<CaseMeasurement> measurements(cases.size());
    for (size_t c = 0; c < cases.size(); ++c) {
        proxies.push_back(makeProxies(cases[c]));
        countIterations(proxies[c], measurements[c]);
    }
    run.progress().stage("timing " + std::to_string(cases.size()) + " query kinds, in turns", repetitions);
    long sink = 0;
    for (int repetition = 0; repetition < repetitions; ++repetition) {
        for (size_t c = 0; c < cases.size(); ++c) sink += timeOnce(proxies[c], measurements[c]);
        run.progress().advance();
    }
    if (sink == 42) run.out() << "";  // a use of the results the optimiser cannot prove away
    for (size_t c = 0; c < cases.size(); ++c)
        addCaseRows(cases[c], measurements[c], pairCount, timing, timingFigure, iterations, plot);
    // One distance-query distribution for comparison: it cannot stop at a separating plane.
    PlotSeries distanceSeries("box-box extents, distance");
    for (const auto& [count, queries] : measurements[0].distanceIterationCounts) {
        distanceSeries.x.push_back(count);
        distanceSeries.y.push_back(double(queries) / double(pairCount));
    }
    plot.series.push_back(distanceSeries);
    run.progress().stage("near-contact pairs at known gaps", 1);
    const CsvTable classification = classifyTable(pairsPerGap);
    run.progress().endStage();

    const std::string precision = realTypeName();
    const std::vector<FigureTable> figures = {
        {{"GJK per query: " + std::to_string(pairCount) + " random box-sized pairs, Real = " + precision +
          "; ns: median of " + std::to_string(repetitions) + " timed passes (quartiles in brackets), it = iterations"},
         &timingFigure},
        {{"Near-contact box pairs (gap > 0: wrong = false positive, gap < 0: wrong = false negative)",
          "ext = extents support, vert = vertex loop, ext_sum = extents with the barycentric-sum face point",
          "unclean = exit other than intersect/separated; dropped = newest support point not kept"},
         &classification}};
    for (const FigureTable& figure : figures) {
        for (const std::string& note : figure.notes) run.out() << note << "\n";
        run.out() << figure.table->toText() << "\n";
    }
    run.writeCsv(timing);
    run.writeCsv(iterations, "-iterations");
    run.writeCsv(classification, "-classification");
    run.writePlot(plot);
    run.writeTables(figures, "-table");
}

}  // namespace

BenchEntry gjkBench() {
    return benchEntry(2, measureGjk, R"(
        gjk: GJK: ns per query (box support by extents vs vertices, hulls), iterations,
            near-contact misjudgements
        gjk.csv                 per query kind: ns per query (median, quartiles), iterations
        gjk-iterations.csv      histogram: how many queries needed each iteration count
        gjk-classification.csv  near-contact pairs: wrong answers per gap and variant
        gjk.svg                 plot of the iteration histogram
        gjk-table.svg           both tables as a figure for the chapter page)");
}

}  // namespace stepwise
