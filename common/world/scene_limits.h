#pragma once
// What a scene or query file may ask for. Each limit is far beyond any scene the engine is meant
// for and well inside what its arithmetic survives, so a value past one is a typo or an attack,
// never a scene: the loader rejects it with its JSON path (docs/scene-format.md, "Limits")
// instead of letting it turn into NaN a few frames later, or into memory the machine lacks.

#include "math/math.h"

#include <cstddef>

namespace stepwise {

/// Positions and anchors, m: at 1e6 m a float position still resolves 6 cm.
constexpr Real kMaxCoordinate = Real(1e6);
/// Shape sizes (half extents, radii, half heights, hull vertex coordinates), m. The smallest
/// is a tenth of a millimetre: below it float inertias (size^5) underflow.
constexpr Real kMinShapeSize = Real(1e-4);
constexpr Real kMaxShapeSize = Real(1e5);
/// Speeds: 1e5 m/s is thirty times a rifle bullet; 1e4 rad/s is about 100,000 rpm.
constexpr Real kMaxSpeed = Real(1e5);
constexpr Real kMaxAngularSpeed = Real(1e4);
/// Gravity, m/s^2: a thousand g.
constexpr Real kMaxGravity = Real(1e4);
/// Mass (kg) and density (kg/m^3) ranges: a milligram to a million tonnes; thinner than air to
/// fifty times osmium.
constexpr Real kMinMass = Real(1e-6);
constexpr Real kMaxMass = Real(1e9);
constexpr Real kMinDensity = Real(1e-3);
constexpr Real kMaxDensity = Real(1e6);
/// Joints: motor forces and torques (N, N m) and joint friction, spring frequencies (Hz) and
/// damping ratios. A spring above ten kilohertz is stiffer than any step can resolve.
constexpr Real kMaxForce = Real(1e9);
constexpr Real kMaxJointHertz = Real(1e4);
constexpr Real kMaxDampingRatio = Real(1e3);
/// Counts: bodies, joints and forces per scene; pairs per query; bytes per file; values (numbers,
/// strings, arrays, objects...) per JSON document, which bounds the memory a parse can take
/// (about 100 bytes a value) whatever the file holds.
constexpr std::size_t kMaxBodies = 100000;
constexpr std::size_t kMaxJoints = 100000;
constexpr std::size_t kMaxForces = 100000;
constexpr std::size_t kMaxQueryPairs = 1000000;
constexpr std::size_t kMaxFileBytes = std::size_t(64) << 20;
/// A mesh's vertices and triangles, a height field's samples and a compound's children: a
/// 2000 x 2000 terrain, or a level of two million triangles.
constexpr std::size_t kMaxMeshVertices = 2000000;
constexpr std::size_t kMaxMeshTriangles = 2000000;
constexpr std::size_t kMaxHeightSamples = 4000000;
constexpr std::size_t kMaxCompoundChildren = 1000;
constexpr std::size_t kMaxJsonValues = 4000000;

}  // namespace stepwise
