#include "10_speed/contact_solver.h"
#include "10_speed/iteration_plan.h"

#include "01_integrators/forces.h"
#include "01_integrators/integrate.h"
#include "01_integrators/methods.h"
#include "01_integrators/rotation.h"
#include "03_epa/chapter.h"
#include "04_pgs/contact_constraints.h"
#include "06_manifolds/stabilisation.h"
#include "10_speed/colouring.h"
#include "10_speed/contact_kernels.h"
#include "10_speed/gyroscopic_pack.h"
#include "10_speed/sleep.h"
#include "10_speed/wide_solver.h"

#include <algorithm>
#include <tuple>
#include <array>
#include <chrono>
#include <cmath>

namespace stepwise {

const char* toString(SolverPath path) { return path == SolverPath::Wide ? "wide" : "scalar"; }

bool fastSolveApplies(const World& world, std::string* why) {
    auto refuse = [&](const char* reason) {
        if (why) *why = reason;
        return false;
    };
    const Settings& settings = world.settings;
    if (!isSubstepped(settings.stabilisation)) return refuse("the stabilisation is not relax or soft_step");
    if (settings.solver != SolverKind::GaussSeidel) return refuse("the solver is Jacobi");
    if (settings.gyroscopic == GyroscopicMode::Explicit) return refuse("the gyroscopic term is explicit");
    if (settings.integrator != IntegratorKind::SemiImplicitEuler) return refuse("the integrator is not semi-implicit Euler");
    if (!world.joints.empty()) return refuse("the scene has joints");
    if (!world.springs.empty()) return refuse("the scene has springs");
    if (!world.dampings.empty()) return refuse("the scene has dampings");
    for (const Motion& motion : world.motions) {
        if (motion.integrator && *motion.integrator != IntegratorKind::SemiImplicitEuler)
            return refuse("a body uses another integrator");
        if (world.bodies[static_cast<std::size_t>(motion.bodyIndex)].type == BodyType::Kinematic)
            return refuse("the scene has kinematic bodies");
    }
    return true;
}

namespace {

// [ch10-prepare-bodies]
void prepareBodies(const World& world, SolverBodies& bodies) {
    bodies.states.assign(1, SolverBodyState{});  // slot 0: everything that does not move
    bodies.info.assign(1, SolverBodyInfo{});
    bodies.slotOfBody.assign(world.bodies.size(), 0);
    bodies.gyroscopic.clear();
    for (const Motion& motion : world.motions) {
        const Body& body = world.bodies[static_cast<std::size_t>(motion.bodyIndex)];
        if (body.type != BodyType::Dynamic || motion.asleep) continue;
        bodies.slotOfBody[static_cast<std::size_t>(motion.bodyIndex)] = static_cast<int>(bodies.states.size());
        SolverBodyState state;
        for (int k = 0; k < 3; ++k) {
            state.linearVelocity[k] = motion.linearVelocity[k];
            state.angularVelocity[k] = motion.angularVelocity[k];
        }
        bodies.states.push_back(state);
        SolverBodyInfo info;
        info.bodyIndex = motion.bodyIndex;
        info.inverseMass = motion.inverseMass;
        info.inverseInertia = worldInverseInertia(body, motion);
        info.startCenter = body.transform.apply(motion.localCenter);
        info.startRotation = body.transform.rotation;
        const Mat3& inertia = motion.inertiaLocal;
        if (!(inertia - Mat3::Identity() * inertia(0, 0)).isZero(0)) {
            const Quat& start = info.startRotation;
            bodies.gyroscopic.push_back(GyroscopicBody{
                static_cast<int>(bodies.info.size()),
                {start.x(), start.y(), start.z(), start.w()},
                {inertia(0, 0), inertia(1, 1), inertia(2, 2), inertia(0, 1), inertia(0, 2), inertia(1, 2)}});
        }
        bodies.info.push_back(info);
    }
}
// [ch10-prepare-bodies]

template <int N>
void setLane(PackVec3<N>& pack, int lane, const Vec3& value) {
    pack.x[lane] = value.x();
    pack.y[lane] = value.y();
    pack.z[lane] = value.z();
}

template <int N>
void setLane(PackSym3<N>& pack, int lane, const Mat3& m) {
    pack.xx[lane] = m(0, 0);
    pack.yy[lane] = m(1, 1);
    pack.zz[lane] = m(2, 2);
    pack.xy[lane] = m(0, 1);
    pack.xz[lane] = m(0, 2);
    pack.yz[lane] = m(1, 2);
}

// [ch10-prepare-contact]
/// Fills one lane of a block from a contact record: what the block takes as it is (the bodies'
/// slots, masses and inertias, the material), and into `inputs` what fillBlockFields turns into
/// the rest (the arms, the friction basis, the carried impulses) for all lanes at once.
template <int N>
void fillLane(ManifoldBlock<N>& block, LaneInputs<N>& inputs, int lane, const World& world, int contactIndex,
              const SolverBodies& bodies, const ContactSolveParams& params) {
    const Contact& contact = world.contacts[static_cast<std::size_t>(contactIndex)];
    const int slotA = bodies.slotOfBody[static_cast<std::size_t>(contact.bodyA)];
    const int slotB = bodies.slotOfBody[static_cast<std::size_t>(contact.bodyB)];
    const SolverBodyInfo& infoA = bodies.info[static_cast<std::size_t>(slotA)];
    const SolverBodyInfo& infoB = bodies.info[static_cast<std::size_t>(slotB)];
    const Body& bodyA = world.bodies[static_cast<std::size_t>(contact.bodyA)];
    const Body& bodyB = world.bodies[static_cast<std::size_t>(contact.bodyB)];
    // A static body's centre is its origin (slot 0 has none): arms only matter for bodies that move.
    setLane(inputs.centerA, lane, slotA ? infoA.startCenter : worldCenterOfMass(world, contact.bodyA));
    setLane(inputs.centerB, lane, slotB ? infoB.startCenter : worldCenterOfMass(world, contact.bodyB));
    setLane(inputs.normal, lane, contact.normal);
    // The arms reach each body's core: a sphere's centre, a capsule's segment (radius 0 for boxes
    // and hulls). Along the normal the arms change no row (every use is n . (w x arm) or arm x n),
    // but pointSeparations turns them with the bodies, and a point on a round surface does not
    // turn with its body: the ball's lowest point stays lowest as it rolls. Turned with the ball,
    // the material point rose r (1 - cos w h) a substep, a false gap the solve let the ball fall
    // into (a ball rolling at 2 m/s kept 8 cm/s of downward speed).
    inputs.roundA[lane] = roundRadius(bodyA.shape);
    inputs.roundB[lane] = roundRadius(bodyB.shape);
    inputs.pointCount[lane] = static_cast<Real>(contact.pointCount);
    for (int i = 0; i < contact.pointCount; ++i) {
        typename LaneInputs<N>::Point& input = inputs.point[i];
        const ContactPoint& point = contact.points[i];
        setLane(input.pointA, lane, point.pointA);
        setLane(input.pointB, lane, point.pointB);
        input.depth[lane] = point.depth;
        input.normalImpulse[lane] = point.normalImpulse;
        input.tangentImpulse1[lane] = point.tangentImpulse[0];
        input.tangentImpulse2[lane] = point.tangentImpulse[1];
    }

    block.slotA[lane] = slotA;
    block.slotB[lane] = slotB;
    block.contactIndex[lane] = contactIndex;
    block.pointCount[lane] = contact.pointCount;
    const Real friction = combinedFriction(bodyA.material, bodyB.material);
    block.friction[lane] = inputs.friction[lane] = friction;
    block.restitution[lane] = combinedRestitution(bodyA.material, bodyB.material);
    // A rolling ball is held back by a torque of c r N (Box2D v3 takes the larger body's too).
    block.rollingLength[lane] = std::max(bodyA.material.rollingResistance * inputs.roundA[lane],
                                         bodyB.material.rollingResistance * inputs.roundB[lane]);
    setLane(block.rollingImpulse, lane, Vec3::Zero());  // not carried between frames
    block.inverseMassA[lane] = infoA.inverseMass;
    block.inverseMassB[lane] = infoB.inverseMass;
    setLane(block.inverseInertiaA, lane, infoA.inverseInertia);
    setLane(block.inverseInertiaB, lane, infoB.inverseInertia);
    const bool againstStatic = slotA == 0 || slotB == 0;
    block.biasRate[lane] = againstStatic ? params.staticBiasRate : params.dynamicBiasRate;
    block.massScale[lane] = againstStatic ? params.staticMassScale : params.dynamicMassScale;
    block.impulseScale[lane] = againstStatic ? params.staticImpulseScale : params.dynamicImpulseScale;
}

/// A lane of no contact in the inputs: a unit normal and no points (emptyLane then writes the
/// block's lane).
template <int N>
void emptyInputs(LaneInputs<N>& inputs, int lane) {
    setLane(inputs.normal, lane, Vec3::UnitY());
    setLane(inputs.centerA, lane, Vec3::Zero());
    setLane(inputs.centerB, lane, Vec3::Zero());
    inputs.roundA[lane] = inputs.roundB[lane] = inputs.pointCount[lane] = inputs.friction[lane] = 0;
}

/// One contact's scalar block, filled whole.
void fillScalarBlock(ManifoldBlock<1>& block, const World& world, int contactIndex, const SolverBodies& bodies,
                     const ContactSolveParams& params) {
    LaneInputs<1> inputs{};  // zeros where the contact has no point
    fillLane(block, inputs, 0, world, contactIndex, bodies, params);
    fillBlockFields(block, inputs, params.carryScale, world.settings.warmStarting);
}
// [ch10-prepare-contact]

template <int N>
void emptyLane(ManifoldBlock<N>& block, int lane) {
    block.slotA[lane] = block.slotB[lane] = 0;
    block.contactIndex[lane] = -1;
    block.pointCount[lane] = 0;
    block.friction[lane] = block.restitution[lane] = block.rollingLength[lane] = 0;
    setLane(block.rollingImpulse, lane, Vec3::Zero());
    block.inverseMassA[lane] = block.inverseMassB[lane] = 0;
    setLane(block.inverseInertiaA, lane, Mat3::Zero());
    setLane(block.inverseInertiaB, lane, Mat3::Zero());
    block.biasRate[lane] = block.impulseScale[lane] = 0;
    block.massScale[lane] = 1;
    block.shockGroup[lane] = 0;
    block.heldA[lane] = block.heldB[lane] = 0;
    setLane(block.normal, lane, Vec3::UnitY());
    setLane(block.tangent1, lane, Vec3::UnitX());
    setLane(block.tangent2, lane, Vec3::UnitZ());
    setLane(block.centerArmA, lane, Vec3::Zero());
    setLane(block.centerArmB, lane, Vec3::Zero());
    block.tangentInverse11[lane] = block.tangentInverse12[lane] = block.tangentInverse22[lane] = 0;
    block.twistMass[lane] = 0;
    block.tangentImpulse1[lane] = block.tangentImpulse2[lane] = block.twistImpulse[lane] = 0;
    for (ManifoldPointPack<N>& p : block.point) {
        setLane(p.armA, lane, Vec3::Zero());
        setLane(p.armB, lane, Vec3::Zero());
        p.adjustedSeparation[lane] = p.normalMass[lane] = p.normalImpulse[lane] = p.twistRadius[lane] = 0;
        p.approachSpeed[lane] = p.maxNormalImpulse[lane] = p.offset1[lane] = p.offset2[lane] = 0;
    }
}

// [ch10-store]
/// Writes the impulses back to the contact points, where every chapter keeps them (chapter 6
/// carries them from point to point, chapter 9 shows them): the centre's friction force F shared
/// equally, plus the twist tau as forces around the centre, f_i = F / n + tau (n x d_i) / sum |d_i|^2
/// with d_i the point's offset from the centre, which add up to exactly F and tau again when
/// fillLane reads them next frame. In the tangent basis, n x d = (-d2, d1).
template <int N>
void storeBlock(const ManifoldBlock<N>& block, World& world) {
    for (int lane = 0; lane < N; ++lane) {
        if (block.contactIndex[lane] < 0) continue;
        Contact& contact = world.contacts[static_cast<std::size_t>(block.contactIndex[lane])];
        const int count = contact.pointCount;
        Real spread = 0;
        for (int i = 0; i < count; ++i)
            spread += block.point[i].offset1[lane] * block.point[i].offset1[lane] +
                      block.point[i].offset2[lane] * block.point[i].offset2[lane];
        const Real twist = spread > 0 ? block.twistImpulse[lane] / spread : 0;
        const Real share1 = block.tangentImpulse1[lane] / static_cast<Real>(count);
        const Real share2 = block.tangentImpulse2[lane] / static_cast<Real>(count);
        for (int i = 0; i < count; ++i) {
            ContactPoint& point = contact.points[i];
            const ManifoldPointPack<N>& p = block.point[i];
            point.normalImpulse = p.normalImpulse[lane];
            point.normalMass = p.normalMass[lane];
            point.tangentImpulse[0] = share1 - twist * p.offset2[lane];
            point.tangentImpulse[1] = share2 + twist * p.offset1[lane];
        }
    }
}
// [ch10-store]

ContactSolveParams solveParams(const Settings& settings, Real h) {
    ContactSolveParams params;
    params.substep = h;
    params.slop = settings.slop;
    params.maxPushOutSpeed = kMaxPushOutSpeed;
    params.restitutionThreshold = settings.restitutionThreshold;
    if (settings.stabilisation == Stabilisation::SoftStep) {
        // Chapter 6's soft contacts: Box2D v3's 30 Hz (at most a quarter of the substep rate),
        // twice as stiff against a body that cannot move.
        const Real hertz = std::min(kContactHertz, Real(0.25) / h);
        const Softness dynamicSoft = makeSoftness(hertz, kContactDampingRatio, h);
        const Softness staticSoft = makeSoftness(2 * hertz, kContactDampingRatio, h);
        params.dynamicBiasRate = dynamicSoft.biasRate;
        params.dynamicMassScale = dynamicSoft.massScale;
        params.dynamicImpulseScale = dynamicSoft.impulseScale;
        params.staticBiasRate = staticSoft.biasRate;
        params.staticMassScale = staticSoft.massScale;
        params.staticImpulseScale = staticSoft.impulseScale;
    } else {  // relax: Baumgarte's fraction per substep, rigid rows
        params.dynamicBiasRate = params.staticBiasRate = settings.baumgarte / h;
    }
    return params;
}

// [ch10-integrate]
void integrateVelocities(World& world, SolverBodies& bodies, Real h, bool firstSubstep, SolverPath path) {
    const Vec3 gravity = world.settings.gravity;
    // Chapter 1's order: the gyroscopic step, then the torque (each body's own; bodies do not interact here).
    if (world.settings.gyroscopic == GyroscopicMode::Implicit) {
        if (path == SolverPath::Wide) {
            gyroscopicStepWide(bodies.states.data(), bodies.gyroscopic, h);
        } else {
            for (const GyroscopicBody& body : bodies.gyroscopic) gyroscopicStepPack<1>(bodies.states.data(), &body, h);
        }
    }
    for (std::size_t slot = 1; slot < bodies.states.size(); ++slot) {
        SolverBodyState& state = bodies.states[slot];
        const SolverBodyInfo& info = bodies.info[slot];
        Vec3 acceleration = gravity;
        if (firstSubstep) {  // a user's push, held for the frame's first substep as chapter 6 does
            Motion& motion = *world.motionOf(info.bodyIndex);
            acceleration += info.inverseMass * motion.force;
            const Vec3 spin = h * (info.inverseInertia * motion.torque);
            for (int k = 0; k < 3; ++k) state.angularVelocity[k] += spin[k];
            motion.force = motion.torque = Vec3::Zero();
        }
        for (int k = 0; k < 3; ++k) state.linearVelocity[k] += h * acceleration[k];
    }
}

void integratePositions(SolverBodies& bodies, Real h, SolverPath path) {
    const int count = static_cast<int>(bodies.states.size());
    if (path == SolverPath::Wide) return integratePositionsWide(bodies.states.data(), count, h);
    for (int slot = 1; slot < count; ++slot) integratePositionsPack<1>(bodies.states.data(), &slot, h);
}

void writeBodiesBack(World& world, const SolverBodies& bodies) {
    for (std::size_t slot = 1; slot < bodies.states.size(); ++slot) {
        const SolverBodyState& state = bodies.states[slot];
        const SolverBodyInfo& info = bodies.info[slot];
        Motion& motion = *world.motionOf(info.bodyIndex);
        Transform& pose = world.bodies[static_cast<std::size_t>(info.bodyIndex)].transform;
        const Quat delta(state.deltaRotation[3], state.deltaRotation[0], state.deltaRotation[1], state.deltaRotation[2]);
        const Vec3 center = info.startCenter + Vec3(state.deltaPosition[0], state.deltaPosition[1], state.deltaPosition[2]);
        pose.rotation = (delta * info.startRotation).normalized();
        pose.position = center - pose.rotation * motion.localCenter;
        motion.linearVelocity = Vec3(state.linearVelocity[0], state.linearVelocity[1], state.linearVelocity[2]);
        motion.angularVelocity = Vec3(state.angularVelocity[0], state.angularVelocity[1], state.angularVelocity[2]);
    }
}
// [ch10-integrate]

bool usableContact(const World& world, const Contact& contact, const SolverBodies& bodies) {
    const int count = static_cast<int>(world.bodies.size());
    if (contact.bodyA < 0 || contact.bodyB < 0 || contact.bodyA >= count || contact.bodyB >= count) return false;
    if (contact.pointCount <= 0 || contact.pointCount > 4 || contact.bodyA == contact.bodyB) return false;
    if (!contact.normal.allFinite() || std::abs(contact.normal.norm() - 1) > Real(1e-3)) return false;
    for (int i = 0; i < contact.pointCount; ++i)
        if (!contact.points[i].pointA.allFinite() || !contact.points[i].pointB.allFinite() ||
            !std::isfinite(contact.points[i].depth))
            return false;
    return bodies.slotOfBody[static_cast<std::size_t>(contact.bodyA)] != 0 ||
           bodies.slotOfBody[static_cast<std::size_t>(contact.bodyB)] != 0;
}

/// Colours the contacts (colourContacts) and counts each colour's. A colour of one contact gives
/// it to the overflow: a wide block for one contact gathers, solves and scatters eight lanes for
/// it, and a ball rolling on the ground stepped 10% faster with a scalar block (1.24 against
/// 1.38 us a frame); from two contacts on the wide block is as fast or faster.
std::array<int, kMaxColours> colourForBlocks(ContactSolverScratch& scratch) {
    colourContacts(scratch.slotA, scratch.slotB, static_cast<int>(scratch.bodies.states.size()), scratch.colours,
                   scratch.colourBits);
    std::array<int, kMaxColours> counts{};
    for (const int colour : scratch.colours)
        if (colour >= 0) ++counts[static_cast<std::size_t>(colour)];
    for (int& colour : scratch.colours)
        if (colour >= 0 && counts[static_cast<std::size_t>(colour)] == 1) {
            counts[static_cast<std::size_t>(colour)] = 0;
            colour = -1;
        }
    return counts;
}

/// The coloured contacts in the order their lanes are filled: colour by colour, and within a
/// colour by the shock sweep's group (0 first: not swept). A colour's lanes share no body, so
/// their order changes no bit of the solve; it puts a group's lanes side by side, and the sweep
/// solves each group over the few blocks that hold it (solveHeldBlock). Two stable counting sorts.
void orderLanes(ContactSolverScratch& scratch) {
    std::vector<int>& byGroup = scratch.laneScratch;
    std::vector<int>& lanes = scratch.laneOrder;
    std::vector<int>& start = scratch.laneBuckets;
    const auto countingSort = [&](const std::vector<int>& from, std::vector<int>& to, int buckets, const std::vector<int>& key) {
        start.assign(static_cast<std::size_t>(buckets) + 1, 0);
        for (const int i : from) ++start[static_cast<std::size_t>(key[static_cast<std::size_t>(i)]) + 1];
        for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
        to.resize(from.size());
        for (const int i : from) to[static_cast<std::size_t>(start[static_cast<std::size_t>(key[static_cast<std::size_t>(i)])]++)] = i;
    };
    lanes.clear();
    for (std::size_t i = 0; i < scratch.contactOrder.size(); ++i)
        if (scratch.colours[i] >= 0) lanes.push_back(static_cast<int>(i));
    if (scratch.shockGroups > 0) {
        countingSort(lanes, byGroup, scratch.shockGroups + 1, scratch.shockGroupOf);
        std::swap(lanes, byGroup);
    }
    countingSort(lanes, byGroup, kMaxColours, scratch.colours);
    std::swap(lanes, byGroup);
}

/// A lane's place in the shock sweep (groupShockSweep): its group and which body it holds still.
template <int N>
void setShockLane(ManifoldBlock<N>& block, int lane, const ContactSolverScratch& scratch, std::size_t i) {
    const int group = scratch.shockGroups > 0 ? scratch.shockGroupOf[i] : 0;
    const bool heldIsA = group > 0 && scratch.shockHeldIsA[i] != 0;
    block.shockGroup[lane] = group;
    block.heldA[lane] = heldIsA ? Real(1) : Real(0);
    block.heldB[lane] = group > 0 && !heldIsA ? Real(1) : Real(0);
}

// [ch10-wide-blocks]
/// Colours the contacts and packs each colour kWideLanes at a time (orderLanes); the overflow goes
/// to scratch.scalarBlocks.
void buildWideBlocks(const World& world, ContactSolverScratch& scratch, const ContactSolveParams& params) {
    const std::vector<int>& order = scratch.contactOrder;
    colourForBlocks(scratch);
    orderLanes(scratch);
    scratch.wideBlocks.clear();
    scratch.scalarBlocks.clear();
    LaneInputs<kWideLanes>& inputs = scratch.laneInputs;
    const auto finishBlock = [&](int lanes) {  // the lanes' shared arithmetic, then the empty ones
        for (int lane = lanes; lane < kWideLanes; ++lane) emptyInputs(inputs, lane);
        fillWide(scratch.wideBlocks.back(), inputs, params.carryScale, world.settings.warmStarting);
        for (int lane = lanes; lane < kWideLanes; ++lane) emptyLane(scratch.wideBlocks.back(), lane);
    };
    int lane = kWideLanes, blockColour = -1;
    for (const int contact : scratch.laneOrder) {
        const auto i = static_cast<std::size_t>(contact);
        if (lane == kWideLanes || scratch.colours[i] != blockColour) {  // a block per colour's kWideLanes
            if (lane < kWideLanes) finishBlock(lane);
            scratch.wideBlocks.emplace_back();
            lane = 0;
            blockColour = scratch.colours[i];
        }
        setShockLane(scratch.wideBlocks.back(), lane, scratch, i);
        fillLane(scratch.wideBlocks.back(), inputs, lane++, world, order[i], scratch.bodies, params);
        if (lane == kWideLanes) finishBlock(lane);
    }
    if (lane < kWideLanes) finishBlock(lane);
    for (std::size_t i = 0; i < order.size(); ++i) {
        if (scratch.colours[i] >= 0) continue;
        scratch.scalarBlocks.emplace_back();
        fillScalarBlock(scratch.scalarBlocks.back(), world, order[i], scratch.bodies, params);
        setShockLane(scratch.scalarBlocks.back(), 0, scratch, i);
    }
}
// [ch10-wide-blocks]

/// The scalar path's blocks, one contact each, in the wide path's order: colour by colour, then
/// the overflow. Lanes of a wide block share no body, nor do the blocks of one colour, so the wide
/// sweep is this sweep done eight contacts at a time, and the two paths give the same bits (no
/// lane's answer depends on the lanes beside it): what the scalar solve measures is the lanes alone.
void buildScalarBlocks(const World& world, ContactSolverScratch& scratch, const ContactSolveParams& params) {
    const std::vector<int>& order = scratch.contactOrder;
    const std::array<int, kMaxColours> counts = colourForBlocks(scratch);
    scratch.wideBlocks.clear();
    scratch.scalarBlocks.resize(order.size());
    std::size_t next = 0;
    const auto fill = [&](std::size_t i) {
        setShockLane(scratch.scalarBlocks[next], 0, scratch, i);
        fillScalarBlock(scratch.scalarBlocks[next++], world, order[i], scratch.bodies, params);
    };
    for (int colour = 0; colour < kMaxColours; ++colour) {
        if (counts[static_cast<std::size_t>(colour)] == 0) continue;
        for (std::size_t i = 0; i < order.size(); ++i)
            if (scratch.colours[i] == colour) fill(i);
    }
    for (std::size_t i = 0; i < order.size(); ++i)
        if (scratch.colours[i] < 0) fill(i);
}

// [ch10-shock-groups]
/// The shock sweep's groups (orderShockSweep, in the sweep's order, numbered from 1) of the
/// contacts whose two bodies were slow when the frame began (isSlow, the sleep test), and which of
/// each contact's bodies is the lower one, held still. Set before the blocks are filled: each lane
/// carries its group (setShockLane), and the blocks are prepared for the sweep as well
/// (prepareHeld), so that the sweep needs no blocks of its own.
void groupShockSweep(const World& world, ContactSolverScratch& scratch) {
    const SolverBodies& bodies = scratch.bodies;
    const std::vector<int>& depth = scratch.stackSearch.depth;  // this frame's (plannedIterations)
    const std::size_t moving = bodies.states.size();
    std::vector<int>& slotDepth = scratch.slotDepth;
    slotDepth.assign(moving, 0);
    for (std::size_t slot = 1; slot < moving; ++slot) {
        const auto body = static_cast<std::size_t>(bodies.info[slot].bodyIndex);
        slotDepth[slot] = body < depth.size() ? depth[body] : 0;
    }
    const ShockOrder& order = scratch.shockOrder;
    orderShockSweep(scratch.slotA, scratch.slotB, slotDepth, scratch.shockOrder);
    std::vector<std::uint8_t>& slow = scratch.slowSlot;
    slow.assign(moving, 0);
    for (std::size_t slot = 1; slot < moving; ++slot) slow[slot] = isSlow(world, bodies.info[slot].bodyIndex) ? 1 : 0;
    scratch.shockGroupOf.assign(scratch.contactOrder.size(), 0);
    scratch.shockHeldIsA.assign(scratch.contactOrder.size(), 0);
    scratch.shockGroups = static_cast<int>(order.groupStart.size()) - 1;
    for (std::size_t group = 0; group + 1 < order.groupStart.size(); ++group) {
        for (int k = order.groupStart[group]; k < order.groupStart[group + 1]; ++k) {
            const auto i = static_cast<std::size_t>(order.entries[static_cast<std::size_t>(k)]);
            if (!slow[static_cast<std::size_t>(scratch.slotA[i])] || !slow[static_cast<std::size_t>(scratch.slotB[i])]) continue;
            scratch.shockGroupOf[i] = static_cast<int>(group) + 1;
            scratch.shockHeldIsA[i] = order.lowerIsA[static_cast<std::size_t>(k)];
        }
    }
}

/// The sweep's visits: every block holding lanes of a group, once per group it holds, in the
/// groups' order (a stable counting sort; a group's lanes are independent, so the blocks' order
/// within it changes no bit). A wide block holds one colour's lanes sorted by group (orderLanes).
void orderShockVisits(ContactSolverScratch& scratch) {
    std::vector<ShockVisit>& visits = scratch.shockScratch;
    visits.clear();
    for (std::size_t b = 0; b < scratch.wideBlocks.size(); ++b) {
        int last = 0;
        for (const int group : scratch.wideBlocks[b].shockGroup)
            if (group > 0 && group != last) visits.push_back({true, b, last = group});
    }
    for (std::size_t b = 0; b < scratch.scalarBlocks.size(); ++b)
        if (const int group = scratch.scalarBlocks[b].shockGroup[0]; group > 0) visits.push_back({false, b, group});
    std::vector<int>& start = scratch.laneBuckets;
    start.assign(static_cast<std::size_t>(scratch.shockGroups) + 2, 0);
    for (const ShockVisit& visit : visits) ++start[static_cast<std::size_t>(visit.group) + 1];
    for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
    scratch.shockVisits.resize(visits.size());
    for (const ShockVisit& visit : visits)
        scratch.shockVisits[static_cast<std::size_t>(start[static_cast<std::size_t>(visit.group)]++)] = visit;
}
// [ch10-shock-groups]

template <int N>
void warmStartAll(std::vector<ManifoldBlock<N>>& blocks, SolverBodyState* states) {
    for (ManifoldBlock<N>& block : blocks) warmStartBlock(block, states);
}
template <int N>
void solveAll(std::vector<ManifoldBlock<N>>& blocks, SolverBodyState* states, const ContactSolveParams& params,
              bool useBias) {
    for (ManifoldBlock<N>& block : blocks) solveBlock(block, states, params, useBias);
}
template <int N>
void restitutionAll(std::vector<ManifoldBlock<N>>& blocks, SolverBodyState* states, Real threshold) {
    for (ManifoldBlock<N>& block : blocks) restitutionBlock(block, states, threshold);
}

template <int N>
bool collideAll(std::vector<ManifoldBlock<N>>& blocks, SolverBodyState* states, const ContactSolveParams& params) {
    bool struck = false;
    for (ManifoldBlock<N>& block : blocks) struck = collideBlock(block, states, params) || struck;
    return struck;
}
template <int N>
bool anyRestitution(const std::vector<ManifoldBlock<N>>& blocks) {
    for (const ManifoldBlock<N>& block : blocks)
        for (int lane = 0; lane < N; ++lane)
            if (block.restitution[lane] > 0) return true;
    return false;
}

/// Collision sweeps a substep at most: a row of this many touching balls passes an impact on.
constexpr int kCollisionSweeps = 16;

template <int N>
void resetImpulses(std::vector<ManifoldBlock<N>>& blocks) {
    for (ManifoldBlock<N>& block : blocks) {
        for (ManifoldPointPack<N>& p : block.point) p.normalImpulse = Pack<N>::splat(0);
        block.tangentImpulse1 = block.tangentImpulse2 = block.twistImpulse = Pack<N>::splat(0);
        block.rollingImpulse = PackVec3<N>{Pack<N>::splat(0), Pack<N>::splat(0), Pack<N>::splat(0)};
    }
}

/// The solve's phase times: one clock read per phase, and none unless asked for (at about 25 ns a
/// read, the forty reads of ten substeps were a third of a one-ball step).
class PhaseClock {
public:
    explicit PhaseClock(bool on) : on_(on) {
        if (on_) last_ = std::chrono::steady_clock::now();
    }
    /// Milliseconds since the last lap (0 when off).
    double lap() {
        if (!on_) return 0;
        const auto now = std::chrono::steady_clock::now();
        const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
        last_ = now;
        return ms;
    }

private:
    bool on_;
    std::chrono::steady_clock::time_point last_{};
};

/// Bodies that touch nothing, each through all the substeps at once: chapter 1's semi-implicit
/// Euler for the velocities and the turn, without gathering every body's state and forces again
/// each substep (which cost a one-body scene more than its integration), and the centre moved
/// along its exact parabola. The fast solve takes no springs, dampings or kinematic bodies, so
/// each body feels its weight and the user's force only, constant through the frame (a kinematic
/// body added since the plan takes chapter 1's functions).
void moveFreeBodies(World& world, Real h, int substeps) {
    const bool allDynamic = std::all_of(world.motions.begin(), world.motions.end(), [&](const Motion& motion) {
        return world.bodies[static_cast<std::size_t>(motion.bodyIndex)].type == BodyType::Dynamic;
    });
    if (!allDynamic) {
        for (int substep = 0; substep < substeps; ++substep) {
            applyForces(world);
            stepwise::integrateVelocities(world, h);
            stepwise::integratePositions(world, h);
        }
        return;
    }
    const GyroscopicMode gyroscopic = world.settings.gyroscopic;
    for (Motion& motion : world.motions) {
        const Body& body = world.bodies[static_cast<std::size_t>(motion.bodyIndex)];
        const Vec3 weight = motion.mass * world.settings.gravity;
        for (int substep = 0; substep < substeps; ++substep) {
            motion.force += weight;
            MotionState state = readMotionState(world, motion);
            const Vec3 velocityBefore = state.linearVelocity;
            eulerVelocityStep(motion, worldInverseInertia(body, motion), Wrench{motion.force, motion.torque}, gyroscopic,
                              h, state);
            motion.linearVelocity = state.linearVelocity;
            motion.angularVelocity = state.angularVelocity;
            motion.force = motion.torque = Vec3::Zero();
            eulerPositionStep(h, state);
            // [ch10-free-flight]
            // The force is the same all through the substep, so the centre's path is the parabola
            // x0 + v0 h + a h^2 / 2: it moves by the mean of the two velocities, where Euler's
            // step moved it by the new one, h (v1 - v0) / 2 too far. One substep is then exact.
            state.center -= (h / 2) * (state.linearVelocity - velocityBefore);
            // [ch10-free-flight]
            writeMotionState(world, motion, state);
        }
    }
}

}  // namespace

void addPhaseTimes(FastSolveStats& total, const FastSolveStats& frame) {
    total.bodies = frame.bodies;
    total.manifolds = frame.manifolds;
    total.points = frame.points;
    total.wideBlocks = frame.wideBlocks;
    total.overflow = frame.overflow;
    for (std::size_t phase = 0; phase < kSolvePhaseCount; ++phase) total.phaseMs[phase] += frame.phaseMs[phase];
}

// [ch10-solve-fast]
void solveFast(World& world, Real dt, SolverPath path, ContactSolverScratch& scratch) {
    if (!(dt > 0) || !std::isfinite(dt)) return;
    scratch.stats = FastSolveStats{};
    FastSolveStats& stats = scratch.stats;
    PhaseClock clock(scratch.timePhases);
    // Contacts found at an earlier substep of the frame (Settings::substeps > 1, collision once per
    // frame) are where their bodies were then: their points move with the bodies first.
    if (world.step.substep > 0 && world.step.contactsFoundAtSubstep < world.step.substep) followContactAnchors(world);
    scratch.contactOrder.clear();
    scratch.slotA.clear();
    scratch.slotB.clear();
    if (everyBodyAsleep(world)) {  // nothing to gather, solve or move (the fast solve has no kinematic body)
        stats.bodies = 0;
        world.step.solver = SolverStats{};
        world.step.velocitiesBeforeForces.clear();
        return;
    }
    const bool allAwakeDynamic = std::all_of(world.motions.begin(), world.motions.end(), [&](const Motion& motion) {
        return !motion.asleep && world.bodies[static_cast<std::size_t>(motion.bodyIndex)].type == BodyType::Dynamic;
    });
    if (world.contacts.empty() && allAwakeDynamic) {
        // Nothing touches: no solver state to gather, the bodies move on their own (below).
        stats.bodies = static_cast<int>(world.motions.size());
        const int substeps = plannedIterations(world, dt, scratch.contactOrder, world.step.iterationPlan, scratch.stackSearch);
        moveFreeBodies(world, dt / static_cast<Real>(substeps), substeps);
        world.step.solver = SolverStats{};
        world.step.velocitiesBeforeForces.clear();
        return;
    }
    prepareBodies(world, scratch.bodies);
    stats.bodies = static_cast<int>(scratch.bodies.states.size()) - 1;
    if (stats.bodies == 0) {  // everything sleeps (or cannot move): nothing to solve or move
        world.step.solver = SolverStats{};
        world.step.velocitiesBeforeForces.clear();
        return;
    }

    // The contacts that involve a moving body, in contact order (canonical: sorted by pair).
    SolverStats solverStats;
    for (std::size_t i = 0; i < world.contacts.size(); ++i) {
        const Contact& contact = world.contacts[i];
        if (!usableContact(world, contact, scratch.bodies)) {
            if (contact.pointCount > 0 && (contact.bodyA < 0 || contact.bodyB < 0 || contact.pointCount > 4 ||
                                           !contact.normal.allFinite()))
                solverStats.invalidSkipped += std::clamp(contact.pointCount, 1, 4);
            continue;
        }
        scratch.contactOrder.push_back(static_cast<int>(i));
        scratch.slotA.push_back(scratch.bodies.slotOfBody[static_cast<std::size_t>(contact.bodyA)]);
        scratch.slotB.push_back(scratch.bodies.slotOfBody[static_cast<std::size_t>(contact.bodyB)]);
        stats.points += contact.pointCount;
    }
    stats.manifolds = static_cast<int>(scratch.contactOrder.size());
    // Every body moves in the substeps, touching or not (chapter 6's solve says why).
    const int lastSubsteps = world.step.iterationPlan.iterations;  // 0 before the first frame
    const int substeps = plannedIterations(world, dt, scratch.contactOrder, world.step.iterationPlan, scratch.stackSearch,
                                           scratch.shockAllowed);
    const Real h = dt / static_cast<Real>(substeps);
    // Nothing touches and nothing sleeps: the bodies fly free (moveFreeBodies).
    if (stats.manifolds == 0 && stats.bodies == static_cast<int>(world.motions.size())) {
        moveFreeBodies(world, h, substeps);
        world.step.solver = solverStats;
        world.step.velocitiesBeforeForces.clear();
        return;
    }
    ContactSolveParams params = solveParams(world.settings, h);
    if (lastSubsteps > 0 && lastSubsteps != substeps)
        params.carryScale = static_cast<Real>(lastSubsteps) / static_cast<Real>(substeps);

    // The shock sweep's groups first: the blocks carry them (groupShockSweep).
    const bool shock = world.step.iterationPlan.shockPropagation;
    scratch.shockGroups = 0;
    if (shock) groupShockSweep(world, scratch);
    if (path == SolverPath::Wide) {
        buildWideBlocks(world, scratch, params);
    } else {
        buildScalarBlocks(world, scratch, params);
    }

    stats.wideBlocks = static_cast<int>(scratch.wideBlocks.size());
    stats.overflow = path == SolverPath::Wide ? static_cast<int>(scratch.scalarBlocks.size()) : 0;
    SolverBodyState* states = scratch.bodies.states.data();
    prepareWide(scratch.wideBlocks, states, shock);
    for (ManifoldBlock<1>& block : scratch.scalarBlocks) prepareBlock(block, states, shock);
    stats.ms(SolvePhase::Prepare) += clock.lap();

    const bool warmStarting = world.settings.warmStarting;
    // Scenes without restitution (most) have no collisions to sweep.
    const bool collisions = anyRestitution(scratch.wideBlocks) || anyRestitution(scratch.scalarBlocks);
    for (int substep = 0; substep < substeps; ++substep) {
        integrateVelocities(world, scratch.bodies, h, substep == 0, path);
        // [ch10-collisions-first]
        // Collisions first, on the speeds before the warm start adds last substep's pushes.
        for (int sweep = 0; collisions && sweep < kCollisionSweeps; ++sweep) {
            const bool struckWide = collideWide(scratch.wideBlocks, states, params);
            const bool struckScalar = collideAll(scratch.scalarBlocks, states, params);
            if (!struckWide && !struckScalar) break;
        }
        // [ch10-collisions-first]
        stats.ms(SolvePhase::Integrate) += clock.lap();
        if (!warmStarting) {
            resetImpulses(scratch.wideBlocks);
            resetImpulses(scratch.scalarBlocks);
        } else {
            warmStartWide(scratch.wideBlocks, states);
            warmStartAll(scratch.scalarBlocks, states);
        }
        stats.ms(SolvePhase::WarmStart) += clock.lap();
        solveWide(scratch.wideBlocks, states, params, /*useBias=*/true);
        solveAll(scratch.scalarBlocks, states, params, true);
        stats.ms(SolvePhase::Solve) += clock.lap();
        integratePositions(scratch.bodies, h, path);
        stats.ms(SolvePhase::Integrate) += clock.lap();
        solveWide(scratch.wideBlocks, states, params, /*useBias=*/false);  // relax
        solveAll(scratch.scalarBlocks, states, params, false);
        stats.ms(SolvePhase::Relax) += clock.lap();
    }
    // [ch10-shock-sweep]
    if (shock) {
        orderShockVisits(scratch);
        for (const ShockVisit& visit : scratch.shockVisits) {
            if (visit.wide)
                solveHeldWide(scratch.wideBlocks[visit.block], states, params, visit.group);
            else
                solveHeldBlock(scratch.scalarBlocks[visit.block], states, params, visit.group);
        }
    }
    // [ch10-shock-sweep]
    stats.ms(SolvePhase::Relax) += clock.lap();
    if (collisions) {  // some lane has restitution
        restitutionWide(scratch.wideBlocks, states, params.restitutionThreshold);
        restitutionAll(scratch.scalarBlocks, states, params.restitutionThreshold);
    }

    writeBodiesBack(world, scratch.bodies);
    for (const ManifoldBlock<kWideLanes>& block : scratch.wideBlocks) storeBlock(block, world);
    for (const ManifoldBlock<1>& block : scratch.scalarBlocks) storeBlock(block, world);

    stats.ms(SolvePhase::Store) += clock.lap();
    solverStats.contactPoints = stats.points;
    solverStats.rows = stats.points + 3 * stats.manifolds;  // normal rows, and three friction rows per manifold
    world.step.solver = solverStats;
    world.step.velocitiesBeforeForces.clear();
}
// [ch10-solve-fast]

}  // namespace stepwise
