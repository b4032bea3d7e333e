// Determinism rules that live in the source rather than in the arithmetic: the order of random
// draws, hash-table iteration and addresses. Each test reads the engine's sources (chapters/,
// common/, bench/, apps/: what lays out a scene or steps it) and names the line that breaks its
// rule (docs/reliability.md, "Determinism across machines").
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct SourceFile {
    std::string path;  // relative to the repository
    std::string text;  // with // comments removed
};

std::string withoutLineComments(const std::string& text) {
    std::istringstream in(text);
    std::string line, out;
    while (std::getline(in, line)) {
        const auto comment = line.find("//");
        out += (comment == std::string::npos ? line : line.substr(0, comment)) + "\n";
    }
    return out;
}

// The tests run in the repository's root (catch_discover_tests' WORKING_DIRECTORY).
std::vector<SourceFile> engineSources() {
    std::vector<SourceFile> files;
    for (const char* folder : {"chapters", "common", "bench", "apps"}) {
        REQUIRE(std::filesystem::is_directory(folder));
        for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
            const std::string extension = entry.path().extension().string();
            if (extension != ".cpp" && extension != ".h") continue;
            std::ifstream in(entry.path());
            std::stringstream text;
            text << in.rdbuf();
            files.push_back({entry.path().generic_string(), withoutLineComments(text.str())});
        }
    }
    REQUIRE(files.size() > 100);
    return files;
}

int lineOf(const std::string& text, std::size_t offset) {
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

}  // namespace

TEST_CASE("evaluation order: at most one random draw per statement", "[reliability][source_rules]") {
    // The arguments of one call, or the operands of one operator, are evaluated in an order the
    // compiler chooses (C++17 [expr.call]/8: indeterminately sequenced): GCC builds Vec3(draw(),
    // draw(), draw()) from the right, Clang from the left, and the scene differs. A statement
    // holds at most one draw; a conditional (?:) sequences its condition first, so it may hold two.
    const std::regex draw(R"(\b\w*[Rr]andom\w*\s*\.\s*(uniform|uniformReal|rotation|unitVector)\s*\()");
    std::string broken;
    for (const SourceFile& file : engineSources()) {
        std::size_t start = 0;
        while (start < file.text.size()) {
            const std::size_t end = std::min(file.text.find(';', start), file.text.size());
            const std::string statement = file.text.substr(start, end - start);
            const auto count = std::distance(std::sregex_iterator(statement.begin(), statement.end(), draw), std::sregex_iterator());
            if (count > 1 && statement.find('?') == std::string::npos)
                broken += file.path + ":" + std::to_string(lineOf(file.text, start)) + ":" + statement + "\n";
            start = end + 1;
        }
    }
    INFO(broken);
    CHECK(broken.empty());
}

TEST_CASE("hash iteration order: no unordered container is iterated", "[reliability][source_rules]") {
    // An unordered_map's iteration order depends on the standard library's hash and bucket policy
    // (libstdc++, libc++ and MSVC's differ) and, for pointer keys, on where the allocator put
    // things. The engine keeps such containers for lookup only: each one is listed here with the
    // member that must never be walked.
    const std::set<std::string> allowed = {"chapters/13_worlds/world_manifold.h"};  // meshes: find and emplace
    const std::regex walk(R"(for\s*\([^;)]*:\s*[\w.>-]*meshes\s*\)|meshes\s*\.\s*c?begin\s*\()");
    for (const SourceFile& file : engineSources()) {
        INFO(file.path);
        if (file.text.find("unordered_map") != std::string::npos || file.text.find("unordered_set") != std::string::npos)
            CHECK(allowed.count(file.path) == 1);
        CHECK_FALSE(std::regex_search(file.text, walk));
    }
}

TEST_CASE("pointer order: no ordered container is keyed by address", "[reliability][source_rules]") {
    // A std::map or std::set of pointers iterates in address order, which the allocator and
    // address-space randomisation change from run to run: key by index instead.
    const std::regex byAddress(R"(\b(std::)?(map|set|multimap|multiset)\s*<\s*(const\s+)?[\w:]+\s*\*)");
    for (const SourceFile& file : engineSources()) {
        INFO(file.path);
        CHECK_FALSE(std::regex_search(file.text, byAddress));
    }
}
