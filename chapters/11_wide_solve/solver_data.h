#pragma once
// The data the fast step solves on, laid out for speed. Chapters 4 and 6 build a ConstraintRow per
// contact direction with both bodies' indices into the World and a full 3x3 inverse inertia per
// body, and rebuild them every substep. Here (as in Box3D and Jolt):
//
// - a body's hot state, the part every contact reads and writes, is 64 bytes, one cache line, in a
//   contiguous array (SolverBodyState); its cold data (mass, inertia, start pose) sits apart and
//   is read once per frame or substep (SolverBodyInfo);
// - a contact's data is built once per frame, for up to four points together (ManifoldBlock), and
//   the substeps only update each point's separation from how far its bodies moved;
// - manifolds are grouped N at a time, one per lane, into blocks whose lanes never share a moving
//   body (colouring.h), so N of them are solved with one stream of SIMD instructions.

#include "11_wide_solve/lanes.h"

#include <cstdint>
#include <vector>

namespace stepwise {

// [ch11-hot-cold]
/// What every contact row of a body reads and writes during a frame: one cache line.
struct alignas(64) SolverBodyState {
    Real linearVelocity[3] = {0, 0, 0};    // of the centre of mass, m/s
    Real angularVelocity[3] = {0, 0, 0};   // rad/s
    Real deltaPosition[3] = {0, 0, 0};     // centre of mass moved since the solve (its piece) began, m
    Real deltaRotation[4] = {0, 0, 0, 1};  // x y z w: turned since the solve (its piece) began
};

/// What the solve reads of a body once per frame or substep.
struct SolverBodyInfo {
    int bodyIndex = -1;                 // into World::bodies
    Real inverseMass = 0;
    Mat3 inverseInertia = Mat3::Zero(); // world axes at the frame's start (kept for the frame, as Box3D does)
    Vec3 startCenter = Vec3::Zero();    // centre of mass when the frame began
    Quat startRotation = Quat::Identity();
};
// [ch11-hot-cold]

/// What the gyroscopic step reads of a body whose inertia is not a multiple of the identity (where
/// w x I w can be non-zero; the others skip the step). Plain
/// Reals: the wide file reads it, and an Eigen member's alignment (a Quat of doubles) depends on
/// the instruction set a file is built for, so a struct holding one is laid out differently there.
/// The rotation first and the inertia after, 32-byte aligned: in the AVX2 float build eight of them
/// are two rows of eight floats each, gathered by a transpose (gyroscopic_pack.h).
struct alignas(32) GyroscopicBody {
    Real startRotation[4] = {0, 0, 0, 1};  // x y z w, as SolverBodyInfo::startRotation
    Real inertia[6] = {0, 0, 0, 0, 0, 0};  // body axes: xx yy zz xy xz yz
    int slot = 0;
};

/// The solver's bodies. Slot 0 is every static (and sleeping) body at once: zero velocity, zero
/// inverse mass. Slots 1 to firstDynamic - 1 are the kinematic bodies: zero inverse mass, but
/// their own velocity, which the rows read and the substeps move them by. Slots from firstDynamic
/// on are the awake dynamic bodies.
struct SolverBodies {
    int firstDynamic = 1;
    std::vector<SolverBodyState> states;
    std::vector<SolverBodyInfo> info;
    std::vector<int> slotOfBody;        // per World body; 0 when it does not move in this solve
    std::vector<GyroscopicBody> gyroscopic;  // in slot order
};

/// One contact point of a manifold, per lane.
template <int N>
struct ManifoldPointPack {
    PackVec3<N> armA, armB;          // contact point minus each centre of mass, at the frame's start, m
    PackVec3<N> turnA, turnB;        // what a unit normal impulse does to each angular velocity, I^-1 (arm x n)
                                     // (arm x n itself is not kept: normalAngulars)
    Pack<N> adjustedSeparation;      // separation at the frame's start minus normal . (armB - armA), m
    Pack<N> normalMass;              // effective mass of the normal row, kg; 0 for a missing point
    Pack<N> normalImpulse;           // accumulated, N s
    Pack<N> offset1, offset2;        // from the manifold's centre along tangent1 and tangent2, m
    Pack<N> twistRadius;             // distance from the manifold's centre in the contact plane, m
    Pack<N> approachSpeed;           // normal velocity when the frame began, or when its gap closed (restitution), m/s
    Pack<N> maxNormalImpulse;        // largest this frame: restitution only where the point pushed
};

/// The rows' effective masses as the solve reads them (prepareBlock): each normal row's alone, the
/// normal block's inverse (ManifoldBlock::normalBlockInverse), the tangent block's and the twist's.
template <int N>
struct RowMasses {
    Pack<N> normalMass[4];
    Pack<N> blockInverse[10];
    Pack<N> tangentInverse11, tangentInverse12, tangentInverse22;
    Pack<N> twistMass;
};

/// Whether a manifold of `pointCount` points is solved by its one row (solveSinglePoint) in a
/// block of such manifolds, rather than in a four-row block.
constexpr bool takesSinglePointRow(int pointCount) { return pointCount <= 1; }

/// Up to N manifolds solved side by side, one per lane.
template <int N>
struct ManifoldBlock {
    // Provided, and empty: value-initialisation (emplace_back()) of a block without it would zero
    // all of it first, kilobytes a block, for nothing: a frame fills every lane it solves
    // (fillLane, emptyLane), and prepareBlock derives the rest.
    ManifoldBlock() {}
    int slotA[N] = {};               // SolverBodies slots (0: static, sleeping or an empty lane)
    int slotB[N] = {};
    int contactIndex[N] = {};        // into World::contacts; -1 for an empty lane
    int pointCount[N] = {};
    bool singlePoint = false;        // every lane takes a single point's row (takesSinglePointRow)
    PackVec3<N> normal, tangent1, tangent2;
    Pack<N> friction, restitution;
    Pack<N> inverseMassA, inverseMassB;
    PackSym3<N> inverseInertiaA, inverseInertiaB;
    Pack<N> biasRate, massScale, impulseScale;  // position feedback of deep points (stabilisation)
    ManifoldPointPack<N> point[4];
    // Friction for the whole manifold at its centre (the mean of its points): two tangent rows
    // solved together, and a twist row about the normal. Coulomb's limits are those of the four
    // points sliding together: |tangent impulse| <= mu sum(lambda), |twist| <= mu sum(lambda r).
    PackVec3<N> centerArmA, centerArmB;         // centre minus each centre of mass, frame start, m
    PackVec3<N> frictionTurnA[2], frictionTurnB[2];        // I^-1 (centre arm x tangent k; tangentAngulars)
    PackVec3<N> twistTurnA, twistTurnB;                    // I^-1 n: what a unit twist does to each body
    Pack<N> tangentInverse11, tangentInverse12, tangentInverse22;  // the 2x2 tangent block's K^-1, kg
    Pack<N> twistMass;                          // 1 / (n . IA^-1 n + n . IB^-1 n), kg m^2
    Pack<N> tangentImpulse1, tangentImpulse2, twistImpulse;      // accumulated, N s and N m s
    // Rolling resistance (Material::rollingResistance): the bodies' relative turn, all three axes,
    // held back by an angular impulse of at most rollingLength times the manifold's load.
    Pack<N> rollingLength;                      // max over the two bodies of resistance x round radius, m
    PackSym3<N> rollingMass;                    // (IA^-1 + IB^-1)^-1, kg m^2; 0 where rollingLength is
    PackVec3<N> rollingImpulse;                 // accumulated this frame, N m s
    /// The inverse of the four normal rows' effective-mass matrix K (upper triangle: 00 01 02 03 11
    /// 12 13 22 23 33), K slightly regularised: a face's four corners make K singular (three
    /// independent directions, four rows), and (K + eps diag K)^-1 picks the least change of load.
    /// Constant over the frame (prepareNormalBlock).
    Pack<N> normalBlockInverse[10];
    /// The shock sweep's view of the lane (shock_propagation.h), prepared only in a frame that ends
    /// with it: the sweep's group the lane is solved in (0: not swept), which body is held still
    /// (1 where it is A or B), and the effective masses with that body infinitely heavy.
    int shockGroup[N] = {};
    Pack<N> heldA, heldB;
    RowMasses<N> heldMasses;
};

/// What filling a block reads of each lane's contact record, gathered lane by lane (fillLane), so
/// that the arithmetic that turns it into the block's fields runs on all lanes at once
/// (fillBlockFields). A point past a lane's pointCount keeps what an earlier lane left there:
/// fillBlockFields selects it away in every result.
template <int N>
struct LaneInputs {
    PackVec3<N> normal, centerA, centerB;  // centres of mass at the frame's start
    Pack<N> roundA, roundB;                // roundRadius of each shape
    Pack<N> pointCount, friction;
    struct Point {
        PackVec3<N> pointA, pointB;
        Pack<N> depth, normalImpulse, tangentImpulse1, tangentImpulse2;
    } point[4];
};

/// The regularisation of the normal block: 0.1% of each row's own effective mass.
constexpr Real kNormalBlockRegularisation = Real(1e-3);

/// Sweeps of a manifold's normal rows per pass, forwards then backwards, where the block solve
/// does not apply (a corner lifting off, a soft row). One sweep in one order leaves the first
/// corner pushing harder than the last, a torque that tilts a tall stack; sweeps in both
/// directions bring the corners close to one answer. Behind the block, which takes most of a
/// resting stack's manifolds, two keep the stack of 16 upright (docs/ch11_wide_solve.md).
constexpr int kNormalSweeps = 2;

/// The solve's knobs for one frame, from Settings and the stabilisation.
struct ContactSolveParams {
    Real substep = 0;                // h, s
    Real slop = 0;                   // m of penetration left alone
    Real maxPushOutSpeed = 0;        // m/s
    Real restitutionThreshold = 0;   // m/s
    Real staticBiasRate = 0, staticMassScale = 1, staticImpulseScale = 0;    // against a body that cannot move
    Real dynamicBiasRate = 0, dynamicMassScale = 1, dynamicImpulseScale = 0;
    /// What last frame's impulses are multiplied by before they warm start this frame: an
    /// impulse is a force times the substep, so when the planner changes the substep count the
    /// same force is last frame's count over this frame's times the impulse (1 when unchanged).
    Real carryScale = 1;
    Real mostSpin = 0;  // rad/s: the fastest a dynamic body spins in this solve (mostSpin in solve_steps.h)
};

}  // namespace stepwise
