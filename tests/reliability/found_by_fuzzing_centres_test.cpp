// What fuzz_narrowphase found once its CI smoke stopped walking the same inputs every run
// (docs/reliability.md): pairs that share a centre, or nearly, and shapes of extreme aspect.
// Each case pins the exact numbers the fuzzer printed (STEPWISE_FUZZ_VERBOSE=1) and holds the
// answer to the target's own invariants: both points on their shape's surface within 1e-4 of the
// pair's size plus the spacing of Real positions there, and the depth the geometry gives.
#include <catch2/catch.hpp>

#include "03_epa/narrowphase.h"
#include "random_shapes.h"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace stepwise;

namespace {

/// The fuzz target's tolerance for a point on a surface, m.
double surfaceTolerance(const Shape& a, const Transform& poseA, const Shape& b, const Transform& poseB) {
    const double pairSize = std::max(double(boundingRadius(a)), double(boundingRadius(b)));
    const double farthest = std::max(double(poseA.position.norm()), double(poseB.position.norm())) + pairSize;
    return 1e-4 * pairSize + 64 * double(kEpsilon) * farthest;
}

double offSurface(const Shape& shape, const Transform& pose, const Vec3& worldPoint) {
    const Eigen::Vector3d local =
        pose.rotation.cast<double>().conjugate() * (worldPoint.cast<double>() - pose.position.cast<double>());
    return std::abs(fuzz::signedDistance(shape, local));
}

/// Both routes (closed forms on and off) answer the pair with points on both surfaces; returns
/// the depth of the GJK/EPA route.
Real checkPointsOnSurfaces(const Shape& a, const Transform& poseA, const Shape& b, const Transform& poseB) {
    const double tolerance = surfaceTolerance(a, poseA, b, poseB);
    Real depth = 0;
    for (const bool closedForms : {true, false}) {
        CollideOptions options;
        options.closedForms = closedForms;
        const ContactQuery query = collideShapes(a, poseA, b, poseB, options);
        INFO("closed forms " << closedForms << ", routine " << query.routine << ", depth " << query.depth);
        CHECK(offSurface(a, poseA, query.pointA) <= tolerance);
        CHECK(offSurface(b, poseB, query.pointB) <= tolerance);
        if (!closedForms) depth = query.depth;
    }
    return depth;
}

Quat fromPrinted(double x, double y, double z, double w) { return Quat(Real(w), Real(x), Real(y), Real(z)); }

Shape hull(const std::vector<Vec3>& points) { return Shape::convex(points); }

const Quat kAxesCycled = fromPrinted(-0.5, -0.5, -0.5, -0.5);

}  // namespace

TEST_CASE("a 47 m capsule crossing a small one at its centre gets points on both surfaces", "[reliability][closed-form]") {
    // The closest points of the two axes were a few rounding errors of 47 m apart, more than the
    // coincidence test allowed from the cores' small coordinates: the normal followed the noise
    // and left pointB 5.8 cm inside the long capsule.
    Transform poseA, poseB;
    poseA.position = poseB.position = Vec3(Real(-99.9984894), Real(96.0784302), Real(96.0784302));
    poseA.rotation = fromPrinted(-0.365269601, -0.537456393, -0.537456393, -0.537456393);
    poseB.rotation = fromPrinted(-0.576403499, -0.576403439, 0.576393843, -0.0573435687);
    const Shape small = Shape::capsule(Real(0.0513076931), Real(0.0513076819));
    const Shape long_ = Shape::capsule(Real(0.261997849), Real(23.5208683));
    const ContactQuery query = collideShapes(small, poseA, long_, poseB);
    CHECK(query.depth == Approx(0.0513076931 + 0.261997849).epsilon(1e-4));
    checkPointsOnSurfaces(small, poseA, long_, poseB);
}

TEST_CASE("a thin plate through a box's centre is as deep as the box's half plus the plate's", "[reliability][epa]") {
    // GJK's tetrahedron had the origin on an edge; EPA's first new face through that edge lay
    // 1.6e-7 m nearer than the face it replaced (both pass within 4e-7 m of the origin), was
    // taken for round-off breaking convexity, and EPA answered depth 0 for a 7 cm cube around a
    // 1.3 mm plate.
    const Shape plate = hull({Vec3(Real(-0.0564012192), Real(-0.000650906004), Real(-0.030849101)),
                              Vec3(Real(0.0568453297), Real(0.000650906062), Real(0.0568444543)),
                              Vec3(Real(-0.0359776393), Real(0.000650906062), Real(0.0568453297)),
                              Vec3(Real(0.0414126813), Real(0.000645860506), Real(-0.0568453297)),
                              Vec3(Real(-0.0565160736), Real(-0.000252325728), Real(-0.00435564248)),
                              Vec3(Real(-0.0568453297), Real(-0.000650906062), Real(-0.0568453297)),
                              Vec3(Real(0.0455660261), Real(-6.66688939e-05), Real(-0.0353436619)),
                              Vec3(Real(-0.0568453297), Real(-0.000650906062), Real(-0.0568453297)),
                              Vec3(Real(-0.0568453297), Real(-0.000650906062), Real(-0.0568453297))});
    const Real half = Real(0.0343514271);
    const Shape cube = Shape::box(Vec3(half, half, half));
    const Transform pose{Vec3(-100, -100, -100), kAxesCycled};
    const Real depth = checkPointsOnSurfaces(plate, pose, cube, pose);
    CHECK(depth == Approx(0.0343514271 + 0.000650906).epsilon(0.01));
}

TEST_CASE("two nearly equal boxes at one pose get points on both surfaces", "[reliability][epa]") {
    // Rotations 4e-6 apart give A - B faces a few micrometres wide: a support point in line with
    // a horizon edge made a sliver, EPA stopped at 0.0192 of 0.0195 and put pointB 4.9 mm inside.
    const Shape boxA = Shape::box(Vec3(Real(0.0125603555), Real(0.015850896), Real(0.0155661134)));
    const Real half = Real(0.00694650458);
    const Shape boxB = Shape::box(Vec3(half, Real(0.00694650551), half));
    const Transform poseA{Vec3(-100, -100, -100), fromPrinted(-0.500003815, -0.500003815, -0.500003815, -0.499988556)};
    const Transform poseB{Vec3(-100, -100, -100), kAxesCycled};
    const Real depth = checkPointsOnSurfaces(boxA, poseA, boxB, poseB);
    CHECK(depth == Approx(0.0125603555 + 0.00694650458).epsilon(0.005));
}

TEST_CASE("a 28 m needle beside a small box gets a closest point on the box", "[reliability][gjk]") {
    // GJK's closest point on a 28 m by 14 cm triangle of A - B: the Voronoi tests (differences
    // of products) called it the face region, the accurate weights were -0.5, and the point
    // they built on the box lay 6.4 cm outside it.
    const Shape needle = hull({Vec3(Real(-0.0715878904), Real(12.943059), Real(-0.346088171)),
                               Vec3(Real(-0.142389521), Real(-15.0074673), Real(0.237805575)),
                               Vec3(Real(-0.0743235573), Real(-5.36775732), Real(-0.414224058)),
                               Vec3(Real(-0.414224058), Real(-15.0078669), Real(-0.414224058)),
                               Vec3(Real(-0.414224058), Real(-15.0078669), Real(-0.414224058))});
    const Real half = Real(0.0685588419);
    const Shape box = Shape::box(Vec3(half, half, half));
    const Transform pose{Vec3(-100, -100, -100), kAxesCycled};
    const Real depth = checkPointsOnSurfaces(needle, pose, box, pose);
    CHECK(depth == Approx(-0.0364).epsilon(0.01));  // separated by 3.6 cm
}

TEST_CASE("a plate 1/1600 of its width thick through a 5 mm box gets a way out", "[reliability][epa]") {
    // EPA's polytope stopped growing on a face through the origin, 3.8 mm inside the boundary:
    // depth 0 and a point on the plate 4.4 m from the box. The tightest support bound it saw is
    // the answer now.
    const Shape plate = hull({Vec3(Real(-4.42375755), Real(-4.42375755), Real(-4.42369986)),
                              Vec3(Real(4.42375755), Real(4.42375755), Real(4.42375755)),
                              Vec3(Real(4.42375755), Real(4.42362213), Real(-4.42375755)),
                              Vec3(Real(4.42375708), Real(4.42362213), Real(-4.42375803)),
                              Vec3(Real(-4.42375708), Real(-4.42375708), Real(-4.42370033)),
                              Vec3(Real(4.42375755), Real(4.40215969), Real(-4.42352819)),
                              Vec3(Real(4.42375708), Real(4.42362213), Real(-4.42375803)),
                              Vec3(Real(4.42375755), Real(4.40215969), Real(-4.42352819))});
    const Real half = Real(0.00268756971);
    const Shape box = Shape::box(Vec3(half, half, half));
    const Transform pose{Vec3(-100, -100, -100), kAxesCycled};
    const Real depth = checkPointsOnSurfaces(plate, pose, box, pose);
    CHECK(depth >= half);
    CHECK(depth <= Real(0.01));
}
