// The format page and the program agree: every example in docs/scene-format.md goes through the
// `stepwise` program, and what the page says the program prints is what it prints.
//
//   docs_examples <stepwise exe> <source dir> <scratch dir>
//
// - A scene example (```json with "bodies", or {}) is written to a file and run for 60 frames;
//   it must load and run (exit 0).
// - A query example ("pairs") goes through `stepwise collide`; the ```json block after it
//   ("results") is the documented output: every key it shows must match the program's answer
//   (numbers to 1e-4, since the page rounds them; strings, booleans and counts exactly).
// - The report example ("stepwise-report") must have the keys, in order, and the pipeline of a
//   real report of the scene it names.
// - The recording example ("stepwise-recording") must have the keys, in order, of a recording the
//   program writes.
// - Every query shipped in scenes/queries/ is one of the page's query examples, as it stands.
// - Every "error: ..." line in a ```text block must be printed, as a whole line, by a run of one
//   of the bad files the CLI test runs (tests/cli/cases.txt).
// Prints one line per failed check; exits 1 when any failed.

#include "support/json_keys.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#ifndef _WIN32
#include <sys/wait.h>
#endif

namespace {

using Json = nlohmann::ordered_json;
using stepwise::test::keysOf;
namespace fs = std::filesystem;

int failures = 0;
int checks = 0;

void check(bool ok, const std::string& what) {
    ++checks;
    if (!ok) {
        ++failures;
        std::cout << "FAILED " << what << "\n";
    }
}

std::string readText(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

void writeText(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

struct Run {
    int code = -1;
    std::string out, err;
};

// Runs `stepwise ARGS` in `directory`, capturing both streams through files.
Run runProgram(const std::string& program, const std::string& arguments, const fs::path& directory,
               const fs::path& scratch) {
    const fs::path out = scratch / "stdout.txt", err = scratch / "stderr.txt";
    const std::string command =
        "\"" + program + "\" " + arguments + " > \"" + out.string() + "\" 2> \"" + err.string() + "\"";
    fs::current_path(directory);  // messages name paths relative to it, as the docs show them
    const int status = std::system(command.c_str());
    Run run;
#ifdef _WIN32
    run.code = status;
#else
    run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
#endif
    run.out = readText(out);
    run.err = readText(err);
    return run;
}

// Every key the documented value shows matches the actual one (numbers to `tolerance`).
bool matches(const Json& documented, const Json& actual, double tolerance, std::string& why) {
    if (documented.is_object()) {
        if (!actual.is_object()) return why = "not an object", false;
        for (const auto& item : documented.items()) {
            if (!actual.contains(item.key())) return why = "no key " + item.key(), false;
            if (!matches(item.value(), actual[item.key()], tolerance, why)) return why = item.key() + ": " + why, false;
        }
        return true;
    }
    if (documented.is_array()) {
        if (!actual.is_array() || actual.size() != documented.size()) return why = "array length differs", false;
        for (std::size_t i = 0; i < documented.size(); ++i)
            if (!matches(documented[i], actual[i], tolerance, why)) return why = "[" + std::to_string(i) + "] " + why, false;
        return true;
    }
    if (documented.is_number_float() || (documented.is_number() && actual.is_number_float())) {
        const bool ok = actual.is_number() && std::abs(documented.get<double>() - actual.get<double>()) <= tolerance;
        if (!ok) why = "documented " + documented.dump() + ", program " + actual.dump();
        return ok;
    }
    if (documented != actual) return why = "documented " + documented.dump() + ", program " + actual.dump(), false;
    return true;
}

// The bad files of the CLI test and the lines each makes the program print.
std::vector<std::string> errorLinesOfBadFiles(const std::string& program, const fs::path& cases, const fs::path& scratch) {
    std::set<std::string> files;
    std::istringstream list(readText(cases / "cases.txt"));
    for (std::string line; std::getline(list, line);)
        if (!line.empty() && line[0] != '#' && line.find('|') != std::string::npos) files.insert(line.substr(0, line.find('|')));
    std::vector<std::string> lines;
    for (const std::string& file : files) {
        std::istringstream err(runProgram(program, "run " + file + " --frames 2 --quiet", cases, scratch).err);
        for (std::string line; std::getline(err, line);) lines.push_back(line);
    }
    return lines;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: docs_examples <stepwise> <source dir> <scratch dir>\n";
        return 2;
    }
    const std::string program = fs::absolute(argv[1]).string();
    const fs::path source = fs::absolute(argv[2]), scratch = fs::absolute(argv[3]);
    fs::create_directories(scratch);
    const std::string page = readText(source / "docs" / "scene-format.md");
    check(!page.empty(), "docs/scene-format.md is readable");

    const std::regex block("```(json|text)\\n([\\s\\S]*?)```");
    Json lastResults;  // the program's answer to the latest query example
    std::vector<Json> queryExamples;
    int scenes = 0, queries = 0, outputs = 0, reports = 0, recordings = 0, errorLines = 0;
    std::vector<std::string> badFileLines;
    for (auto it = std::sregex_iterator(page.begin(), page.end(), block); it != std::sregex_iterator(); ++it) {
        const std::string kind = (*it)[1].str(), text = (*it)[2].str();
        if (kind == "text") {
            std::istringstream lines(text);
            for (std::string line; std::getline(lines, line);) {
                if (line.rfind("error: ", 0) != 0) continue;
                if (badFileLines.empty()) badFileLines = errorLinesOfBadFiles(program, source / "tests" / "cli", scratch);
                bool printed = false;
                for (const std::string& actual : badFileLines) printed = printed || actual == line;
                check(printed, "no bad file in tests/cli/cases.txt makes the program print the documented line\n  " + line);
                ++errorLines;
            }
            continue;
        }
        Json example;
        try {
            example = Json::parse(text);
        } catch (const std::exception& error) {
            check(false, std::string("a ```json example does not parse: ") + error.what() + "\n" + text);
            continue;
        }
        const fs::path file = scratch / "example.json";
        writeText(file, text);
        if (example.contains("pairs")) {
            queryExamples.push_back(example);
            const Run run = runProgram(program, "collide --input \"" + file.string() + "\"", scratch, scratch);
            check(run.code == 0, "collide on the query example exits 0 (got " + std::to_string(run.code) + "): " + run.err);
            lastResults = run.code == 0 ? Json::parse(run.out) : Json();
            ++queries;
        } else if (example.contains("results")) {
            std::string why;
            check(!lastResults.is_null() && matches(example, lastResults, 1e-4, why),
                  "the documented collide output differs from the program's: " + why + "\nprogram: " + lastResults.dump());
            ++outputs;
        } else if (example.value("format", "") == "stepwise-report") {
            const std::string scene = example.value("scene", "");
            const fs::path report = scratch / "report.json";
            const Run run = runProgram(program, "run \"" + (source / "scenes" / (scene + ".json")).string() +
                                                    "\" --frames 3 --quiet --report \"" + report.string() + "\"",
                                       scratch, scratch);
            check(run.code == 0, "the report example names a shipped scene that runs: " + scene + " " + run.err);
            if (run.code == 0) {
                const Json real = Json::parse(readText(report));
                check(keysOf(example) == keysOf(real), "the report example has a real report's keys in order");
                check(keysOf(example["timing_ms"]["stages"]) == keysOf(real["timing_ms"]["stages"]),
                      "the report example's stage timings are those of a real run: " + real["timing_ms"]["stages"].dump());
                check(example["pipeline"] == real["pipeline"],
                      "the report example's pipeline is a real run's: " + real["pipeline"].dump());
                check(keysOf(example["energy"]) == keysOf(real["energy"]), "the report example's energy keys");
            }
            ++reports;
        } else if (example.value("format", "") == "stepwise-recording") {
            // Its hashes hold one build's bits, so it is not replayed: it must have a real
            // recording's keys in order, and so must its start states and edits.
            const fs::path recording = scratch / "recording.json";
            const Run run = runProgram(program, "record debug-drop --frames 3 --output \"" + recording.string() + "\"",
                                       scratch, scratch);
            check(run.code == 0, "stepwise record runs for the recording example: " + run.err);
            if (run.code == 0) {
                const Json real = Json::parse(readText(recording));
                check(keysOf(example) == keysOf(real), "the recording example has a real recording's keys in order");
                check(keysOf(example["start"][0]) == keysOf(real["start"][0]), "the recording example's start state keys");
            }
            ++recordings;
        } else {
            const Run run = runProgram(program, "run \"" + file.string() + "\" --frames 60 --quiet", scratch, scratch);
            check(run.code == 0, "the scene example runs (exit " + std::to_string(run.code) + "): " + run.err + "\n" + text);
            ++scenes;
        }
    }
    for (const auto& entry : fs::directory_iterator(source / "scenes" / "queries")) {
        const Json shipped = Json::parse(readText(entry.path()));
        bool shown = false;
        for (const Json& example : queryExamples) shown = shown || example == shipped;
        check(shown, "the page shows the shipped query " + entry.path().filename().string() + " as it stands");
    }
    // The page shows at least its shipped scenes, one query with its output, a report and errors.
    check(scenes >= 3 && queries >= 1 && outputs >= 1 && reports == 1 && recordings == 1 && errorLines >= 10,
          "examples found: " + std::to_string(scenes) + " scenes, " + std::to_string(queries) + " queries, " +
              std::to_string(outputs) + " outputs, " + std::to_string(reports) + " reports, " +
              std::to_string(recordings) + " recordings, " +
              std::to_string(errorLines) + " error lines");
    std::cout << "docs examples: " << checks - failures << " passed, " << failures << " failed\n";
    return failures ? 1 : 0;
}
