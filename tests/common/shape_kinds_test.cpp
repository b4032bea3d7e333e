// The shapes of chapter 13 as data: cylinders, compounds, meshes and height fields load from scene
// files (inline or OBJ), save back, refuse bad input at its JSON path, and have the mass
// properties and boxes of their closed forms.
#include "world/scene.h"
#include "support/temp_path.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

using namespace stepwise;

namespace {

std::string shapeKindsScene(const std::string& bodies) { return "{\"bodies\": [" + bodies + "]}"; }

void shapeKindsCheckRejected(const std::string& json, const std::string& path, const std::string& message) {
    INFO(json);
    try {
        loadSceneFromString(json);
        FAIL("accepted");
    } catch (const SceneError& error) {
        CHECK(error.path() == path);
        CHECK_THAT(error.what(), Catch::Contains(message));
    }
}

Real shapeKindsRelative(Real a, Real b) { return std::abs(a - b) / std::max(std::abs(b), Real(1e-30)); }

}  // namespace

TEST_CASE("a cylinder has the closed-form mass, inertia and box", "[common][shapes]") {
    const Shape cylinder = Shape::cylinder(Real(0.5), Real(1));
    const MassProperties props = computeMassProperties(cylinder, 1000);
    const Real mass = 1000 * kPi * Real(0.25) * 2;
    CHECK(shapeKindsRelative(props.mass, mass) < Real(1e-6));
    CHECK(shapeKindsRelative(props.inertia(1, 1), mass * Real(0.25) / 2) < Real(1e-6));
    CHECK(shapeKindsRelative(props.inertia(0, 0), mass * (3 * Real(0.25) + 4) / 12) < Real(1e-6));
    // Turned 30 degrees about z: the box is the rim's and the caps' extreme points, sampled.
    Transform pose;
    pose.position = Vec3(1, 2, 3);
    pose.rotation = Quat(Eigen::AngleAxis<Real>(Real(0.5235988), Vec3::UnitZ()));
    const Aabb box = computeAabb(cylinder, pose);
    Aabb sampled;
    for (int i = 0; i < 3600; ++i) {
        const Real angle = Real(2) * kPi * Real(i) / Real(3600);
        for (Real y : {Real(-1), Real(1)}) sampled.grow(pose.apply(Vec3(Real(0.5) * std::cos(angle), y, Real(0.5) * std::sin(angle))));
    }
    CHECK((box.min - sampled.min).cwiseAbs().maxCoeff() < Real(1e-5));
    CHECK((box.max - sampled.max).cwiseAbs().maxCoeff() < Real(1e-5));
}

TEST_CASE("a compound's mass properties are its children's by the parallel-axis theorem", "[common][shapes]") {
    // Two unit cubes side by side are one 2 x 1 x 1 box, exactly.
    CompoundChild left{Shape::box(Vec3::Constant(Real(0.5))), Transform{}};
    CompoundChild right = left;
    left.transform.position = Vec3(Real(-0.5), 0, 0);
    right.transform.position = Vec3(Real(0.5), 0, 0);
    const MassProperties pair = computeMassProperties(Shape::compoundOf({left, right}), 500);
    const MassProperties whole = computeMassProperties(Shape::box(Vec3(1, Real(0.5), Real(0.5))), 500);
    CHECK(shapeKindsRelative(pair.mass, whole.mass) < Real(1e-6));
    CHECK(pair.localCenter.norm() < Real(1e-6));
    CHECK((pair.inertia - whole.inertia).cwiseAbs().maxCoeff() < Real(1e-5) * whole.inertia.norm());
    // A child turned a quarter about y is the box with x and z swapped; moved off the origin, the
    // centre of mass follows it.
    CompoundChild turned{Shape::box(Vec3(1, Real(0.25), Real(0.5))), Transform{}};
    turned.transform.rotation = Quat(Eigen::AngleAxis<Real>(kPi / 2, Vec3::UnitY()));
    turned.transform.position = Vec3(0, 2, 0);
    const MassProperties one = computeMassProperties(Shape::compoundOf({turned}), 1000);
    const MassProperties swapped = computeMassProperties(Shape::box(Vec3(Real(0.5), Real(0.25), 1)), 1000);
    CHECK((one.localCenter - Vec3(0, 2, 0)).norm() < Real(1e-6));
    CHECK((one.inertia - swapped.inertia).cwiseAbs().maxCoeff() < Real(1e-5) * swapped.inertia.norm());
}

TEST_CASE("the new shape kinds load, save and load again", "[common][shapes]") {
    const std::string json = shapeKindsScene(
        R"({"name": "can", "shape": {"cylinder": {"radius": 0.3, "half_height": 0.6}}, "position": [0, 2, 0]},
           {"name": "table", "shape": {"compound": {"children": [
               {"shape": {"box": {"half_extents": [1, 0.05, 0.5]}}, "position": [0, 0.5, 0]},
               {"shape": {"cylinder": {"radius": 0.05, "half_height": 0.45}}, "position": [0.9, 0, 0.4], "orientation": [0, 0, 0, 1]}]}},
            "position": [3, 1, 0]},
           {"name": "floor", "type": "static", "shape": {"mesh": {"vertices": [[0, 0, 0], [0, 0, 1], [1, 0, 0]], "triangles": [[0, 1, 2]]}}},
           {"name": "hill", "type": "static", "shape": {"heightfield": {"rows": 2, "columns": 3, "cell_size": 2,
               "heights": [0, 1, null, 0.5, 0, 0]}}})");
    const World world = loadSceneFromString(json);
    REQUIRE(world.bodies.size() == 4);
    CHECK(world.bodies[0].shape.type == ShapeType::Cylinder);
    CHECK(world.bodies[1].shape.compound->children.size() == 2);
    CHECK(world.bodies[2].shape.mesh->triangles.size() == 1);
    CHECK(std::isnan(world.bodies[3].shape.heightField->heights[2]));
    CHECK(world.bodies[3].shape.heightField->highest == 1);
    // Saved and read back: the same shapes (a mass is saved and read back through the density, to
    // its last digit or so).
    const World again = loadSceneFromString(saveSceneToString(world));
    REQUIRE(again.bodies.size() == world.bodies.size());
    CHECK(again.bodies[0].shape.radius == world.bodies[0].shape.radius);
    CHECK(again.bodies[0].shape.halfHeight == world.bodies[0].shape.halfHeight);
    const auto& children = again.bodies[1].shape.compound->children;
    REQUIRE(children.size() == 2);
    CHECK(children[1].shape.type == ShapeType::Cylinder);
    CHECK(children[1].transform.position == world.bodies[1].shape.compound->children[1].transform.position);
    CHECK(again.bodies[2].shape.mesh->vertices == world.bodies[2].shape.mesh->vertices);
    CHECK(again.bodies[2].shape.mesh->triangles == world.bodies[2].shape.mesh->triangles);
    const std::vector<Real>& heights = again.bodies[3].shape.heightField->heights;
    for (std::size_t i = 0; i < heights.size(); ++i) {
        const Real original = world.bodies[3].shape.heightField->heights[i];
        CHECK((std::isnan(heights[i]) ? std::isnan(original) : heights[i] == original));
    }
    CHECK(shapeKindsRelative(again.motionOf(1)->mass, world.motionOf(1)->mass) < Real(1e-6));
}

TEST_CASE("a mesh loads from an OBJ file named relative to the scene file", "[common][shapes]") {
    const std::filesystem::path folder = test::tempPath("stepwise_shape_kinds_test");
    std::filesystem::create_directories(folder / "models");
    std::ofstream(folder / "models" / "quad.obj") << "# a quad\nv 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nvn 0 1 0\nf 1//1 4//1 3//1 2//1\n";
    std::ofstream(folder / "ground.json") << shapeKindsScene(R"({"type": "static", "shape": {"mesh": {"obj": "models/quad.obj"}}})");
    const World world = loadSceneFile((folder / "ground.json").string());
    REQUIRE(world.bodies[0].shape.type == ShapeType::Mesh);
    CHECK(world.bodies[0].shape.mesh->triangles.size() == 2);  // the quad, fanned
    std::ofstream(folder / "models" / "bad.obj") << "v 0 0 0\nv 1 0 0\nf 1 2 7\n";
    std::ofstream(folder / "bad.json") << shapeKindsScene(R"({"type": "static", "shape": {"mesh": {"obj": "models/bad.obj"}}})");
    try {
        loadSceneFile((folder / "bad.json").string());
        FAIL("accepted");
    } catch (const SceneError& error) {
        CHECK(error.path() == "bodies[0].shape.mesh.obj");
        CHECK_THAT(error.what(), Catch::Contains("bad.obj:3") && Catch::Contains("names no vertex"));
    }
    std::filesystem::remove_all(folder);
}

TEST_CASE("bad meshes, height fields, compounds and cylinders are refused at their path", "[common][shapes]") {
    shapeKindsCheckRejected(shapeKindsScene(R"({"shape": {"cylinder": {"radius": 0, "half_height": 1}}})"),
                            "bodies[0].shape.cylinder.radius", "must be > 0");
    shapeKindsCheckRejected(shapeKindsScene(R"({"shape": {"compound": {"children": []}}})"),
                            "bodies[0].shape.compound.children", "at least one child");
    shapeKindsCheckRejected(
        shapeKindsScene(R"({"shape": {"compound": {"children": [{"shape": {"mesh": {"vertices": [[0,0,0],[1,0,0],[0,0,1]], "triangles": [[0,1,2]]}}}]}}})"),
        "bodies[0].shape.compound.children[0].shape", "must be convex");
    shapeKindsCheckRejected(shapeKindsScene(R"({"type": "static", "shape": {"mesh": {"vertices": [[0,0,0]], "triangles": []}}})"),
                            "bodies[0].shape.mesh.triangles", "at least one triangle");
    shapeKindsCheckRejected(shapeKindsScene(R"({"type": "static", "shape": {"mesh": {"vertices": [[0,0,0],[1,0,0],[0,0,1]], "triangles": [[0,1,3]]}}})"),
                            "bodies[0].shape.mesh.triangles[0][2]", "vertex index in [0, 3)");
    shapeKindsCheckRejected(shapeKindsScene(R"({"type": "static", "shape": {"mesh": {"vertices": [[0,0,0],[1,0,0],[2,0,0]], "triangles": [[0,1,2]]}}})"),
                            "bodies[0].shape.mesh.triangles", "triangle 0 is degenerate");
    shapeKindsCheckRejected(shapeKindsScene(R"({"shape": {"mesh": {"vertices": [[0,0,0],[1,0,0],[0,0,1]], "triangles": [[0,1,2]]}}})"),
                            "bodies[0].shape", "static only");
    shapeKindsCheckRejected(
        shapeKindsScene(R"({"type": "static", "shape": {"heightfield": {"rows": 2, "columns": 2, "cell_size": 1, "heights": [0, 0, 0]}}})"),
        "bodies[0].shape.heightfield.heights", "has 3 heights; rows * columns is 4");
    shapeKindsCheckRejected(
        shapeKindsScene(R"({"type": "static", "shape": {"heightfield": {"rows": 2, "columns": 2, "cell_size": 1, "heights": [null, null, null, null]}}})"),
        "bodies[0].shape.heightfield.heights", "every height is a hole");
    shapeKindsCheckRejected(
        shapeKindsScene(R"({"type": "static", "shape": {"heightfield": {"rows": 1, "columns": 2, "cell_size": 1, "heights": [0, 0]}}})"),
        "bodies[0].shape.heightfield.rows", "must be an integer in [2, 65536]");
    shapeKindsCheckRejected(shapeKindsScene(R"({"type": "static", "shape": {"mesh": {"obj": "no/such/file.obj"}}})"),
                            "bodies[0].shape.mesh.obj", "file.obj");
}
