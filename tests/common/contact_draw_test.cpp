// The one contact drawer: each flag adds exactly its marks.
#include "world/contact_draw.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

World worldWithOneLoadedPoint() {
    World world;
    Contact contact;
    contact.bodyA = 0;
    contact.bodyB = 1;
    contact.normal = Vec3::UnitY();
    contact.pointCount = 1;
    contact.points[0].pointA = Vec3(0, Real(0.01), 0);
    contact.points[0].pointB = Vec3::Zero();
    contact.points[0].normalImpulse = Real(0.5);
    contact.points[0].tangentImpulse[0] = Real(0.1);
    world.contacts.push_back(contact);
    return world;
}

int arrowsOfColor(const RecordingDraw& draw, Color color) {
    int count = 0;
    for (const RecordingDraw::Command& command : draw.commands())
        count += command.kind == RecordingDraw::Kind::Arrow && command.color.r == color.r && command.color.g == color.g;
    return count;
}

}  // namespace

TEST_CASE("the contact drawer shows points, normals or impulses as its flags say", "[common][draw]") {
    const World world = worldWithOneLoadedPoint();
    RecordingDraw draw;
    drawContacts(draw, world);
    CHECK(draw.count(RecordingDraw::Kind::Box) == 2);   // one cube on each surface
    CHECK(arrowsOfColor(draw, colors::kYellow) == 1);   // the fixed-length normal
    CHECK(arrowsOfColor(draw, colors::kOrange) == 0);

    ContactDrawOptions impulses;
    impulses.points = false;
    impulses.impulses = true;
    draw.clear();
    drawContacts(draw, world, impulses);
    CHECK(draw.count(RecordingDraw::Kind::Box) == 0);
    REQUIRE(arrowsOfColor(draw, colors::kYellow) == 1);
    CHECK(arrowsOfColor(draw, colors::kOrange) == 1);
    // The normal arrow is the mean force over the step: 0.5 N s / (1/60 s) = 30 N, at 0.05 m/N.
    const RecordingDraw::Command& normalArrow = draw.commands().front();
    CHECK((normalArrow.b - normalArrow.a).norm() == Approx(1.5).epsilon(1e-5));

    draw.clear();
    drawContact(draw, Vec3::Zero(), Vec3::UnitX(), Vec3::UnitX(), ContactDrawOptions{false, true});
    CHECK(draw.count(RecordingDraw::Kind::Box) == 0);
    CHECK(draw.count(RecordingDraw::Kind::Arrow) == 1);
}
