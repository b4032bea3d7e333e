// The recorder's measure: the box the demo frames a scene's drawing with (renderer_dx12's
// DemoState::framing), tested here because the renderer's own tests need Windows.
#include "world/debug_draw.h"
#include "world/shape.h"

#include <catch2/catch.hpp>

#include <limits>

using namespace stepwise;

TEST_CASE("a recorder measures the box around all it drew, finite points only", "[common][draw]") {
    RecordingDraw draw;
    CHECK(draw.empty());
    // A box turned 90 degrees about y: its x and z extents swap.
    const Transform turned{Vec3(10, 0, 0), Quat(Eigen::AngleAxis<Real>(kPi / 2, Vec3::UnitY()))};
    draw.box(turned, Vec3(1, 2, 3), colors::kWhite, Fill::Solid);
    CHECK_FALSE(draw.empty());
    CHECK(draw.bounds().min.isApprox(Vec3(7, -2, -1), Real(1e-5)));
    CHECK(draw.bounds().max.isApprox(Vec3(13, 2, 1), Real(1e-5)));
    // A capsule standing on its local +y axis: the balls at both ends.
    draw.capsule(Transform{Vec3(0, 0, 0), Quat::Identity()}, Real(0.5), 4, colors::kWhite, Fill::Wire);
    CHECK(draw.bounds().max.y() == Real(4.5));
    CHECK(draw.bounds().min.x() == Real(-0.5));
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    draw.line(Vec3(nan, 0, 0), Vec3(0, 20, 0), colors::kRed);
    draw.text(Vec3(0, 0, -30), "label", colors::kWhite);
    CHECK(draw.bounds().max.y() == Real(20));
    CHECK(draw.bounds().min.z() == Real(-30));
    CHECK((draw.bounds().min.allFinite() && draw.bounds().max.allFinite()));
    draw.clear();
    CHECK(draw.empty());
}
