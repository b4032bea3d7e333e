// Scene saving: a saved scene loads back to the same world, its numbers written short.

#include "world/scene.h"

#include <catch2/catch.hpp>

#include <string>

using namespace stepwise;

TEST_CASE("A saved scene loads back to the same world", "[common][scene]") {
    const std::string original = R"({
      "name": "round-trip",
      "settings": {"gravity": [0, -3.7, 0.5], "dt": 0.01, "substeps": 4, "solver_iterations": 20, "baumgarte": 0.1,
                   "slop": 0.01, "warm_starting": false, "broadphase": "sap", "ccd": "on", "integrator": "verlet",
                   "gyroscopic": "off", "solver": "jacobi", "restitution_threshold": 0.25},
      "bodies": [
        {"name": "floor", "type": "static", "shape": {"box": {"half_extents": [10, 0.5, 10]}}, "position": [0, -0.5, 0]},
        {"name": "pill", "shape": {"capsule": {"radius": 0.2, "half_height": 0.6}}, "position": [1, 2, 3],
         "orientation": [0.2, 0.1, 0, 0.9746794], "velocity": [1, 2, 3], "angular_velocity": [0.1, 0.2, 0.3],
         "density": 700, "friction": 0.9, "restitution": 0.3, "bullet": true, "integrator": "rk4"},
        {"name": "gem", "shape": {"convex": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [0.1, 0.1, 0.1]]}},
         "position": [-2, 1, 0], "mass": 3},
        {"name": "paddle", "type": "kinematic", "shape": {"sphere": {"radius": 0.3}}, "velocity": [0, 0, 1]}
      ],
      "joints": [
        {"type": "distance", "a": "pill", "b": "gem", "length": 1.5},
        {"type": "ball_socket", "a": "pill", "b": "gem", "anchor_a": [0, 0.8, 0]},
        {"type": "hinge", "a": "floor", "b": "gem", "axis": [0, 0, 2], "limits": [-0.5, 0.5]},
        {"type": "cone_twist", "a": "pill", "b": "paddle", "axis": [1, 0, 0], "cone_angle": 0.7, "twist_limits": [-0.1, 0.2]},
        {"type": "fixed", "a": "gem", "b": "paddle", "anchor_b": [0.1, 0.2, 0.3]}
      ],
      "forces": [
        {"type": "spring", "a": "pill", "anchor_b": [0, 5, 0], "rest_length": 1, "stiffness": 40, "damping": 0.5},
        {"type": "damping", "body": "gem", "linear": 0.1, "angular": 0.2},
        {"type": "damping", "linear": 0.01}
      ]})";
    const World first = loadSceneFromString(original);
    const std::string saved = saveSceneToString(first);
    const World second = loadSceneFromString(saved, "saved");

    CHECK(saveSceneToString(second) == saved);  // saving is a fixed point after one pass
    CHECK(second.name == "round-trip");
    CHECK(second.settings.gravity == first.settings.gravity);
    CHECK(second.settings.dt == first.settings.dt);
    CHECK(second.settings.substeps == 4);
    CHECK(second.settings.solverIterations == 20);
    CHECK(second.settings.baumgarte == first.settings.baumgarte);
    CHECK(second.settings.slop == first.settings.slop);
    CHECK(second.settings.restitutionThreshold == first.settings.restitutionThreshold);
    CHECK_FALSE(second.settings.warmStarting);
    CHECK(second.settings.broadphase == BroadphaseMode::Sap);
    CHECK(second.settings.ccd == CcdMode::On);
    CHECK(second.settings.integrator == IntegratorKind::Verlet);
    CHECK(second.settings.gyroscopic == GyroscopicMode::Off);
    CHECK(second.settings.solver == SolverKind::Jacobi);

    REQUIRE(second.bodies.size() == first.bodies.size());
    for (std::size_t i = 0; i < first.bodies.size(); ++i) {
        const Body& a = first.bodies[i];
        const Body& b = second.bodies[i];
        INFO(a.name);
        CHECK(b.name == a.name);
        CHECK(b.type == a.type);
        CHECK(b.shape.type == a.shape.type);
        CHECK(b.shape.halfExtents == a.shape.halfExtents);
        CHECK(b.shape.radius == a.shape.radius);
        CHECK(b.shape.halfHeight == a.shape.halfHeight);
        CHECK(b.transform.position == a.transform.position);
        CHECK(b.transform.rotation.coeffs().isApprox(a.transform.rotation.coeffs(), Real(1e-6)));
        CHECK(b.material.friction == a.material.friction);
        CHECK(b.material.restitution == a.material.restitution);
        CHECK(b.bullet == a.bullet);
        const Motion* ma = first.motionOf(int(i));
        const Motion* mb = second.motionOf(int(i));
        REQUIRE((ma == nullptr) == (mb == nullptr));
        if (!ma) continue;
        CHECK(mb->linearVelocity == ma->linearVelocity);
        CHECK(mb->angularVelocity == ma->angularVelocity);
        CHECK(mb->mass == Approx(ma->mass).epsilon(1e-6));
        CHECK(mb->inertiaLocal.isApprox(ma->inertiaLocal, Real(1e-5)));
        CHECK(mb->localCenter.isApprox(ma->localCenter, Real(1e-5)));
        CHECK(mb->integrator == ma->integrator);
    }
    // The interior point of the hull is dropped by the hull builder, on both loads.
    CHECK(second.bodies[2].shape.hull->vertices.size() == 4);

    REQUIRE(second.joints.size() == 5);
    for (std::size_t i = 0; i < first.joints.size(); ++i) {
        const JointDesc& a = first.joints[i];
        const JointDesc& b = second.joints[i];
        INFO(toString(a.type));
        CHECK(b.type == a.type);
        CHECK(b.bodyA == a.bodyA);
        CHECK(b.bodyB == a.bodyB);
        CHECK(b.localAnchorA == a.localAnchorA);
        CHECK(b.localAnchorB == a.localAnchorB);
        CHECK(b.axis == a.axis);
        CHECK(b.length == a.length);
        CHECK(b.limits == a.limits);
        CHECK(b.coneAngle == a.coneAngle);
        CHECK(b.twistLimits == a.twistLimits);
    }
    CHECK(second.joints[2].axis == Vec3(0, 0, 1));  // normalised on load

    REQUIRE(second.springs.size() == 1);
    CHECK(second.springs[0].bodyB == -1);
    CHECK(second.springs[0].anchorB == first.springs[0].anchorB);
    CHECK(second.springs[0].restLength == first.springs[0].restLength);
    CHECK(second.springs[0].stiffness == first.springs[0].stiffness);
    CHECK(second.springs[0].damping == first.springs[0].damping);
    REQUIRE(second.dampings.size() == 2);
    CHECK(second.dampings[0].body == 2);
    CHECK(second.dampings[1].body == -1);
    CHECK(second.dampings[1].linear == first.dampings[1].linear);
}

TEST_CASE("Saved numbers are short: 0.1 stays 0.1", "[common][scene]") {
    const World world = loadSceneFromString(R"({"bodies": [{"shape": {"sphere": {"radius": 0.1}}, "position": [0.3, -0.7, 0]}]})");
    const std::string saved = saveSceneToString(world);
    CHECK_THAT(saved, Catch::Contains("\"radius\": 0.1\n"));
    CHECK_THAT(saved, Catch::Contains("0.3,"));
    CHECK_THAT(saved, Catch::Contains("-0.7,"));
}
