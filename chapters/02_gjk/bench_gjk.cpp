// `stepwise bench gjk`: what a GJK query costs with each box support map and for hulls, how many
// iterations it takes, and how often each box support map misjudges near-contact pairs.
// Writes the timing table as CSV (--csv), the iteration histogram as SVG (--plot), and next to
// them <name>-iterations.csv, <name>-classification.csv and <name>-table.svg (both tables as a
// figure for the chapter page).

#include "02_gjk/bench_gjk.h"

#include "02_gjk/random_pairs.h"
#include "02_gjk/study.h"
#include "app/bench_util.h"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

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
    double intersectNs = 1e300;           // best run
    double distanceNs = 1e300;
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
// One timed pass per query kind; keeps the best time per query seen so far. The best of many
// short runs is the estimate least disturbed by other processes on a shared machine, and the
// cases take turns within each repetition (runGjkBench), so a burst of load hits all alike.
long timeOnce(const CaseProxies& proxies, CaseMeasurement& measurement) {
    const double count = double(proxies.a.size());
    long sink = 0;
    Stopwatch clock;
    for (size_t i = 0; i < proxies.a.size(); ++i) sink += gjkIntersect(proxies.a[i], proxies.b[i]).iterations;
    measurement.intersectNs = std::min(measurement.intersectNs, clock.seconds() * 1e9 / count);
    clock.restart();
    for (size_t i = 0; i < proxies.a.size(); ++i) sink += gjkDistance(proxies.a[i], proxies.b[i]).iterations;
    measurement.distanceNs = std::min(measurement.distanceNs, clock.seconds() * 1e9 / count);
    return sink;
}
// [ch02-bench-timing]

std::string withSuffix(const std::string& path, const std::string& extension, const std::string& suffix) {
    const bool hasExtension = path.size() >= extension.size() &&
                              path.compare(path.size() - extension.size(), extension.size(), extension) == 0;
    return (hasExtension ? path.substr(0, path.size() - extension.size()) : path) + suffix + extension;
}

std::string escapeXml(const std::string& text) {
    std::string out;
    for (char c : text) out += c == '<' ? std::string("&lt;") : c == '>' ? std::string("&gt;") : c == '&' ? std::string("&amp;") : std::string(1, c);
    return out;
}

// A titled table for the SVG figure.
struct FigureTable {
    std::vector<std::string> notes;   // lines of text above the table
    const CsvTable* table = nullptr;
};

// The tables as an SVG figure the chapter page can show (Doxygen includes images, not CSV): one
// <text> per cell, columns placed by their widest cell, so no renderer needs a monospace font.
void writeSvgTables(const std::string& path, const std::vector<FigureTable>& figures) {
    const double lineHeight = 17, charWidth = 7.0, margin = 10;
    std::ostringstream body;
    double y = margin + 12, width = 0;
    auto textAt = [&](double x, const std::string& text, bool bold) {
        body << "<text x=\"" << x << "\" y=\"" << y << "\"" << (bold ? " font-weight=\"bold\"" : "") << ">"
             << escapeXml(text) << "</text>\n";
    };
    for (const FigureTable& figure : figures) {
        for (const std::string& note : figure.notes) {
            textAt(margin, note, false);
            width = std::max(width, 2 * margin + charWidth * double(note.size()));
            y += lineHeight;
        }
        const CsvTable& table = *figure.table;
        std::vector<double> columnX;
        double x = margin;
        for (size_t c = 0; c < table.columns().size(); ++c) {
            size_t widest = table.columns()[c].size();
            for (const auto& row : table.rows()) widest = std::max(widest, c < row.size() ? row[c].size() : 0);
            columnX.push_back(x);
            x += charWidth * double(widest + 2);
        }
        width = std::max(width, x + margin);
        for (size_t c = 0; c < table.columns().size(); ++c) textAt(columnX[c], table.columns()[c], true);
        y += lineHeight;
        for (const auto& row : table.rows()) {
            for (size_t c = 0; c < row.size() && c < columnX.size(); ++c) textAt(columnX[c], row[c], false);
            y += lineHeight;
        }
        y += lineHeight;
    }
    std::ofstream file(path, std::ios::binary);
    if (!file) throw std::runtime_error("cannot write '" + path + "'");
    file << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << y
         << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
         << body.str() << "</svg>\n";
}

}  // namespace

int runGjkBench(const BenchOptions& options) {
    std::ostream& out = options.out ? *options.out : std::cout;
    const int pairCount = options.quick ? 2000 : 20000;
    const int repetitions = options.quick ? 15 : 40;
    const int pairsPerGap = options.quick ? 300 : 3000;

    CsvTable timing({"pair", "support", "ns_intersect", "ns_distance", "mean_iterations", "max_iterations",
                     "mean_distance_iterations", "intersecting"});
    CsvTable iterations({"pair", "support", "iterations", "fraction"});
    PlotSpec plot;
    plot.title = "GJK: support points per query (boolean unless marked distance)";
    plot.xLabel = "support points evaluated";
    plot.yLabel = "fraction of queries";
    plot.logX = false;
    plot.logY = false;
    const std::vector<QueryCase> cases = makeCases(pairCount);
    std::vector<CaseProxies> proxies;
    std::vector<CaseMeasurement> measurements(cases.size());
    for (size_t c = 0; c < cases.size(); ++c) {
        proxies.push_back(makeProxies(cases[c]));
        countIterations(proxies[c], measurements[c]);
    }
    // Cases take turns within each repetition, so a burst of load elsewhere hits all alike.
    long sink = 0;
    for (int repetition = 0; repetition < repetitions; ++repetition)
        for (size_t c = 0; c < cases.size(); ++c) sink += timeOnce(proxies[c], measurements[c]);
    if (sink == 42) out << "";  // a use of the results the optimiser cannot prove away
    for (size_t c = 0; c < cases.size(); ++c) {
        const QueryCase& queryCase = cases[c];
        const CaseMeasurement& m = measurements[c];
        timing.addRow({queryCase.name, queryCase.support, formatNumber(m.intersectNs, 3), formatNumber(m.distanceNs, 3),
                       formatNumber(m.meanIterations, 3), std::to_string(m.maxIterations),
                       formatNumber(m.meanDistanceIterations, 3), formatNumber(m.intersectingFraction, 3)});
        PlotSeries series;
        series.title = queryCase.name + " " + queryCase.support;
        for (const auto& [count, queries] : m.iterationCounts) {
            const double fraction = double(queries) / double(pairCount);
            iterations.addRow({queryCase.name, queryCase.support, std::to_string(count), formatNumber(fraction, 4)});
            series.x.push_back(count);
            series.y.push_back(fraction);
        }
        plot.series.push_back(series);
    }
    // One distance-query distribution for comparison: it cannot stop at a separating plane.
    PlotSeries distanceSeries;
    distanceSeries.title = "box-box extents, distance";
    for (const auto& [count, queries] : measurements[0].distanceIterationCounts) {
        distanceSeries.x.push_back(count);
        distanceSeries.y.push_back(double(queries) / double(pairCount));
    }
    plot.series.push_back(distanceSeries);

    // Columns per variant: wrong answers, exits other than intersect/separated, and queries in
    // which the newest support point was dropped (a region the "skip" shortcut never tests).
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

    const std::string precision = sizeof(Real) == 4 ? "float" : "double";
    const std::vector<FigureTable> figures = {
        {{"GJK per query: " + std::to_string(pairCount) + " random box-sized pairs, Real = " + precision + ", best of " +
          std::to_string(repetitions) + " runs"},
         &timing},
        {{"Near-contact box pairs (gap > 0: wrong = false positive, gap < 0: wrong = false negative)",
          "ext = extents support, vert = vertex loop, ext_sum = extents with the barycentric-sum face point",
          "unclean = exit other than intersect/separated; dropped = newest support point not kept"},
         &classification}};
    for (const FigureTable& figure : figures) {
        for (const std::string& note : figure.notes) out << note << "\n";
        out << figure.table->toText() << "\n";
    }

    try {
        if (!options.csvPath.empty()) {
            timing.write(options.csvPath);
            iterations.write(withSuffix(options.csvPath, ".csv", "-iterations"));
            classification.write(withSuffix(options.csvPath, ".csv", "-classification"));
        }
        if (!options.plotPath.empty()) {
            writeSvgPlot(options.plotPath, plot);
            writeSvgTables(withSuffix(options.plotPath, ".svg", "-table"), figures);
        }
    } catch (const std::exception& error) {
        std::cerr << "error: bench gjk: " << error.what() << "\n";
        return 2;  // a path the user gave cannot be written: bad input
    }
    return 0;
}

}  // namespace stepwise
