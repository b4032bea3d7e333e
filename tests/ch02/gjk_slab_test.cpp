// A small box resting on a large one: the commonest pair of a scene (a crate on the ground) and
// the hardest shape for GJK's simplex, since A - B is then a slab 40 m wide and about a metre
// thick, and the tetrahedra near the origin are slivers millimetres thick. Against the oracle.

#include "gjk_test_util.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace stepwise;
using namespace stepwise::test;

namespace {

/// A box of edges 0.2..1.2 m resting on a face, at a random place over a 40 m ground box (top face
/// y = 0), lowered so that its lowest corner lies `depth` below the top (< 0: above it).
BoxPair boxOnGround(Random& random, double depth) {
    BoxPair pair;
    pair.halfExtentsA = Vec3(20, Real(0.5), 20);
    pair.poseA = Transform{Vec3(0, Real(-0.5), 0), Quat::Identity()};
    pair.halfExtentsB = Vec3(random.uniformReal(Real(0.1), Real(0.6)), random.uniformReal(Real(0.1), Real(0.6)),
                             random.uniformReal(Real(0.1), Real(0.6)));
    // Resting on a face, as boxes on the ground do: a random face down, a random heading, and a
    // tilt of up to half a degree (a random rotation is almost never this close to flat, and the
    // flat ones are the slivers).
    const int face = static_cast<int>(random.uniform() * 6) % 6;
    const Vec3 faceAxis = face < 2 ? Vec3::UnitX() : face < 4 ? Vec3::UnitZ() : Vec3::UnitY();
    const Real faceAngle = face < 4 ? Real(face % 2 ? 1.5707963 : -1.5707963) : Real(face == 5 ? 3.1415927 : 0);
    const Quat heading(Eigen::AngleAxis<Real>(random.uniformReal(0, Real(6.2831853)), Vec3::UnitY()));
    const Quat tilt(Eigen::AngleAxis<Real>(random.uniformReal(0, Real(0.0087)), random.unitVector()));
    const Quat rotation = (tilt * heading * Quat(Eigen::AngleAxis<Real>(faceAngle, faceAxis))).normalized();
    const Mat3 axes = rotation.toRotationMatrix();
    // The lowest corner's height below the centre: the half extents along the world's up axis.
    double reach = 0;
    for (int k = 0; k < 3; ++k) reach += std::abs(double(axes(1, k))) * double(pair.halfExtentsB[k]);
    const Real x = random.uniformReal(-15, 15), z = random.uniformReal(-15, 15);
    pair.poseB = Transform{Vec3(x, Real(reach - depth), z), rotation};
    return pair;
}

}  // namespace

TEST_CASE("a small box on a 40 m ground box: GJK agrees with the oracle on touching and apart",
          "[ch02][gjk][scale]") {
    Random random(0x51AB);
    int checked = 0;
    for (const double depth : {-3e-3, -1e-3, 1e-3, 3e-3, 1e-2}) {
        for (int index = 0; index < 2000; ++index) {
            const BoxPair pair = boxOnGround(random, depth);
            const oracle::OracleBox ground = oracleA(pair), box = oracleB(pair);
            const double exact = oracle::boxSignedDistance(ground, box);  // < 0: overlap
            const BoxPairProxies proxies(pair, SupportMode::Extents);
            const GjkTolerances tolerances = gjkTolerances(proxies.a, proxies.b);
            // Beyond twice the touching tolerance (plus the pose's own float rounding) the
            // answer is clear-cut.
            const double clear = 2 * double(tolerances.touching) + 1e-5;
            if (std::abs(exact) < clear) continue;
            ++checked;
            const GjkResult intersect = gjkIntersect(proxies.a, proxies.b);
            const GjkDistanceResult distance = gjkDistance(proxies.a, proxies.b);
            INFO("depth " << depth << ", pair " << index << ": oracle " << exact << ", gjk " << intersect.intersect
                          << " (" << toString(intersect.exit) << "), distance " << distance.separated << " "
                          << distance.distance << " (" << toString(distance.exit) << ")");
            CHECK(intersect.intersect == (exact < 0));
            CHECK(distance.separated == (exact > 0));
            // A walk that ends cleanly has the distance; one stopped by a rounding floor, with its
            // gap proven by a support plane, has the distance of two points of the shapes: never
            // less than the distance.
            const double tolerance = distanceTolerance(exact, 41);
            if (exact > 0 && distance.exit == GjkExit::Separated) CHECK(double(distance.distance) == Approx(exact).margin(tolerance));
            if (exact > 0) CHECK(double(distance.distance) >= exact - tolerance);
        }
    }
    CHECK(checked > 8000);
}
