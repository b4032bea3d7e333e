#include "app/bench_util.h"

#include "app/runner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#if defined(__unix__) || defined(__APPLE__)
#include <time.h>
#endif

namespace stepwise {

double ThreadStopwatch::now() {
#if defined(CLOCK_THREAD_CPUTIME_ID)
    timespec time{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &time);
    return static_cast<double>(time.tv_sec) + 1e-9 * static_cast<double>(time.tv_nsec);
#else
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
#endif
}

std::string formatNumber(double value, int significantDigits) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", significantDigits, value);
    return buffer;
}

void CsvTable::write(const std::string& path) const {
    std::ofstream file(path, std::ios::binary);
    if (!file) throw std::runtime_error("cannot write '" + path + "'");
    auto writeRow = [&](const std::vector<std::string>& cells) {
        for (size_t i = 0; i < cells.size(); ++i) file << (i ? "," : "") << cells[i];
        file << "\n";
    };
    writeRow(columns_);
    for (const auto& row : rows_) writeRow(row);
    if (!file) throw std::runtime_error("cannot write '" + path + "'");
}

std::string CsvTable::toText() const {
    std::vector<size_t> widths(columns_.size(), 0);
    for (size_t i = 0; i < columns_.size(); ++i) widths[i] = columns_[i].size();
    for (const auto& row : rows_)
        for (size_t i = 0; i < row.size() && i < widths.size(); ++i) widths[i] = std::max(widths[i], row[i].size());
    std::ostringstream out;
    auto writeRow = [&](const std::vector<std::string>& cells) {
        for (size_t i = 0; i < cells.size() && i < widths.size(); ++i)
            out << cells[i] << std::string(widths[i] - cells[i].size() + 2, ' ');
        out << "\n";
    };
    writeRow(columns_);
    for (const auto& row : rows_) writeRow(row);
    return out.str();
}

Spread spreadOf(const std::vector<double>& samples) {
    return Spread{median(samples), percentile(samples, 0.25), percentile(samples, 0.75)};
}

std::string withSuffix(const std::string& path, const std::string& suffix, const std::string& extension) {
    const bool hasExtension = path.size() >= extension.size() &&
                              path.compare(path.size() - extension.size(), extension.size(), extension) == 0;
    return (hasExtension ? path.substr(0, path.size() - extension.size()) : path) + suffix + extension;
}

// --- progress ---------------------------------------------------------------------------------

void BenchProgress::stage(const std::string& name, long total) {
    endStage();
    name_ = name;
    done_ = 0;
    total_ = std::max(1L, total);
    open_ = true;
    clock_.restart();
    lastDraw_ = -1;
    draw();
}

void BenchProgress::advance(long steps) {
    if (!open_) return;
    done_ = std::min(total_, done_ + steps);
    // Redraw at most ten times a second: a terminal is slow next to a fast loop.
    if (clock_.seconds() - lastDraw_ >= 0.1 || done_ == total_) draw();
}

void BenchProgress::endStage() {
    if (!open_) return;
    done_ = total_;
    draw();
    if (enabled_) std::fputc('\n', stderr);
    open_ = false;
}

void BenchProgress::draw() {
    lastDraw_ = clock_.seconds();
    if (!enabled_) return;
    constexpr int kBarWidth = 20;
    const int filled = int(kBarWidth * done_ / total_);
    std::fprintf(stderr, "\r  bench %s  %-34s [%s%s] %ld/%ld  %.1f s", suite_.c_str(), name_.c_str(),
                 std::string(size_t(filled), '#').c_str(), std::string(size_t(kBarWidth - filled), '.').c_str(), done_,
                 total_, lastDraw_);
    std::fflush(stderr);
}

// --- the frame --------------------------------------------------------------------------------

BenchRun::BenchRun(const BenchEntry& entry, const BenchOptions& options)
    : entry_(entry), options_(options),
      progress_(entry.name, !options.quiet && stderrIsTerminal()) {}

std::ostream& BenchRun::out() const { return options_.out ? *options_.out : std::cout; }

std::string BenchRun::pathOf(const BenchFile& file) const {
    const bool csv = file.kind == BenchFile::Kind::Csv;
    const std::string& base = csv ? options_.csvPath : options_.plotPath;
    if (base.empty()) return "";
    return file.suffix.empty() ? base : withSuffix(base, file.suffix, csv ? ".csv" : ".svg");
}

const BenchFile& BenchRun::declared(BenchFile::Kind kind, const std::string& suffix) const {
    for (const BenchFile& file : entry_.files)
        if (file.kind == kind && file.suffix == suffix) return file;
    throw std::logic_error("bench " + entry_.name + " writes a file it does not declare (suffix \"" + suffix + "\")");
}

void BenchRun::record(const BenchFile& file, const std::string& path) { written_.emplace_back(path, &file); }

void BenchRun::writeCsv(const CsvTable& table, const std::string& suffix) {
    const BenchFile& file = declared(BenchFile::Kind::Csv, suffix);
    const std::string path = pathOf(file);
    if (path.empty()) return;
    table.write(path);
    record(file, path);
}

void BenchRun::writePlot(const PlotSpec& plot, const std::string& suffix) {
    const BenchFile& file = declared(BenchFile::Kind::Plot, suffix);
    const std::string path = pathOf(file);
    if (path.empty()) return;
    writeSvgPlot(path, plot);
    record(file, path);
}

void BenchRun::writePlotFor(const PlotSpec& plot, const std::string& suffix, const std::string& item) {
    const BenchFile& file = declared(BenchFile::Kind::Plot, suffix);
    if (!file.oneEach) throw std::logic_error("bench " + entry_.name + ": \"" + suffix + "\" is not a file per item");
    if (options_.plotPath.empty()) return;
    const std::string path = withSuffix(options_.plotPath, suffix + "-" + item, ".svg");
    writeSvgPlot(path, plot);
    record(file, path);
}

void BenchRun::writeTables(const std::vector<FigureTable>& figures, const std::string& suffix) {
    const BenchFile& file = declared(BenchFile::Kind::Plot, suffix);
    const std::string path = pathOf(file);
    if (path.empty()) return;
    writeSvgTables(path, figures);
    record(file, path);
}

int runBench(const BenchEntry& entry, const BenchOptions& options) {
    // A part of a run prints its tables; the files hold whole runs only.
    if (!options.only.empty() && (!options.csvPath.empty() || !options.plotPath.empty())) {
        std::cerr << "error: bench " << entry.name << " --only prints the chosen scenes' tables and writes no files: "
                  << "drop --csv and --plot, or --only for a whole run\n";
        return 2;
    }
    BenchRun run(entry, options);
    // Before minutes of measuring: every output can be written. Opening for appending creates
    // a missing file and leaves an existing one as it is until the suite overwrites it.
    for (const BenchFile& file : entry.files) {
        const std::string path = run.pathOf(file);
        if (file.oneEach) continue;  // named only while the suite runs; their folder is the plot's
        if (!path.empty() && !std::ofstream(path, std::ios::binary | std::ios::app)) {
            std::cerr << "error: bench " << entry.name << ": cannot write '" << path << "'\n";
            return 2;
        }
    }
    try {
        entry.measure(run);
    } catch (const std::runtime_error& error) {
        run.progress().endStage();
        std::cerr << "error: bench " << entry.name << ": " << error.what() << "\n";
        return 2;
    }
    run.progress().endStage();
    // A declared file the suite did not write would make --help lie.
    for (const BenchFile& file : entry.files) {
        if (file.oneEach) continue;  // as many as the run has items, possibly none
        const std::string path = run.pathOf(file);
        const auto isPath = [&](const auto& item) { return item.first == path; };
        if (!path.empty() && std::none_of(run.written().begin(), run.written().end(), isPath))
            throw std::logic_error("bench " + entry.name + " declares '" + path + "' but did not write it");
    }
    if (!options.quiet && !run.written().empty()) {
        size_t width = 0;
        for (const auto& [path, file] : run.written()) width = std::max(width, path.size());
        run.out() << "\nfiles written:\n";
        for (const auto& [path, file] : run.written())
            run.out() << "  " << path << std::string(width + 2 - path.size(), ' ') << file->what << "\n";
    }
    return 0;
}

std::string benchFilesHelp(const std::vector<BenchEntry>& benches) {
    std::ostringstream text;
    text << "Files each suite writes, given --csv out/NAME.csv --plot out/NAME.svg:\n";
    for (const BenchEntry& entry : benches) {
        text << "  " << entry.name << "\n";
        for (const BenchFile& file : entry.files) {
            const bool csv = file.kind == BenchFile::Kind::Csv;
            const std::string path = "out/" + entry.name + file.suffix + (file.oneEach ? "-NAME" : "") + (csv ? ".csv" : ".svg");
            text << "    " << path << std::string(path.size() < 32 ? 32 - path.size() : 1, ' ') << file.what << "\n";
        }
    }
    return text.str();
}

}  // namespace stepwise
