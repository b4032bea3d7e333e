// Chapter 11's blocks: the frame's contacts coloured, packed kWideLanes to a block (or one to a
// block on the scalar path), and their impulses stored back.
#include "11_wide_solve/solve_steps.h"

#include "04_pgs/contact_constraints.h"
#include "06_manifolds/stabilisation.h"
#include "11_wide_solve/colouring.h"
#include "11_wide_solve/contact_kernels.h"
#include "11_wide_solve/wide_solver.h"
#include "world/contact_round.h"

#include <algorithm>
#include <array>
#include <cmath>

#if defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
#include <xmmintrin.h>  // _mm_prefetch
#endif

namespace stepwise {

namespace {

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

// [ch11-prepare-contact]
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
    // The arms reach each body's core: a sphere's centre, a capsule's segment, a lying cylinder's
    // axis (radius 0 for boxes, hulls and a cylinder's caps). Along the normal the arms change no row (every use is n . (w x arm) or arm x n),
    // but pointSeparations turns them with the bodies, and a point on a round surface does not
    // turn with its body: the ball's lowest point stays lowest as it rolls. Turned with the ball,
    // the material point would rise r (1 - cos w h) a substep, a false gap the solve would let the
    // ball fall into, every substep.
    inputs.roundA[lane] = contactRoundRadius(bodyA.shape, bodyA.transform, contact.normal);
    inputs.roundB[lane] = contactRoundRadius(bodyB.shape, bodyB.transform, contact.normal);
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
    const bool againstStatic = slotA < bodies.firstDynamic || slotB < bodies.firstDynamic;  // static or kinematic
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
    block.singlePoint = takesSinglePointRow(block.pointCount[0]);
    fillBlockFields(block, inputs, params.carryScale, world.settings.warmStarting);
}
// [ch11-prepare-contact]

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


// [ch11-store]
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
// [ch11-store]

/// Colours the contacts (colourContacts) and counts each colour's. A colour of one contact gives
/// it to the overflow: a wide block for one contact would gather, solve and scatter kWideLanes
/// lanes for it, where a scalar block does one (a ball alone on the ground steps faster so); from
/// two contacts on, the wide block is as fast or faster.
std::array<int, kMaxColours> colourForBlocks(ContactSolverScratch& scratch) {
    colourContacts(scratch.slotA, scratch.slotB, static_cast<int>(scratch.bodies.states.size()), scratch.colours,
                   scratch.colourBits, scratch.bodies.firstDynamic);
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

/// Whether a contact's lane goes to a block of single points (solveSinglePoint): 0 if so, else 1.
int pointClass(const World& world, const ContactSolverScratch& scratch, std::size_t i) {
    return takesSinglePointRow(world.contacts[static_cast<std::size_t>(scratch.contactOrder[i])].pointCount) ? 0 : 1;
}

/// How a manifold's points carried last frame (their warm-start impulses): 0 every point, 1 none,
/// 2 some but not all. A manifold whose points carry unevenly is the one whose normal block lets a
/// corner go or fails (two bricks leaning on an edge); laid side by side, such lanes share the
/// packs that sweep rows one at a time, and the others are spared it. Those that carry nothing
/// (neighbours in a row of bricks, a ball near another) fill blocks that hold no impulse, which
/// the sweeps skip (holdsNoImpulse).
int loadClass(const Contact& contact) {
    int loaded = 0;
    for (int k = 0; k < contact.pointCount; ++k) loaded += contact.points[k].normalImpulse > 0 ? 1 : 0;
    return loaded == contact.pointCount ? 0 : loaded == 0 ? 1 : 2;
}

/// The coloured contacts in the order their lanes are filled: colour by colour, within a colour by
/// the shock sweep's group (0 first: not swept), within a group single points first, and within
/// those by how their points carried (loadClass). A colour's lanes share no body, so their order
/// changes no bit of the solve; it puts a group's lanes side by side, and the sweep solves each
/// group over the few blocks that hold it (solveHeldBlock), it fills whole blocks of single
/// points, and it gathers the lanes whose blocks fail. Four stable counting sorts.
void orderLanes(const World& world, ContactSolverScratch& scratch) {
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
    std::vector<int>& classes = scratch.laneClass;
    std::vector<int>& loads = scratch.laneLoad;
    classes.resize(scratch.contactOrder.size());
    loads.resize(scratch.contactOrder.size());
    for (std::size_t i = 0; i < scratch.contactOrder.size(); ++i) {
        if (scratch.colours[i] < 0) continue;
        classes[i] = pointClass(world, scratch, i);
        loads[i] = loadClass(world.contacts[static_cast<std::size_t>(scratch.contactOrder[i])]);
        lanes.push_back(static_cast<int>(i));
    }
    countingSort(lanes, byGroup, 3, loads);
    std::swap(lanes, byGroup);
    countingSort(lanes, byGroup, 2, classes);
    std::swap(lanes, byGroup);
    if (scratch.laneGroups > 0) {
        countingSort(lanes, byGroup, scratch.laneGroups + 1, scratch.laneGroupOf);
        std::swap(lanes, byGroup);
    }
    countingSort(lanes, byGroup, kMaxColours, scratch.colours);
    std::swap(lanes, byGroup);
}

/// A lane's place in the shock sweep (groupShockSweep): its group and which body it holds still.
template <int N>
void setLaneGroup(ManifoldBlock<N>& block, int lane, const ContactSolverScratch& scratch, std::size_t i) {
    const int group = scratch.laneGroups > 0 ? scratch.laneGroupOf[i] : 0;
    const bool heldIsA = group > 0 && scratch.laneHeldIsA[i] != 0;
    block.shockGroup[lane] = group;
    block.heldA[lane] = heldIsA ? Real(1) : Real(0);
    block.heldB[lane] = group > 0 && !heldIsA ? Real(1) : Real(0);
}


/// The lanes are filled colour by colour, so their contact records are read in no order a cache
/// predicts: each is a few hundred bytes a cache miss away, and so are its bodies' solver data.
/// Asking for a record kPrefetchLanesAhead lanes ahead, and for its bodies' data half as far
/// ahead (the record has arrived by then), overlaps the misses with the filling (the same bits;
/// only the wait changes).
constexpr std::size_t kPrefetchLanesAhead = 8;

void prefetchBytes(const void* at, std::size_t size) {
    const char* bytes = static_cast<const char*>(at);
    for (std::size_t offset = 0; offset < size; offset += 64) {
#if defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
        _mm_prefetch(bytes + offset, _MM_HINT_T0);
#elif !defined(_MSC_VER)
        __builtin_prefetch(bytes + offset);
#endif
    }
}

/// The prefetches for lane k of the fill order (buildWideBlocks).
void prefetchLanes(const World& world, const ContactSolverScratch& scratch, std::size_t k) {
    const std::vector<int>& laneOrder = scratch.laneOrder;
    const auto contactAt = [&](std::size_t lane) -> const Contact& {
        const auto i = static_cast<std::size_t>(laneOrder[lane]);
        return world.contacts[static_cast<std::size_t>(scratch.contactOrder[i])];
    };
    if (k + kPrefetchLanesAhead < laneOrder.size()) prefetchBytes(&contactAt(k + kPrefetchLanesAhead), sizeof(Contact));
    if (k + kPrefetchLanesAhead / 2 < laneOrder.size()) {
        const Contact& contact = contactAt(k + kPrefetchLanesAhead / 2);
        for (const int body : {contact.bodyA, contact.bodyB}) {
            const int slot = scratch.bodies.slotOfBody[static_cast<std::size_t>(body)];
            prefetchBytes(&scratch.bodies.info[static_cast<std::size_t>(slot)], sizeof(SolverBodyInfo));
        }
    }
}

}  // namespace

bool usableContact(const World& world, const Contact& contact, const SolverBodies& bodies) {
    return validContactRecord(world, contact) &&
           (bodies.slotOfBody[static_cast<std::size_t>(contact.bodyA)] >= bodies.firstDynamic ||
            bodies.slotOfBody[static_cast<std::size_t>(contact.bodyB)] >= bodies.firstDynamic);
}

// [ch11-wide-blocks]
/// Colours the contacts and packs each colour kWideLanes at a time (orderLanes); the overflow goes
/// to scratch.scalarBlocks.
void buildWideBlocks(const World& world, ContactSolverScratch& scratch, const ContactSolveParams& params) {
    const std::vector<int>& order = scratch.contactOrder;
    colourForBlocks(scratch);
    orderLanes(world, scratch);
    scratch.wideBlocks.clear();
    scratch.scalarBlocks.clear();
    LaneInputs<kWideLanes>& inputs = scratch.laneInputs;
    const auto finishBlock = [&](int lanes) {  // the lanes' shared arithmetic, then the empty ones
        for (int lane = lanes; lane < kWideLanes; ++lane) emptyInputs(inputs, lane);
        fillWide(scratch.wideBlocks.back(), inputs, params.carryScale, world.settings.warmStarting);
        for (int lane = lanes; lane < kWideLanes; ++lane) emptyLane(scratch.wideBlocks.back(), lane);
    };
    int lane = kWideLanes, blockColour = -1, blockClass = -1;
    const std::vector<int>& laneOrder = scratch.laneOrder;
    for (std::size_t k = 0; k < laneOrder.size(); ++k) {
        const auto i = static_cast<std::size_t>(laneOrder[k]);
        prefetchLanes(world, scratch, k);
        // A block per colour's kWideLanes, of single points or of larger manifolds, never both:
        // a lane's answer must not depend on the lanes beside it.
        if (lane == kWideLanes || scratch.colours[i] != blockColour || scratch.laneClass[i] != blockClass) {
            if (lane < kWideLanes) finishBlock(lane);
            scratch.wideBlocks.emplace_back();
            lane = 0;
            blockColour = scratch.colours[i];
            blockClass = scratch.laneClass[i];
            scratch.wideBlocks.back().singlePoint = blockClass == 0;
        }
        setLaneGroup(scratch.wideBlocks.back(), lane, scratch, i);
        fillLane(scratch.wideBlocks.back(), inputs, lane++, world, order[i], scratch.bodies, params);
        if (lane == kWideLanes) finishBlock(lane);
    }
    if (lane < kWideLanes) finishBlock(lane);
    for (std::size_t i = 0; i < order.size(); ++i) {
        if (scratch.colours[i] >= 0) continue;
        scratch.scalarBlocks.emplace_back();
        fillScalarBlock(scratch.scalarBlocks.back(), world, order[i], scratch.bodies, params);
        setLaneGroup(scratch.scalarBlocks.back(), 0, scratch, i);
    }
}
// [ch11-wide-blocks]

/// The scalar path's blocks, one contact each, in the wide path's order: colour by colour, then
/// the overflow. Lanes of a wide block share no body, nor do the blocks of one colour, so the wide
/// sweep is this sweep done kWideLanes contacts at a time, and the two paths give the same bits (no
/// lane's answer depends on the lanes beside it): what the scalar solve measures is the lanes alone.
void buildScalarBlocks(const World& world, ContactSolverScratch& scratch, const ContactSolveParams& params) {
    const std::vector<int>& order = scratch.contactOrder;
    const std::array<int, kMaxColours> counts = colourForBlocks(scratch);
    scratch.wideBlocks.clear();
    scratch.scalarBlocks.resize(order.size());
    std::size_t next = 0;
    const auto fill = [&](std::size_t i) {
        setLaneGroup(scratch.scalarBlocks[next], 0, scratch, i);
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


void storeBlocks(const ContactSolverScratch& scratch, World& world) {
    const std::vector<ManifoldBlock<kWideLanes>>& blocks = scratch.wideBlocks;
    for (std::size_t k = 0; k < blocks.size(); ++k) {
        if (k + 1 < blocks.size())  // the next block's records, in no order a cache predicts
            for (const int index : blocks[k + 1].contactIndex)
                if (index >= 0) prefetchBytes(&world.contacts[static_cast<std::size_t>(index)], sizeof(Contact));
        storeBlock(blocks[k], world);
    }
    for (const ManifoldBlock<1>& block : scratch.scalarBlocks) storeBlock(block, world);
}

}  // namespace stepwise
