// Scene loading: every documented example loads, defaults follow docs/scene-format.md, and
// every kind of bad input is rejected with ONE message at the exact JSON path.

#include "world/scene.h"
#include "support/temp_path.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

using namespace stepwise;

namespace {

std::string readText(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

/// A scene holding the given bodies (a JSON array body without brackets) and extra top-level keys.
std::string sceneWith(const std::string& bodies, const std::string& extra = "") {
    return "{" + extra + (extra.empty() ? "" : ", ") + "\"bodies\": [" + bodies + "]}";
}

const std::string kBall = R"({"name": "ball", "shape": {"sphere": {"radius": 0.5}}})";
const std::string kCrate = R"({"name": "crate", "shape": {"box": {"half_extents": [1, 1, 1]}}, "position": [0, 3, 0]})";

struct BadCase {
    std::string json;
    std::string path;
    std::string message;  // a substring of the message
};

}  // namespace

TEST_CASE("The contract's example scene loads with the values it states", "[common][scene]") {
    // The contract's own example (a ball tied to a box by a distance joint), kept verbatim.
    const World world = loadSceneFile("tests/common/data/contract-scene.json");
    CHECK(world.name == "two-box-stack");
    REQUIRE(world.bodies.size() == 3);
    CHECK(world.settings.solverIterations == 10);
    CHECK(world.settings.dt == Approx(0.0166666667));
    CHECK(world.bodies[0].type == BodyType::Static);
    CHECK(world.bodies[0].motionIndex == -1);
    CHECK(world.bodies[0].shape.halfExtents.isApprox(Vec3(20, 0.5, 20)));
    const Motion* box = world.motionOf(1);
    REQUIRE(box != nullptr);
    CHECK(box->mass == Approx(1.0));
    CHECK(world.bodies[1].material.friction == Approx(0.6));
    const Motion* ball = world.motionOf(2);
    REQUIRE(ball != nullptr);
    // density 1000 kg/m^3 times the volume of a 0.25 m sphere
    CHECK(ball->mass == Approx(1000.0 * 4.0 / 3.0 * 3.14159265358979 * 0.25 * 0.25 * 0.25).epsilon(1e-5));
    CHECK(ball->linearVelocity.isApprox(Vec3(0, -1, 0)));
    REQUIRE(world.joints.size() == 1);
    CHECK(std::string(toString(world.joints[0].type)) == "distance");
    CHECK(world.joints[0].bodyA == 1);
    CHECK(world.joints[0].bodyB == 2);
    CHECK(world.joints[0].localAnchorA.isApprox(Vec3(0, 0.5, 0)));
    REQUIRE(world.joints[0].length.has_value());
    CHECK(*world.joints[0].length == Approx(2.25));
}

TEST_CASE("Every scene in scenes/ and every scene example in the docs loads", "[common][scene]") {
    int loaded = 0;
    for (const auto& entry : std::filesystem::directory_iterator("scenes")) {
        if (entry.path().extension() != ".json") continue;
        INFO(entry.path().string());
        const World world = loadSceneFile(entry.path().string());
        CHECK_FALSE(world.bodies.empty());
        ++loaded;
    }
    CHECK(loaded >= 3);

    // The user docs show scenes in ```json blocks; each one that is a scene must load.
    const std::string page = readText("docs/scene-format.md");
    const std::regex block("```json\\n([\\s\\S]*?)```");
    int examples = 0;
    for (auto it = std::sregex_iterator(page.begin(), page.end(), block); it != std::sregex_iterator(); ++it) {
        const std::string text = (*it)[1].str();
        if (text.find("\"bodies\"") == std::string::npos || text.find("stepwise-report") != std::string::npos) continue;
        INFO(text);
        const World example = loadSceneFromString(text, "docs example");
        // An example named after a shipped scene must describe the same world.
        const std::string shipped = "scenes/" + example.name + ".json";
        if (std::filesystem::exists(shipped)) CHECK(saveSceneToString(example) == saveSceneToString(loadSceneFile(shipped)));
        ++examples;
    }
    CHECK(examples >= 2);
}

TEST_CASE("The extension scene spring-pair builds springs and damping", "[common][scene]") {
    const World world = loadSceneFile("scenes/spring-pair.json");
    REQUIRE(world.springs.size() == 2);
    CHECK(world.springs[0].bodyA == world.findBody("upper"));
    CHECK(world.springs[0].bodyB == -1);  // anchored to a world point
    CHECK(world.springs[0].anchorB.isApprox(Vec3(0, 4, 0)));
    CHECK(world.springs[1].bodyB == world.findBody("lower"));
    CHECK(world.springs[1].stiffness == Approx(150));
    REQUIRE(world.dampings.size() == 1);
    CHECK(world.dampings[0].body == -1);  // every dynamic body
    CHECK(world.dampings[0].linear == Approx(0.05));
}

TEST_CASE("Absent keys take the documented defaults", "[common][scene]") {
    const World world = loadSceneFromString(sceneWith(R"({"shape": {"sphere": {"radius": 0.5}}}, {"type": "static", "shape": {"box": {"half_extents": [1, 1, 1]}}})"));
    const Settings defaults;
    CHECK(world.name == "untitled");
    CHECK(world.settings.gravity == defaults.gravity);
    CHECK(world.settings.dt == defaults.dt);
    CHECK(world.settings.substeps == 1);
    CHECK(world.settings.solverIterations == 10);
    CHECK(world.settings.planIterations);  // solver_iterations "auto"
    CHECK(world.settings.restitutionThreshold == Approx(1.0));
    CHECK(world.settings.gyroscopic == GyroscopicMode::Implicit);
    CHECK(world.settings.solver == SolverKind::GaussSeidel);
    REQUIRE(world.bodies.size() == 2);
    const Body& ball = world.bodies[0];
    CHECK(ball.name == "body0");
    CHECK(world.bodies[1].name == "body1");
    CHECK(ball.type == BodyType::Dynamic);
    CHECK(ball.transform.position == Vec3::Zero());
    CHECK(ball.transform.rotation.coeffs() == Quat::Identity().coeffs());
    CHECK(ball.material.friction == Approx(0.6));
    CHECK(ball.material.restitution == 0);
    CHECK_FALSE(ball.bullet);
    const Motion* motion = world.motionOf(0);
    REQUIRE(motion != nullptr);
    CHECK(motion->mass == Approx(1000.0 * 4.0 / 3.0 * 3.14159265358979 * 0.125).epsilon(1e-5));
    CHECK_FALSE(motion->integrator.has_value());
    CHECK(world.joints.empty());
    CHECK(world.springs.empty());
}

TEST_CASE("An empty object is an empty world, and a file's name defaults to its stem", "[common][scene]") {
    CHECK(loadSceneFromString("{}").bodies.empty());
    const auto path = test::tempPath("stepwise-unnamed-scene.json");
    std::ofstream(path) << sceneWith(kBall);
    CHECK(loadSceneFile(path.string()).name == "stepwise-unnamed-scene");
    std::filesystem::remove(path);
}

TEST_CASE("A nearly unit quaternion is normalised", "[common][scene]") {
    const World world = loadSceneFromString(sceneWith(R"({"shape": {"sphere": {"radius": 1}}, "orientation": [0, 0.3826834, 0, 0.9243880]})"));
    const Quat rotation = world.bodies[0].transform.rotation;
    CHECK(rotation.norm() == Approx(1.0).margin(1e-6));
    CHECK(rotation.y() > 0.38);
    CHECK(rotation.y() < 0.39);
}

TEST_CASE("Extensions: gyroscopic, solver, per-body integrator, springs, damping", "[common][scene]") {
    const World world = loadSceneFromString(sceneWith(kBall + ", " + kCrate,
        R"("settings": {"gyroscopic": "explicit", "solver": "jacobi", "restitution_threshold": 0.5, "integrator": "rk4"},
           "forces": [{"type": "spring", "a": "ball", "b": "crate", "stiffness": 10},
                      {"type": "damping", "body": "crate", "angular": 2}])"));
    CHECK(world.settings.gyroscopic == GyroscopicMode::Explicit);
    CHECK(world.settings.solver == SolverKind::Jacobi);
    CHECK(world.settings.integrator == IntegratorKind::Rk4);
    CHECK(world.settings.restitutionThreshold == Approx(0.5));
    REQUIRE(world.springs.size() == 1);
    CHECK(world.springs[0].restLength == Approx(3.0));  // absent: the anchors' distance at load
    CHECK(world.springs[0].damping == 0);
    REQUIRE(world.dampings.size() == 1);
    CHECK(world.dampings[0].body == 1);
    CHECK(world.dampings[0].linear == 0);
    CHECK(world.dampings[0].angular == Approx(2));

    const World verlet = loadSceneFromString(sceneWith(R"({"shape": {"sphere": {"radius": 1}}, "integrator": "verlet"})"));
    REQUIRE(verlet.motionOf(0)->integrator.has_value());
    CHECK(*verlet.motionOf(0)->integrator == IntegratorKind::Verlet);
}

TEST_CASE("Bad scenes are rejected with the exact path and one clear message", "[common][scene]") {
    const std::string ball = R"("shape": {"sphere": {"radius": 1}})";
    const std::string two = kBall + ", " + kCrate;
    const std::vector<BadCase> cases = {
        {"{\"bodies\": [\n  {\"shape\": }\n]}", "", "malformed JSON in scene at line 2, column 13"},
        {"[1, 2]", "", "a scene must be a JSON object"},
        {R"({"format": "stepwise-report"})", "format", "must be \"stepwise-scene\""},
        {R"({"version": 2})", "version", "unsupported version 2 (this engine reads version 1)"},
        {R"({"name": 5})", "name", "must be a string"},
        {R"({"setings": {}})", "", "unknown key \"setings\"; did you mean \"settings\"? (accepted: format, version"},
        {R"({"bodies": {}})", "bodies", "must be an array"},
        {R"({"settings": {"dt": 0}})", "settings.dt", "must be > 0 and <= 1"},
        {R"({"settings": {"dt": 2}})", "settings.dt", "must be > 0 and <= 1"},
        {R"({"settings": {"substeps": 0}})", "settings.substeps", "must be an integer in [1, 64]"},
        {R"({"settings": {"substeps": 2.5}})", "settings.substeps", "must be an integer"},
        {R"({"settings": {"solver_iterations": 1001}})", "settings.solver_iterations", "must be an integer in [0, 1000]"},
        {R"({"settings": {"baumgarte": 1.5}})", "settings.baumgarte", "must be in [0, 1]"},
        {R"({"settings": {"slop": -0.1}})", "settings.slop", "must be >= 0"},
        {R"({"settings": {"restitution_threshold": -1}})", "settings.restitution_threshold", "must be >= 0"},
        {R"({"settings": {"warm_starting": "yes"}})", "settings.warm_starting", "must be true or false"},
        {R"({"settings": {"integrator": "euler"}})", "settings.integrator", R"(must be one of "semi_implicit_euler", "rk4", "verlet" (got "euler"))"},
        {R"({"settings": {"gyroscopic": "on"}})", "settings.gyroscopic", R"(must be one of "off", "explicit", "implicit")"},
        {R"({"settings": {"solver": "sor"}})", "settings.solver", R"(must be one of "gauss_seidel", "jacobi")"},
        {R"({"settings": {"broadphase": "grid"}})", "settings.broadphase", R"(must be one of "auto", "sap", "brute")"},
        {R"({"settings": {"ccd": true}})", "settings.ccd", "must be a string"},
        {R"({"settings": {"gravity": [0, -9.81]}})", "settings.gravity", "must be an array of 3 numbers [x, y, z]"},
        {R"({"settings": {"gravity": [0, 1e999, 0]}})", "settings.gravity[1]", "must be a finite number"},
        {R"({"settings": {"gravity": [0, "down", 0]}})", "settings.gravity[1]", "must be a number"},
        {R"({"settings": {"timestep": 0.01}})", "settings", "unknown key \"timestep\" (accepted: gravity, dt,"},
        {sceneWith(R"({"name": "a"})"), "bodies[0]", "missing required key \"shape\""},
        {sceneWith(R"({"shape": {}})"), "bodies[0].shape", "must hold exactly one of box, sphere, capsule, convex"},
        {sceneWith(R"({"shape": {"box": {"half_extents": [1, 1, 1]}, "sphere": {"radius": 1}}})"), "bodies[0].shape", "must hold exactly one of"},
        {sceneWith(R"({"shape": {"cone": {"radius": 1}}})"), "bodies[0].shape", "unknown shape kind \"cone\""},
        {sceneWith(kBall + R"(, {"shape": {"box": {"half_extents": [1, 0, 1]}}})"), "bodies[1].shape.box.half_extents[1]", "must be > 0"},
        {sceneWith(R"({"shape": {"box": {"hlaf_extents": [1, 1, 1]}}})"), "bodies[0].shape.box", "unknown key \"hlaf_extents\"; did you mean \"half_extents\"? (accepted: half_extents)"},
        {sceneWith(R"({"shape": {"sphere": {"radius": -1}}})"), "bodies[0].shape.sphere.radius", "must be > 0"},
        {sceneWith(R"({"shape": {"capsule": {"radius": 1, "half_height": 0}}})"), "bodies[0].shape.capsule.half_height", "must be > 0"},
        {sceneWith(R"({"shape": {"convex": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}})"), "bodies[0].shape.convex.vertices", "needs at least 4 points"},
        {sceneWith(R"({"shape": {"convex": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]]}}})"), "bodies[0].shape.convex.vertices", "coplanar"},
        {sceneWith(R"({"shape": {"convex": {"vertices": [[0, 0, 0], [1, 0], [0, 1, 0], [0, 0, 1]]}}})"), "bodies[0].shape.convex.vertices[1]", "must be an array of 3 numbers"},
        {sceneWith("{" + ball + R"(, "type": "rigid"})"), "bodies[0].type", R"(must be one of "static", "kinematic", "dynamic")"},
        {sceneWith("{" + ball + R"(, "mass": 0})"), "bodies[0].mass", "must be > 0"},
        {sceneWith("{" + ball + R"(, "density": -5})"), "bodies[0].density", "must be > 0"},
        {sceneWith("{" + ball + R"(, "mass": 1, "density": 5})"), "bodies[0].density", "give mass or density, not both"},
        {sceneWith("{" + ball + R"(, "type": "static", "mass": 1})"), "bodies[0].mass", "only dynamic bodies have mass (this body is static)"},
        {sceneWith("{" + ball + R"(, "type": "kinematic", "density": 1})"), "bodies[0].density", "only dynamic bodies have mass (this body is kinematic)"},
        {sceneWith("{" + ball + R"(, "type": "static", "velocity": [1, 0, 0]})"), "bodies[0].velocity", "not allowed on a static body"},
        {sceneWith("{" + ball + R"(, "orientation": [0, 0, 0, 2]})"), "bodies[0].orientation", "must be a unit quaternion [x, y, z, w] (its length is 2)"},
        {sceneWith("{" + ball + R"(, "orientation": [0, 0, 1]})"), "bodies[0].orientation", "must be an array of 4 numbers [x, y, z, w]"},
        {sceneWith("{" + ball + R"(, "restitution": 1.5})"), "bodies[0].restitution", "must be in [0, 1]"},
        {sceneWith("{" + ball + R"(, "friction": -0.1})"), "bodies[0].friction", "must be >= 0"},
        {sceneWith("{" + ball + R"(, "integrator": "rk5"})"), "bodies[0].integrator", "must be one of"},
        {sceneWith("{" + ball + R"(, "name": ""})"), "bodies[0].name", "must not be empty"},
        {sceneWith("{" + ball + R"(, "mass": 1, "mass": 2})"), "bodies[0]", "duplicate key \"mass\""},
        {sceneWith("{" + ball + R"(, "position": [0, -1e999, 0]})"), "bodies[0].position[1]", "must be a finite number"},
        {sceneWith("{" + ball + R"(, "posit1on": [0, 0, 0]})"), "bodies[0]", "unknown key \"posit1on\"; did you mean \"position\"?"},
        {sceneWith(kBall + ", " + kBall), "bodies[1].name", "duplicate name \"ball\" (also bodies[0])"},
        {sceneWith("{" + ball + R"(, "name": "body1"}, {)" + ball + "}"), "bodies[1]", "its default name \"body1\" is taken by bodies[0]"},
        {sceneWith(two, R"("joints": [{"type": "distance", "a": "ball", "b": "bal"}])"), "joints[0].b", "unknown body \"bal\" (bodies: ball, crate)"},
        {sceneWith(two, R"("joints": [{"type": "rope", "a": "ball", "b": "crate"}])"), "joints[0].type", "must be one of \"distance\", \"ball_socket\""},
        {sceneWith(two, R"("joints": [{"a": "ball", "b": "crate"}])"), "joints[0]", "missing required key \"type\""},
        {sceneWith(two, R"("joints": [{"type": "distance", "a": "ball", "b": "crate", "axis": [0, 1, 0]}])"), "joints[0]", "unknown key \"axis\" (accepted: type, a, b, anchor_a, anchor_b, collide_connected, length, spring_hertz, spring_damping_ratio)"},
        {sceneWith(two, R"("joints": [{"type": "fixed", "a": "ball", "b": "ball"}])"), "joints[0].b", "a joint needs two different bodies"},
        {sceneWith(two, R"("joints": [{"type": "hinge", "a": "ball", "b": "crate", "limits": [1, 0]}])"), "joints[0].limits", "must be [lo, hi] with lo <= hi"},
        {sceneWith(two, R"("joints": [{"type": "hinge", "a": "ball", "b": "crate", "axis": [0, 0, 0]}])"), "joints[0].axis", "must not be zero"},
        {sceneWith(two, R"("forces": [{"type": "spring", "a": "ball", "b": "crate"}])"), "forces[0]", "missing required key \"stiffness\""},
        {sceneWith(two, R"("forces": [{"type": "spring", "a": "ball", "stiffness": -1}])"), "forces[0].stiffness", "must be >= 0"},
        {sceneWith(two, R"("forces": [{"type": "gravity"}])"), "forces[0].type", "must be one of \"spring\", \"damping\""},
        {sceneWith(two, R"("forces": [{"type": "damping", "body": "nobody"}])"), "forces[0].body", "unknown body \"nobody\""},
        {sceneWith(two, R"("forces": [{"type": "damping", "linear": -1}])"), "forces[0].linear", "must be >= 0"},
    };
    for (const BadCase& bad : cases) {
        INFO("scene: " << bad.json);
        bool threw = false;
        try {
            loadSceneFromString(bad.json);
        } catch (const SceneError& error) {
            threw = true;
            CHECK(error.path() == bad.path);
            CHECK_THAT(error.what(), Catch::Contains(bad.message));
            // what() is "path: message", the form the CLI prints.
            if (!bad.path.empty()) CHECK(std::string(error.what()).rfind(bad.path + ": ", 0) == 0);
        }
        CHECK(threw);
    }
}

TEST_CASE("Numbers that overflow Real are rejected, not turned into infinity", "[common][scene]") {
    // 1e300 is a finite double but not a finite float; either way the load must not hand inf on.
    // Static, so that no mass has to be computed from it.
    const std::string text = sceneWith(R"({"type": "static", "shape": {"sphere": {"radius": 1e300}}})");
    if (std::numeric_limits<Real>::max() < 1e300) {
        try {
            loadSceneFromString(text);
            FAIL("1e300 was accepted as a float radius");
        } catch (const SceneError& error) {
            CHECK(error.path() == "bodies[0].shape.sphere.radius");
            CHECK_THAT(error.what(), Catch::Contains("must be a finite number"));
        }
    } else {
        // A finite double, but far past the size limits (world/scene_limits.h), which reject it.
        try {
            loadSceneFromString(text);
            FAIL("1e300 was accepted as a radius");
        } catch (const SceneError& error) {
            CHECK(error.path() == "bodies[0].shape.sphere.radius");
            CHECK_THAT(error.what(), Catch::Contains("must be between"));
        }
    }
}

TEST_CASE("Sizes whose volume or inertia would overflow are rejected, not turned into NaN", "[common][scene]") {
    // Each number is a finite Real, but r^3 (volume) and m r^2 (inertia) are not: the size limits
    // (world/scene_limits.h) stop it before any mass property is computed.
    const std::string radius = std::numeric_limits<Real>::max() < 1e300 ? "1e30" : "1e200";
    try {
        loadSceneFromString(sceneWith(R"({"shape": {"sphere": {"radius": )" + radius + "}}}"));
        FAIL("an overflowing sphere loaded");
    } catch (const SceneError& error) {
        CHECK(error.path() == "bodies[0].shape.sphere.radius");
        CHECK_THAT(error.what(), Catch::Contains("must be between"));
    }
}

TEST_CASE("Missing files and directories name the path", "[common][scene]") {
    try {
        loadSceneFile("no/such/scene.json");
        FAIL("a missing file loaded");
    } catch (const SceneError& error) {
        CHECK(error.path() == "no/such/scene.json");
        CHECK(std::string(error.what()) == "no/such/scene.json: no such file");
    }
    CHECK_THROWS_AS(loadSceneFile("scenes"), SceneError);
}

TEST_CASE("solver_iterations is \"auto\" or a number, and saves as it was read", "[common][scene]") {
    const World automatic = loadSceneFromString(R"({"settings": {"solver_iterations": "auto"}})");
    CHECK(automatic.settings.planIterations);
    CHECK(automatic.settings.solverIterations == 10);
    // The core format's default, 10, written out, is the default: the format's own example
    // states it, and a scene that states every default runs as one that states none.
    const World stated = loadSceneFromString(R"({"settings": {"solver_iterations": 10}})");
    CHECK(stated.settings.planIterations);
    CHECK(stated.settings.solverIterations == 10);
    // Any other number is the count as it stands; plan_iterations says otherwise for either.
    const World fixed = loadSceneFromString(R"({"settings": {"solver_iterations": 14}})");
    CHECK_FALSE(fixed.settings.planIterations);
    CHECK(fixed.settings.solverIterations == 14);
    const World fixedTen = loadSceneFromString(R"({"settings": {"solver_iterations": 10, "plan_iterations": false}})");
    CHECK_FALSE(fixedTen.settings.planIterations);
    const World plannedFrom14 = loadSceneFromString(R"({"settings": {"plan_iterations": true, "solver_iterations": 14}})");
    CHECK(plannedFrom14.settings.planIterations);
    CHECK(plannedFrom14.settings.solverIterations == 14);
    for (const World* world : {&automatic, &stated, &fixed, &fixedTen, &plannedFrom14}) {
        const World again = loadSceneFromString(saveSceneToString(*world));
        CHECK(again.settings.planIterations == world->settings.planIterations);
        CHECK(again.settings.solverIterations == world->settings.solverIterations);
    }
    CHECK(saveSceneToString(automatic).find(R"("solver_iterations": "auto")") != std::string::npos);
    try {
        loadSceneFromString(R"({"settings": {"solver_iterations": "many"}})");
        FAIL("a word other than auto was accepted");
    } catch (const SceneError& error) {
        CHECK(std::string(error.what()).find("settings.solver_iterations") != std::string::npos);
        CHECK(std::string(error.what()).find(R"(must be "auto" or an integer)") != std::string::npos);
    }
    try {
        loadSceneFromString(R"({"settings": {"plan_iterations": "yes"}})");
        FAIL("a word for plan_iterations was accepted");
    } catch (const SceneError& error) {
        CHECK(std::string(error.what()).find("settings.plan_iterations") != std::string::npos);
    }
}
