#include "02_gjk/random_pairs.h"

#include "02_gjk/box_oracle.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

BoxPair randomBoxPair(Random& random, double minSize, double maxSize, const Vec3& origin) {
    BoxPair pair;
    // One draw per statement (z, y, x): a call's arguments are evaluated in an unspecified
    // order, so draws inside one expression would give GCC and Clang different pairs.
    auto halfExtents = [&] {
        const double z = random.uniform(minSize, maxSize);
        const double y = random.uniform(minSize, maxSize);
        const double x = random.uniform(minSize, maxSize);
        return Vec3(Real(0.5 * x), Real(0.5 * y), Real(0.5 * z));
    };
    pair.halfExtentsA = halfExtents();
    pair.halfExtentsB = halfExtents();
    pair.poseA.rotation = random.rotation();
    pair.poseB.rotation = random.rotation();
    const double reach = pair.halfExtentsA.cast<double>().norm() + pair.halfExtentsB.cast<double>().norm();
    const Vec3 direction = random.unitVector();  // one draw per statement
    const Vec3 offset = direction * Real(random.uniform(0, 1.2 * reach));
    pair.poseA.position = origin;
    pair.poseB.position = origin + offset;
    return pair;
}

BoxPair overlappingBoxPair(Random& random, double minDepthFraction, double centreSpread) {
    auto halfExtents = [&] {  // one draw per statement (z, y, x), as in randomBoxPair
        const double z = random.uniform(0.05, 1);
        const double y = random.uniform(0.05, 1);
        const double x = random.uniform(0.05, 1);
        return Vec3(Real(x), Real(y), Real(z));
    };
    for (;;) {
        BoxPair pair;
        pair.halfExtentsA = halfExtents();
        pair.halfExtentsB = halfExtents();
        const double centreZ = random.uniform(-centreSpread, centreSpread);  // one draw per statement (z, y, x)
        const double centreY = random.uniform(-centreSpread, centreSpread);
        const double centreX = random.uniform(-centreSpread, centreSpread);
        pair.poseA.position = Vec3(Real(centreX), Real(centreY), Real(centreZ));
        pair.poseA.rotation = random.rotation();
        pair.poseB.rotation = random.rotation();
        const double reach = pair.halfExtentsA.cast<double>().norm() + pair.halfExtentsB.cast<double>().norm();
        const Real distance = Real(random.uniform(0, reach));  // one draw per statement
        pair.poseB.position = pair.poseA.position + distance * random.unitVector();
        const oracle::SatResult sat = oracle::boxSat(oracle::makeOracleBox(pair.halfExtentsA, pair.poseA),
                                                     oracle::makeOracleBox(pair.halfExtentsB, pair.poseB));
        const double smallest = std::min(pair.halfExtentsA.minCoeff(), pair.halfExtentsB.minCoeff());
        if (!sat.overlap || sat.depth < minDepthFraction * smallest) continue;
        pair.exactGap = -sat.depth;
        return pair;
    }
}

BoxPair nearContactBoxPair(Random& random, double gap) {
    BoxPair pair;
    // One draw per statement (z, y, x), as in randomBoxPair.
    auto halfExtents = [&random](double low, double high) {
        const double z = random.uniform(low, high);
        const double y = random.uniform(low, high);
        const double x = random.uniform(low, high);
        return Vec3(Real(x), Real(y), Real(z));
    };
    pair.halfExtentsA = halfExtents(0.5, 1.0);
    pair.halfExtentsB = halfExtents(0.05, 0.2);
    pair.poseB.rotation = random.rotation();
    // B's corners in double, from the rounded rotation and half extents (the stored pose is
    // what both GJK and this construction must agree on).
    const Eigen::Matrix3d rotationB = pair.poseB.rotation.cast<double>().normalized().toRotationMatrix();
    auto lowestCorner = [&] {
        Eigen::Vector3d lowest(1e300, 0, 0);
        for (int corner = 0; corner < 8; ++corner) {
            const Eigen::Vector3d local((corner & 1) ? pair.halfExtentsB.x() : -pair.halfExtentsB.x(),
                                        (corner & 2) ? pair.halfExtentsB.y() : -pair.halfExtentsB.y(),
                                        (corner & 4) ? pair.halfExtentsB.z() : -pair.halfExtentsB.z());
            const Eigen::Vector3d arm = rotationB * local;
            if (arm.x() < lowest.x()) lowest = arm;
        }
        return lowest;
    };
    const Eigen::Vector3d arm = lowestCorner();
    // The corner lands on A's +X face at (hA.x + gap, y, z) with y, z in the middle half of it.
    const double alongZ = random.uniform(-0.5, 0.5);  // one draw per statement, z first
    const double alongY = random.uniform(-0.5, 0.5);
    const Eigen::Vector3d target(double(pair.halfExtentsA.x()) + gap, alongY * pair.halfExtentsA.y(),
                                 alongZ * pair.halfExtentsA.z());
    pair.poseB.position = (target - arm).cast<Real>();
    // Rounding the position moved the corner by up to half an ulp: measure the gap again.
    pair.exactGap = pair.poseB.position.cast<double>().x() + arm.x() - double(pair.halfExtentsA.x());
    return pair;
}

}  // namespace stepwise
