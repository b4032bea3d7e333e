#pragma once
// Plots and tables as SVG for `stepwise bench` suites and the course pages, written without any
// plotting dependency so every platform gets the same pictures.

#include <string>
#include <utility>
#include <vector>

namespace stepwise {

class CsvTable;

struct PlotSeries {
    PlotSeries() = default;
    explicit PlotSeries(std::string title_, bool markersOnly_ = false)
        : title(std::move(title_)), markersOnly(markersOnly_) {}

    std::string title;
    std::vector<double> x;
    std::vector<double> y;
    bool markersOnly = false;   // points without connecting lines
    bool lineOnly = false;      // a line without markers (dense series, such as one point a frame)
    bool dashed = false;        // a reference line (a limit, a setting) rather than a measurement
    // Optional spread of each point (same length as x, or empty): drawn as whiskers, e.g. the
    // quartiles of repeated timings around their median.
    std::vector<double> xLow, xHigh;
    std::vector<double> yLow, yHigh;
};

struct PlotSpec {
    PlotSpec() = default;
    PlotSpec(std::string title_, std::string xLabel_, std::string yLabel_, bool logX_ = true, bool logY_ = true)
        : title(std::move(title_)), xLabel(std::move(xLabel_)), yLabel(std::move(yLabel_)), logX(logX_), logY(logY_) {}

    std::string title;
    std::string xLabel;
    std::string yLabel;
    bool logX = true;
    bool logY = true;
    bool integerX = false;      // a count axis: ticks on whole numbers only
    bool integerY = false;
    /// What the plot shows and how it was measured, written under it (wrapped); every bench
    /// plot has one, so the SVG file explains itself outside the course pages too.
    std::string caption;
    std::vector<PlotSeries> series;
};

/// Writes an SVG line plot (log axes by default; non-positive values are skipped on log axes).
/// Linear axes get ticks at 1, 2 or 5 times a power of ten; count axes only whole numbers.
/// Throws std::runtime_error naming the path when the file cannot be written.
void writeSvgPlot(const std::string& path, const PlotSpec& spec);

/// A table for an SVG figure, with lines of text above it.
struct FigureTable {
    std::vector<std::string> notes;
    const CsvTable* table = nullptr;
};

/// The tables as one SVG figure a page can show (Doxygen includes images, not CSV): one <text>
/// per cell, columns placed by their widest cell, so no renderer needs a monospace font.
/// Throws std::runtime_error naming the path when the file cannot be written.
void writeSvgTables(const std::string& path, const std::vector<FigureTable>& figures);

/// The tick values of a linear axis over [low, high]: multiples of 1, 2 or 5 times a power of
/// ten (whole numbers only when `integer`), about five of them, covering the range.
std::vector<double> linearTicks(double low, double high, bool integer);

}  // namespace stepwise
