#pragma once
// Small helpers shared by the chapter 2 suites: proxies and oracle boxes from a BoxPair.

#include "02_gjk/gjk.h"
#include "02_gjk/random_pairs.h"
#include "02_gjk/box_oracle.h"

namespace stepwise::test {

/// The two shapes of a box pair and their proxies (the proxies point into this struct: keep it
/// alive and do not copy it while they are used).
struct BoxPairProxies {
    Shape shapeA;
    Shape shapeB;
    ConvexProxy a;
    ConvexProxy b;

    BoxPairProxies(const BoxPair& pair, SupportMode mode)
        : shapeA(Shape::box(pair.halfExtentsA)), shapeB(Shape::box(pair.halfExtentsB)) {
        a = ConvexProxy{&shapeA, pair.poseA, mode};
        b = ConvexProxy{&shapeB, pair.poseB, mode};
    }
    BoxPairProxies(const BoxPairProxies&) = delete;
    BoxPairProxies& operator=(const BoxPairProxies&) = delete;
};

inline oracle::OracleBox oracleA(const BoxPair& pair) { return oracle::makeOracleBox(pair.halfExtentsA, pair.poseA); }
inline oracle::OracleBox oracleB(const BoxPair& pair) { return oracle::makeOracleBox(pair.halfExtentsB, pair.poseB); }

/// The tolerance a distance is checked to: 1e-4 relative, plus an absolute term for the rounding
/// of the support points themselves. A support point of shapes of size L (|w| <= L) carries a
/// few eps L of rounding from the rotation and the subtraction, whatever the distance, so for a
/// small distance in float a purely relative 1e-4 is out of reach (eps L / d > 1e-4 once
/// d < 1e-3 L). The random-pair test prints the worst absolute error it sees in units of eps L
/// (about 2-3 in both builds); 16 eps L leaves a margin of five. That is ~2e-6 L in float and
/// ~4e-15 L in double, where the 1e-4 relative term is what binds.
inline double distanceTolerance(double exact, double pairSize) {
    return 1e-4 * exact + 16.0 * double(kEpsilon) * pairSize;
}

/// True when the simplex is a tetrahedron whose closest point to the origin is within
/// `tolerance`: the origin is inside it or on its boundary (what chapter 3's EPA starts from).
inline bool tetrahedronHoldsOrigin(const Simplex& simplex, Real tolerance) {
    if (simplex.count != 4) return false;
    Vec3 points[4];
    for (int i = 0; i < 4; ++i) points[i] = simplex.vertices[i].w;
    const SimplexClosest closest = closestPointToOrigin(points, 4, 1);
    return closest.inside || closest.point.norm() <= tolerance;
}

}  // namespace stepwise::test
