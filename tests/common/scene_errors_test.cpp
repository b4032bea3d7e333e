// A bad scene reports all its errors at once (up to a limit), each at its own JSON path, so a
// user fixes a file in one go instead of one run per mistake.

#include "world/scene.h"
#include "support/scene_rejection.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

using namespace stepwise;

namespace {

std::vector<std::string> pathsOf(const SceneError& error) {
    std::vector<std::string> paths;
    for (const SceneIssue& issue : error.issues()) paths.push_back(issue.path);
    return paths;
}

using test::rejectionOf;

}  // namespace

TEST_CASE("Independent mistakes are all reported, in file order", "[common][scene]") {
    const SceneError error = rejectionOf(R"({
      "nmae": "typo",
      "settings": {"dt": 0, "substeps": 100, "integrator": "euler"},
      "bodies": [
        {"name": "ground", "type": "static", "mass": 3, "velocity": [0, 1, 0],
         "shape": {"box": {"half_extents": [20, 0, 20]}}},
        {"name": "ball", "shape": {"sphere": {"radius": -1}}, "position": [0, "a", 0], "friction": -2},
        {"name": "ball", "shape": {"sphere": {"radius": 1}}}
      ],
      "joints": [{"type": "distance", "a": "ball", "b": "nobody", "length": -1}]
    })");
    CHECK(pathsOf(error) == std::vector<std::string>{"", "settings.dt", "settings.substeps", "settings.integrator",
                                                     "bodies[0].shape.box.half_extents[1]", "bodies[0].velocity",
                                                     "bodies[0].mass", "bodies[1].shape.sphere.radius",
                                                     "bodies[1].position[1]", "bodies[1].friction", "bodies[2].name",
                                                     "joints[0].b", "joints[0].length"});
    CHECK_FALSE(error.truncated());
    CHECK(error.path().empty());  // the first issue's path: the unknown top-level key
    CHECK(error.issues()[0].message.find("did you mean \"name\"") != std::string::npos);
    // what() holds one "path: message" line per issue, the form the CLI prints after "error: ".
    const std::string what = error.what();
    CHECK(std::count(what.begin(), what.end(), '\n') == 12);
    CHECK(what.find("\nbodies[1].friction: must be >= 0\n") != std::string::npos);
}

TEST_CASE("A body whose shape is bad still lets joints that name it be checked", "[common][scene]") {
    const SceneError error = rejectionOf(R"({"bodies": [
        {"name": "a", "shape": {"sphere": {"radius": 0}}}, {"name": "b", "shape": {"cube": {}}}],
      "joints": [{"type": "distance", "a": "a", "b": "b", "length": -1}]})");
    // No false "unknown body" for a or b: only the real mistakes.
    CHECK(pathsOf(error) == std::vector<std::string>{"bodies[0].shape.sphere.radius", "bodies[1].shape", "joints[0].length"});
}

TEST_CASE("Past the limit the loader stops and says the list is cut short", "[common][scene]") {
    std::string bodies;
    for (int i = 0; i < 30; ++i) bodies += std::string(i ? ", " : "") + R"({"shape": {"sphere": {"radius": -1}}})";
    const SceneError error = rejectionOf("{\"bodies\": [" + bodies + "]}");
    REQUIRE(error.issues().size() == 20);
    CHECK(error.truncated());
    CHECK(error.issues().back().path == "bodies[19].shape.sphere.radius");
    std::ostringstream printed;
    printSceneError(printed, error);
    CHECK(printed.str().find("error: bodies[0].shape.sphere.radius: must be > 0\n") == 0);
    CHECK(printed.str().find("error: stopped after 20 errors\n") != std::string::npos);
}

TEST_CASE("One mistake is one line, exactly as before", "[common][scene]") {
    const SceneError error = rejectionOf(R"({"bodies": [{"shape": {"sphere": {"radius": 0}}}]})");
    CHECK(error.issues().size() == 1);
    CHECK(std::string(error.what()) == "bodies[0].shape.sphere.radius: must be > 0");
    std::ostringstream printed;
    printSceneError(printed, error);
    CHECK(printed.str() == "error: bodies[0].shape.sphere.radius: must be > 0\n");
}

TEST_CASE("Malformed JSON stops at once: nothing after it can be read", "[common][scene]") {
    const SceneError error = rejectionOf("{\"bodies\": [ }");
    CHECK(error.issues().size() == 1);
    CHECK(std::string(error.what()).rfind("malformed JSON in scene at line 1", 0) == 0);
}
