// The registry's texts: scene notes and bench cards are written as paragraphs in raw strings
// (prose), and a bench's card is parsed into its name, description and files. A card that
// does not parse is a programming error the registry reports with the line.
#include "app/bench_util.h"
#include "app/registry.h"
#include "support/registry_fixture.h"

#include <catch2/catch.hpp>

#include <set>
#include <stdexcept>
#include <string>

using namespace stepwise;

TEST_CASE("prose joins a paragraph's lines with single spaces", "[common][registry]") {
    CHECK(prose(R"(
        one line,
          and the next   one
        )") == "one line, and the next   one");
    CHECK(prose("") == "");
    CHECK(prose("\n  \n") == "");
    CHECK(prose("a\r\nb") == "a b");
}

TEST_CASE("a bench card gives the name, the description and the files", "[common][registry]") {
    const BenchEntry entry = benchEntry(7, nullptr, R"(
        demo: what it measures,
            on two lines
        demo.csv          the table
        demo-dt.svg       the plot against dt,
                          in two lines
        demo.svg          the main plot
        demo-scene-*.svg  one plot per scene)");
    CHECK(entry.name == "demo");
    CHECK(entry.chapter == 7);
    CHECK(entry.description == "what it measures, on two lines");
    REQUIRE(entry.files.size() == 4);
    CHECK(entry.files[0].kind == BenchFile::Kind::Csv);
    CHECK(entry.files[0].suffix.empty());
    CHECK(entry.files[0].what == "the table");
    CHECK(entry.files[1].kind == BenchFile::Kind::Plot);
    CHECK(entry.files[1].suffix == "-dt");
    CHECK(entry.files[1].what == "the plot against dt, in two lines");
    CHECK_FALSE(entry.files[1].oneEach);
    CHECK(entry.files[3].suffix == "-scene");
    CHECK(entry.files[3].oneEach);
    CHECK(benchFilesHelp({entry}).find("out/demo-scene-NAME.svg") != std::string::npos);
}

TEST_CASE("a bench card that does not parse names its line", "[common][registry]") {
    const auto message = [](const std::string& card) {
        try {
            benchEntry(3, nullptr, card);
        } catch (const std::logic_error& error) {
            return std::string(error.what());
        }
        return std::string("(no error)");
    };
    CHECK_THAT(message(""), Catch::Contains("is empty"));
    CHECK_THAT(message("no colon here"), Catch::Contains("line 1 \"no colon here\": the card starts with the bench's name"));
    CHECK_THAT(message("two words: x"), Catch::Contains("the card starts with the bench's name"));
    CHECK_THAT(message("demo: x\nother.csv the table"), Catch::Contains("line 2 \"other.csv the table\""));
    CHECK_THAT(message("demo: x\ndemo_dt.csv the table"), Catch::Contains("a suffix starting with '-'"));
    CHECK_THAT(message("demo: x\ndemo.csv"), Catch::Contains("a file needs a line saying what it holds"));
    CHECK_THAT(message("demo: x\ndemo.csv a\ndemo.csv b"), Catch::Contains("names a file twice"));
}

TEST_CASE("every registered bench and scene reads as one line of prose", "[common][registry]") {
    const Registry& registry = test::chapterRegistry();
    std::set<std::string> names;
    for (const BenchEntry& bench : registry.benches()) {
        INFO(bench.name);
        CHECK(names.insert(bench.name).second);
        CHECK_FALSE(bench.description.empty());
        CHECK(bench.measure);
        CHECK_FALSE(bench.files.empty());
        for (const BenchFile& file : bench.files) CHECK_FALSE(file.what.empty());
    }
    for (const SceneEntry& scene : registry.scenes()) {
        INFO(scene.name);
        CHECK_FALSE(scene.observe.empty());
        CHECK(scene.observe.find('\n') == std::string::npos);
        CHECK(scene.observe.find("  ") == std::string::npos);
    }
}
