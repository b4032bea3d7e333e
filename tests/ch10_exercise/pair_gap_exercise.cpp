// Exercise check for chapter 10 (`ctest -L ch10-exercise`): rewrite stillApart in
// chapters/10_skip_work/contact_cache.cpp from the page's section on pairs kept apart, and run this.
// A pair found `gap` apart may be skipped while the gap, less how far B's points can have moved in
// A's frame (the change of B's origin plus the angle B turned times its bounding radius) and less
// GJK's 1 mm allowance, is still at least keepDistance. The checks: the bound on pure moves, pure
// turns and both; only the pose of B in A's frame counts; and on real shapes, a pair the function
// keeps apart is at least keepDistance apart.
#include "10_skip_work/contact_cache.h"

#include "03_epa/narrowphase.h"
#include "math/random.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace stepwise;

namespace {

constexpr Real kAllowance = Real(0.001);  // GJK's tolerance, taken off every gap
constexpr Real kEdge = Real(2e-4);        // how close to the boundary the checks go (float round-off)

Vec3 randomDirection(Random& random) {
    const Vec3 v = random.rotation() * Vec3::UnitX();
    return v.normalized();
}

/// Checks stillApart on both sides of the answer: true a little below `left`, false a little above.
void checkBoundary(const PairGap& gap, const Transform& a, const Transform& b, Real left) {
    INFO("the gap left after the closing and the allowance should be " << left << " m");
    CHECK(stillApart(gap, a, b, left - kEdge));
    CHECK_FALSE(stillApart(gap, a, b, left + kEdge));
}

}  // namespace

TEST_CASE("exercise: a pair kept apart loses exactly B's move in A's frame", "[ch10-exercise]") {
    Random random(10);
    for (int trial = 0; trial < 50; ++trial) {
        PairGap gap;
        gap.gap = random.uniformReal(Real(0.3), Real(1));
        gap.radiusB = random.uniformReal(Real(0.2), Real(1.5));
        const Transform a{Vec3::Zero(), Quat::Identity()};
        const Vec3 built = Vec3(3, 0, 0) + randomDirection(random);
        gap.builtRelativePosition = built;
        gap.builtRelativeRotation = random.rotation();

        {  // a move
            const Real moved = random.uniformReal(0, Real(0.25));
            const Transform b{built + moved * randomDirection(random), gap.builtRelativeRotation};
            checkBoundary(gap, a, b, gap.gap - moved - kAllowance);
        }
        {  // a turn, at the bounding radius
            const Real angle = random.uniformReal(Real(0.05), Real(0.2));
            const Quat turn(Eigen::AngleAxis<Real>(angle, randomDirection(random)));
            const Transform b{built, (turn * gap.builtRelativeRotation).normalized()};
            checkBoundary(gap, a, b, gap.gap - angle * gap.radiusB - kAllowance);
        }
        {  // a move and a turn
            const Real moved = random.uniformReal(0, Real(0.1));
            const Real angle = random.uniformReal(Real(0.05), Real(0.15));
            const Quat turn(Eigen::AngleAxis<Real>(angle, randomDirection(random)));
            const Transform b{built + moved * randomDirection(random), (gap.builtRelativeRotation * turn).normalized()};
            checkBoundary(gap, a, b, gap.gap - moved - angle * gap.radiusB - kAllowance);
        }
        {  // only the pose of B in A's frame counts
            // Carry both bodies anywhere, turned anyhow, B moved 0.1 m in A's frame: the same answer.
            const Transform carriedA{Vec3(random.uniformReal(-50, 50), random.uniformReal(-50, 50), 7), random.rotation()};
            const Vec3 moved = Real(0.1) * randomDirection(random);
            const Transform b{carriedA.apply(built + moved), (carriedA.rotation * gap.builtRelativeRotation).normalized()};
            checkBoundary(gap, carriedA, b, gap.gap - Real(0.1) - kAllowance);
        }
    }
}

TEST_CASE("exercise: a pair the bound keeps apart is that far apart", "[ch10-exercise]") {
    // Two boxes found apart, then moved a little: whenever stillApart skips the pair, the distance
    // GJK measures now is at least the distance asked for.
    Random random(11);
    CollideOptions options;
    options.separationDistance = true;
    int skipped = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const Shape shapeA = Shape::box(Vec3(random.uniformReal(Real(0.2), 1), random.uniformReal(Real(0.2), 1), Real(0.5)));
        const Shape shapeB = Shape::box(Vec3::Constant(random.uniformReal(Real(0.2), Real(0.6))));
        const Transform a{Vec3::Zero(), random.rotation()};
        Transform b{Vec3(random.uniformReal(Real(1.8), 3), random.uniformReal(-1, 1), random.uniformReal(-1, 1)), random.rotation()};
        const ContactQuery found = collideShapes(shapeA, a, shapeB, b, options);
        if (found.intersect || found.depth > -Real(0.05)) continue;
        PairGap gap;
        gap.gap = -found.depth;
        gap.radiusB = boundingRadius(shapeB);
        gap.builtRelativePosition = a.applyInverse(b.position);
        gap.builtRelativeRotation = a.rotation.conjugate() * b.rotation;
        b.position += random.uniformReal(0, Real(0.3)) * randomDirection(random);
        b.rotation = (Quat(Eigen::AngleAxis<Real>(random.uniformReal(0, Real(0.3)), randomDirection(random))) * b.rotation).normalized();
        const Real keep = random.uniformReal(Real(0.01), Real(0.2));
        if (!stillApart(gap, a, b, keep)) continue;
        ++skipped;
        const ContactQuery now = collideShapes(shapeA, a, shapeB, b, options);
        INFO("trial " << trial << ": kept apart at " << keep << " m, measured " << -now.depth << " m");
        CHECK_FALSE(now.intersect);
        CHECK(-now.depth >= keep - Real(1e-4));
    }
    CHECK(skipped > 40);  // the bound must skip some pairs, not answer "ask again" to all
}
