#pragma once
// Small tools for `stepwise bench` suites: a wall clock, CSV output and a log-log SVG plot
// (work-precision diagrams), written without any plotting dependency so Windows gets them too.

#include "world/report.h"  // median(), shared with run reports

#include <chrono>
#include <string>
#include <vector>

namespace stepwise {

/// Seconds since construction, from the steady clock.
class Stopwatch {
public:
    Stopwatch() : start_(std::chrono::steady_clock::now()) {}
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    void restart() { start_ = std::chrono::steady_clock::now(); }

private:
    std::chrono::steady_clock::time_point start_;
};

/// Seconds of CPU time this thread used since construction: on a machine shared with other
/// programs, wall-clock time also counts the time they held the core. POSIX only; elsewhere the
/// steady clock (wall time).
class ThreadStopwatch {
public:
    ThreadStopwatch() { restart(); }
    double seconds() const { return now() - start_; }
    void restart() { start_ = now(); }

private:
    static double now();
    double start_ = 0;
};

/// Rows of a table, written as CSV. Cells are strings; numbers go through formatNumber.
class CsvTable {
public:
    explicit CsvTable(std::vector<std::string> columns) : columns_(std::move(columns)) {}
    void addRow(std::vector<std::string> cells) { rows_.push_back(std::move(cells)); }
    const std::vector<std::string>& columns() const { return columns_; }
    const std::vector<std::vector<std::string>>& rows() const { return rows_; }
    /// Throws std::runtime_error naming the path when the file cannot be written.
    void write(const std::string& path) const;
    /// Aligned plain-text table for the terminal.
    std::string toText() const;

private:
    std::vector<std::string> columns_;
    std::vector<std::vector<std::string>> rows_;
};

std::string formatNumber(double value, int significantDigits = 4);

struct PlotSeries {
    std::string title;
    std::vector<double> x;
    std::vector<double> y;
    bool markersOnly = false;   // points without connecting lines
};

struct PlotSpec {
    std::string title;
    std::string xLabel;
    std::string yLabel;
    bool logX = true;
    bool logY = true;

    std::vector<PlotSeries> series;
    bool xCounts = false;       // x ticks as whole numbers with separators ("10,000"): body counts
};

/// Writes an SVG line plot (log axes by default; non-positive values are skipped on log axes).
/// Throws std::runtime_error naming the path when the file cannot be written.
void writeSvgPlot(const std::string& path, const PlotSpec& spec);

}  // namespace stepwise
