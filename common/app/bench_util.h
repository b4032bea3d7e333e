#pragma once
// The frame every `stepwise bench` suite runs in (one place, so the suites only measure):
// options, output files checked before minutes of measuring, progress on a terminal, CSV and
// SVG writing, and the list of files written at the end. Plus the small tools the suites share:
// a wall clock, a CSV table, and robust statistics for timings on a shared machine.

#include "app/registry.h"
#include "app/svg_plot.h"
#include "world/report.h"  // median() and percentile(), shared with run reports

#include <chrono>
#include <functional>
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

/// "float" or "double": what Real is in this build, for table and plot titles.
inline const char* realTypeName() { return sizeof(Real) == 4 ? "float" : "double"; }

/// A timing as the median of repeated runs with its quartiles: the median ignores the runs a
/// burst of load elsewhere slowed down, and the quartiles show how far the runs scatter, so a
/// plot can show whether a difference is larger than the noise.
struct Spread {
    double median = 0, lower = 0, upper = 0;  // lower and upper quartile
};
Spread spreadOf(const std::vector<double>& samples);

/// "out/x.svg" + "-dt" -> "out/x-dt.svg"; a path without the extension gets suffix + extension.
std::string withSuffix(const std::string& path, const std::string& suffix, const std::string& extension);

/// A bench's progress on a terminal, one line per stage with a bar redrawn in place:
///   bench epa  tolerance sweep, boxes   [##########..........]  4/8  0.9 s
/// Silent when disabled (standard error is not a terminal, or --quiet).
class BenchProgress {
public:
    BenchProgress(std::string suite, bool enabled) : suite_(std::move(suite)), enabled_(enabled) {}
    BenchProgress(const BenchProgress&) = delete;
    BenchProgress& operator=(const BenchProgress&) = delete;
    ~BenchProgress() { endStage(); }
    /// Ends the current stage, starts one of `total` steps.
    void stage(const std::string& name, long total);
    void advance(long steps = 1);
    void endStage();
    bool enabled() const { return enabled_; }

private:
    void draw();
    std::string suite_;
    bool enabled_;
    bool open_ = false;
    std::string name_;
    long done_ = 0, total_ = 0;
    Stopwatch clock_;
    double lastDraw_ = -1;
};

/// What a suite gets while it runs: its options, its output stream, its progress line, and
/// writers for the files it declared in its BenchEntry (writing an undeclared file is a bug).
class BenchRun {
public:
    BenchRun(const BenchEntry& entry, const BenchOptions& options);
    std::ostream& out() const;
    bool quick() const { return options_.quick; }
    const BenchOptions& options() const { return options_; }
    BenchProgress& progress() { return progress_; }

    /// Each writes the declared file with this suffix when its option (--csv, --plot) was given.
    /// Throws std::runtime_error naming the path when the file cannot be written.
    void writeCsv(const CsvTable& table, const std::string& suffix = "");
    void writePlot(const PlotSpec& plot, const std::string& suffix = "");
    /// Writes one of the files of a oneEach entry: suffix "-scene", item "ramp" -> x-scene-ramp.svg.
    void writePlotFor(const PlotSpec& plot, const std::string& suffix, const std::string& item);
    void writeTables(const std::vector<FigureTable>& figures, const std::string& suffix);

    /// The file `file` goes to with these options, or "" when its option was not given.
    std::string pathOf(const BenchFile& file) const;
    const std::vector<std::pair<std::string, const BenchFile*>>& written() const { return written_; }
    const BenchEntry& entry() const { return entry_; }

private:
    const BenchFile& declared(BenchFile::Kind kind, const std::string& suffix) const;
    void record(const BenchFile& file, const std::string& path);

    const BenchEntry& entry_;
    const BenchOptions& options_;
    BenchProgress progress_;
    std::vector<std::pair<std::string, const BenchFile*>> written_;
};

/// Runs a suite (entry.measure) in the shared frame: checks every output path can be written
/// before measuring (else "error: bench NAME: cannot write 'PATH'", exit 2), measures, checks it
/// wrote every file it declares, and lists the files written (unless --quiet). Returns the
/// exit code: 0, 2 for an output that cannot be written.
int runBench(const BenchEntry& entry, const BenchOptions& options);

/// The `--help` text naming the files each suite writes, e.g. for `--csv out/x.csv`.
std::string benchFilesHelp(const std::vector<BenchEntry>& benches);

}  // namespace stepwise
