#pragma once
// A bench run in quick mode into the temporary directory, for the chapters' bench tests: every
// file its entry names (BenchEntry::files) checked and removed, its table read back, what it
// printed. A chapter's test then checks only what its bench measures.
//   const test::QuickBench run = test::runQuickBench(broadphaseBench(), "ch05_bench_test");
//   REQUIRE(run.exitCode == 0);
//   CHECK(run.header == "part,density,...");
//   for (const std::vector<std::string>& cells : run.rows) ...

#include "app/bench_util.h"
#include "app/registry.h"
#include "temp_path.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace stepwise::test {

struct QuickBench {
    int exitCode = -1;
    std::string header;                          // the table's first line
    std::vector<std::string> lines;              // the other lines
    std::vector<std::vector<std::string>> rows;  // the same, split at commas
    std::string printed;                         // what the bench wrote to its stream
    std::vector<std::string> missingFiles;       // files the entry names that were not written
    std::string plotText;                        // the main plot's SVG, empty when it has none
};

inline std::vector<std::string> splitCells(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream stream(line);
    for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
    return cells;
}

inline std::string readWholeFile(const std::string& path) {
    std::ifstream file(path);
    return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

/// With STEPWISE_BENCH_RUNS set (the float build's ctest, docs/CMakeLists.txt), a copy of every
/// file the run wrote, named as `stepwise bench NAME --quick --csv bench-NAME.csv --plot
/// bench-NAME.svg` names them, and what it printed as bench-NAME.txt, written last: docs.build
/// takes them instead of running the same quick bench again.
inline void keepForDocs(const BenchEntry& entry, const std::filesystem::path& directory, const std::string& stem,
                        const std::string& printed) {
    const char* keep = std::getenv("STEPWISE_BENCH_RUNS");
    if (!keep || !*keep) return;
    const std::filesystem::path into(keep);
    std::filesystem::create_directories(into);
    const std::string name = "bench-" + entry.name;
    for (const std::filesystem::directory_entry& written : std::filesystem::directory_iterator(directory)) {
        const std::string file = written.path().filename().string();
        const bool main = file == stem + ".csv" || file == stem + ".svg";
        if (main || file.rfind(stem + "-", 0) == 0)
            std::filesystem::copy_file(written.path(), into / (name + file.substr(stem.size())),
                                       std::filesystem::copy_options::overwrite_existing);
    }
    std::ofstream(into / (name + ".txt")) << printed;
}

/// Runs `entry` quick, with its CSV and (when it names one) its plot in the temporary directory
/// under the name `stem`; reads them back and removes every file the entry names. Checks what
/// every bench promises: exit code 0, every declared file written, and the table's first line
/// (when `expectedHeader` is given).
inline QuickBench runQuickBench(const BenchEntry& entry, const std::string& stem, const std::string& expectedHeader = "") {
    const std::filesystem::path& directory = tempFolder();
    const auto pathOf = [&](const BenchFile& file) {
        return (directory / (stem + file.suffix + (file.kind == BenchFile::Kind::Csv ? ".csv" : ".svg"))).string();
    };
    std::ostringstream out;
    BenchOptions options;
    options.quick = true;
    options.quiet = true;
    options.out = &out;
    for (const BenchFile& file : entry.files) {
        if (!file.suffix.empty() || file.oneEach) continue;
        (file.kind == BenchFile::Kind::Csv ? options.csvPath : options.plotPath) = pathOf(file);
    }
    QuickBench run;
    run.exitCode = runBench(entry, options);
    run.printed = out.str();
    std::ifstream table(options.csvPath);
    std::getline(table, run.header);
    for (std::string line; std::getline(table, line);) {
        run.lines.push_back(line);
        run.rows.push_back(splitCells(line));
    }
    if (!options.plotPath.empty()) run.plotText = readWholeFile(options.plotPath);
    if (run.exitCode == 0) keepForDocs(entry, directory, stem, run.printed);
    for (const BenchFile& file : entry.files) {
        if (file.oneEach) continue;  // removed below, from the list of files written
        const std::string path = pathOf(file);
        if (!std::ifstream(path).good()) run.missingFiles.push_back(path);
        std::remove(path.c_str());
    }
    for (const std::filesystem::directory_entry& written : std::filesystem::directory_iterator(directory))
        if (written.path().filename().string().rfind(stem + "-", 0) == 0) std::filesystem::remove(written.path());
    INFO("bench " << entry.name << " printed:\n" << run.printed);
    REQUIRE(run.exitCode == 0);
    CHECK(run.missingFiles.empty());
    if (!expectedHeader.empty()) CHECK(run.header == expectedHeader);
    return run;
}

/// Whether the bench refuses a CSV path it cannot write with exit code 2, as the CLI promises.
inline bool rejectsUnwritablePath(const BenchEntry& entry) {
    std::ostringstream out;
    BenchOptions options;
    options.quick = true;
    options.quiet = true;
    options.out = &out;
    options.csvPath = "/nonexistent-dir/x.csv";
    return runBench(entry, options) == 2;
}

}  // namespace stepwise::test
