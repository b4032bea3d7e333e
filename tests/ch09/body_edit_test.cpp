// What the inspector and the gizmo write: an edit that changes nothing changes no bit; mass and
// inertia edits keep their inverses consistent; the gizmo's move stops the body; bad edits are
// refused with the field named, and the world is left as it was.
#include "09_debug/body_edit.h"

#include "09_debug/scenes.h"
#include "world/state_hash.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace stepwise;

TEST_CASE("body edits: the current state written back changes nothing", "[ch09][edit]") {
    World world = buildDebugHullOnBox();
    const std::uint64_t before = stateHash(world);
    const std::vector<Motion> motions = world.motions;
    for (int body = 0; body < int(world.bodies.size()); ++body) applyEdit(world, currentState(world, body));
    CHECK(stateHash(world) == before);
    for (std::size_t i = 0; i < motions.size(); ++i) {
        CHECK(world.motions[i].inverseMass == motions[i].inverseMass);
        CHECK(world.motions[i].inverseInertiaLocal == motions[i].inverseInertiaLocal);
    }
}

TEST_CASE("body edits: mass, inertia, velocities and the gizmo's move", "[ch09][edit]") {
    World world = buildDebugDrop();
    const int box = world.findBody("box");
    BodyEdit edit = currentState(world, box);
    edit.mass = 8;
    edit.inertiaLocal = Vec3(1, 2, Real(2.5)).asDiagonal();
    edit.angularVelocity = Vec3(0, 3, 0);
    applyEdit(world, edit);
    const Motion& motion = *world.motionOf(box);
    CHECK(motion.mass == 8);
    CHECK(motion.inverseMass == Real(1) / 8);
    CHECK(motion.inverseInertiaLocal(1, 1) == Approx(0.5));
    CHECK(motion.angularVelocity.y() == 3);
    const Transform target{Vec3(1, 2, 3), Quat(Eigen::AngleAxis<Real>(Real(0.4), Vec3::UnitX()))};
    applyEdit(world, moveEdit(world, box, target));
    CHECK(world.bodies[std::size_t(box)].transform.position == Vec3(1, 2, 3));
    CHECK(world.motionOf(box)->angularVelocity == Vec3::Zero());
    CHECK(world.motionOf(box)->linearVelocity == Vec3::Zero());
    CHECK(world.motionOf(box)->mass == 8);   // the gizmo moves; it does not reweigh
    // A static body can be moved (the gizmo on the ground) but has no mass to edit.
    applyEdit(world, moveEdit(world, 0, Transform{Vec3(0, Real(-0.6), 0), Quat::Identity()}));
    CHECK(world.bodies[0].transform.position.y() == Real(-0.6));
}

TEST_CASE("body edits: bad values are refused with the field named, the world untouched", "[ch09][edit]") {
    World world = buildDebugDrop();
    const int box = world.findBody("box");
    const std::uint64_t before = stateHash(world);
    const auto refusal = [&](const std::function<void(BodyEdit&)>& spoil) {
        BodyEdit edit = currentState(world, box);
        spoil(edit);
        const std::string message = validateEdit(world, edit);
        CHECK_THROWS_AS(applyEdit(world, edit), std::invalid_argument);
        return message;
    };
    CHECK(refusal([](BodyEdit& e) { e.body = 42; }).find("body 42 does not exist") != std::string::npos);
    CHECK(refusal([](BodyEdit& e) { e.mass = 0; }).find("body 'box': mass must be positive") != std::string::npos);
    CHECK(refusal([](BodyEdit& e) { e.mass = std::nan(""); }).find("mass") != std::string::npos);
    CHECK(refusal([](BodyEdit& e) { e.transform.position.x() = INFINITY; }).find("position") != std::string::npos);
    CHECK(refusal([](BodyEdit& e) { e.transform.rotation = Quat(2, 0, 0, 0); }).find("unit quaternion") != std::string::npos);
    CHECK(refusal([](BodyEdit& e) { e.linearVelocity.y() = std::nan(""); }).find("linear velocity") != std::string::npos);
    CHECK(refusal([](BodyEdit& e) { e.inertiaLocal(0, 0) = -1; }).find("positive definite") != std::string::npos);
    CHECK(refusal([](BodyEdit& e) { e.inertiaLocal(0, 1) = 1; }).find("symmetric") != std::string::npos);
    CHECK(refusal([](BodyEdit& e) { e.inertiaLocal = Vec3(1, 1, 5).asDiagonal(); }).find("triangle inequality") != std::string::npos);
    CHECK(stateHash(world) == before);
}
