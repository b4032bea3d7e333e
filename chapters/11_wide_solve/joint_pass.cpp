// Joints, springs and drag in chapter 11's substeps, on the solve's own bodies: the frame's
// preparation and each substep's rows (joint_substeps.cpp: the passes over them).
#include "11_wide_solve/joint_pass.h"
#include "11_wide_solve/joint_kept_lanes.h"

#include "01_integrators/integrate.h"
#include "08_joints/joint_frame.h"
#include "11_wide_solve/solve_steps.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

// [ch11-joint-feedback]
JointFeedback fastJointFeedback(const Settings& settings, Real h) {
    JointFeedback feedback;
    feedback.kind = JointFeedback::Kind::Soft;
    const Real hertz = std::min(settings.jointHertz, kJointHertzPerSubstepRate / h);
    feedback.soft = makeSoftness(hertz, settings.jointDampingRatio, h);
    return feedback;
}
// [ch11-joint-feedback]

bool needsJointPass(const World& world) {
    return !world.joints.empty() || !world.springs.empty() || !world.dampings.empty();
}

namespace {

int entryFor(const World& world, const SolverBodies& bodies, int body, JointPass& pass) {
    int& entry = pass.entryOfBody[static_cast<std::size_t>(body)];
    if (entry >= 0) return entry;
    entry = static_cast<int>(pass.bodies.size());
    const int slot = bodies.slotOfBody[static_cast<std::size_t>(body)];
    pass.worldBody.push_back(body);
    pass.slot.push_back(slot);
    SolverBody solverBody;  // slot 0: zero mass and velocity, as the contacts see it
    const SolverBodyInfo& info = bodies.info[static_cast<std::size_t>(slot)];
    solverBody.inverseMass = info.inverseMass;
    solverBody.inverseInertia = info.inverseInertia;  // the frame's start, as the contacts take it
    solverBody.center = slot ? info.startCenter : worldCenterOfMass(world, body);
    pass.bodies.push_back(solverBody);
    return entry;
}

// Centre to anchor of entry `entry`'s body as the piece began, world axes: where the solve's turn
// since then (SolverBodyState::deltaRotation) carries it from (slotPose's rotation is that turn
// after the start's).
Vec3 startArm(const World& world, const SolverBodies& bodies, const JointPass& pass, int entry, const Vec3& localAnchor) {
    const int slot = pass.slot[static_cast<std::size_t>(entry)];
    const int body = pass.worldBody[static_cast<std::size_t>(entry)];
    if (slot == 0) return world.bodies[static_cast<std::size_t>(body)].transform.apply(localAnchor) - pass.bodies[static_cast<std::size_t>(entry)].center;
    const SolverBodyInfo& info = bodies.info[static_cast<std::size_t>(slot)];
    return info.startRotation * (localAnchor - world.motionOf(body)->localCenter);
}

// Whether a joint's Jacobians depend on its bodies' turns alone: the point joints' rows run
// along fixed axes through arms that turn with the bodies, their turn rows about axes that turn
// with them. A distance joint's row runs along the line between the anchors and a slider's
// through the gap between them, which the bodies' moves turn too: always built.
bool rowsFollowTurnsAlone(JointType type) {
    return type == JointType::BallSocket || type == JointType::Hinge || type == JointType::ConeTwist ||
           type == JointType::Fixed;
}

// What each listed joint asks of the lanes' layout: room for all its slots, used or not.
void fillRooms(const World& world, JointPass& pass) {
    pass.rooms.resize(pass.joints.size());
    for (std::size_t i = 0; i < pass.joints.size(); ++i) {
        const JointType type = world.joints[static_cast<std::size_t>(pass.joints[i])].type;
        JointRoom& room = pass.rooms[i];
        room.joint = static_cast<int>(i);
        room.rows = jointSlotCount(type);
        room.block = hasPointBlock(type);
        room.keepable = rowsFollowTurnsAlone(type);
        room.slotA = pass.slot[static_cast<std::size_t>(pass.entryA[i])];
        room.slotB = pass.slot[static_cast<std::size_t>(pass.entryB[i])];
    }
}

}  // namespace

void prepareJointPass(const World& world, const SolverBodies& bodies, Real carryScale, JointPass& pass) {
    pass.joints.clear();
    pass.entryA.clear();
    pass.entryB.clear();
    pass.worldBody.clear();
    pass.slot.clear();
    pass.bodies.clear();
    pass.carried.clear();
    pass.startArmA.clear();
    pass.startArmB.clear();
    pass.jointsBuilt = 0;
    pass.jointsKept = 0;
    pass.laidOut = false;
    pass.entryOfBody.assign(world.bodies.size(), -1);
    if (world.joints.empty()) return;
    for (const int jointIndex : pass.sweep.order(world, kDefaultJointOrder)) {
        const JointDesc& joint = world.joints[static_cast<std::size_t>(jointIndex)];
        if (!jointBodiesValid(world, joint)) continue;
        const int slotA = bodies.slotOfBody[static_cast<std::size_t>(joint.bodyA)];
        const int slotB = bodies.slotOfBody[static_cast<std::size_t>(joint.bodyB)];
        if (slotA < bodies.firstDynamic && slotB < bodies.firstDynamic) continue;  // nothing it holds moves
        pass.joints.push_back(jointIndex);
        pass.entryA.push_back(entryFor(world, bodies, joint.bodyA, pass));
        pass.entryB.push_back(entryFor(world, bodies, joint.bodyB, pass));
        // Only a distance joint reads its arms from the piece's start (distanceFrame).
        const bool distance = joint.type == JointType::Distance;
        pass.startArmA.push_back(distance ? startArm(world, bodies, pass, pass.entryA.back(), joint.localAnchorA) : Vec3::Zero());
        pass.startArmB.push_back(distance ? startArm(world, bodies, pass, pass.entryB.back(), joint.localAnchorB) : Vec3::Zero());
        JointImpulses carried;
        if (world.settings.warmStarting && static_cast<std::size_t>(jointIndex) < world.jointImpulses.size())
            for (int k = 0; k < JointImpulses::kSlots; ++k)
                carried.slot[k] = carryScale * world.jointImpulses[static_cast<std::size_t>(jointIndex)].slot[k];
        pass.carried.push_back(carried);
    }
    pass.placedAt.assign(pass.bodies.size(), -1);
    fillRooms(world, pass);
}

namespace {

// The sweeps push a point block by its arms and make every row's effective mass with M^-1 J^T
// (writePackedJoint): the batch leaves both out.
constexpr JointBatchNeeds kPackedNeeds{/*pointJacobians=*/false, /*effectiveMasses=*/false};

// Whether the turn from `built` to `now` is at most `most` in the small-angle form, 2 |v| of the
// quotient, without making it: |v|^2 = 1 - w^2, and w of the quotient of two unit quaternions is
// their dot product.
bool turnedAtMost(const Quat& built, const Quat& now, Real most) {
    const Real w = built.coeffs().dot(now.coeffs());
    return 1 - w * w <= most * most / 4;
}

// A slot's turn since the piece began (slot 0 does not turn).
Quat turnOf(const SolverBodies& bodies, int slot) {
    const Real* q = bodies.states[static_cast<std::size_t>(slot)].deltaRotation;
    return slot == 0 ? Quat::Identity() : Quat(q[3], q[0], q[1], q[2]);
}

// Whether neither body of listed joint i has turned more than kJointRowsKeptTurn since its rows
// were built. Both turns are measured from the piece's start, so their quotient is the turn since.
// The turns the rows were built at are the joint's lane's (JointLaneGroup::builtA, builtB).
bool bodiesTurnedLittle(const SolverBodies& bodies, const JointPass& pass, std::size_t i) {
    const Quat a = turnOf(bodies, pass.slot[static_cast<std::size_t>(pass.entryA[i])]);
    const Quat b = turnOf(bodies, pass.slot[static_cast<std::size_t>(pass.entryB[i])]);
    const PackedJoint& joint = pass.packed.joints[i];
    const JointLaneGroup& group = pass.packed.groups[static_cast<std::size_t>(joint.group)];
    const auto built = [lane = joint.lane](const PackQuat<kWideLanes>& q) {
        return Quat(q.w[lane], q.x[lane], q.y[lane], q.z[lane]);
    };
    return turnedAtMost(built(group.builtA), a, kJointRowsKeptTurn) && turnedAtMost(built(group.builtB), b, kJointRowsKeptTurn);
}

// A distance joint's anchors and arms now, from the arms as the piece began turned by the bodies'
// turns since and the centres moved by their moves: the distance row needs nothing else of the
// poses. The same numbers as chapter 8's jointRowFrame to rounding.
JointFrame distanceFrame(const SolverBodies& bodies, const JointPass& pass, std::size_t i) {
    JointFrame frame;
    const auto place = [&](int entry, const Vec3& startArm, Vec3& arm, Vec3& anchor) {
        const int slot = pass.slot[static_cast<std::size_t>(entry)];
        const Vec3& center = pass.bodies[static_cast<std::size_t>(entry)].center;
        if (slot == 0) {
            arm = startArm;
            anchor = center + arm;
            return;
        }
        const Real* moved = bodies.states[static_cast<std::size_t>(slot)].deltaPosition;
        arm = turnOf(bodies, slot) * startArm;
        anchor = center + Vec3(moved[0], moved[1], moved[2]) + arm;
    };
    place(pass.entryA[i], pass.startArmA[i], frame.armA, frame.anchorA);
    place(pass.entryB[i], pass.startArmB[i], frame.armB, frame.anchorB);
    return frame;
}

// The piece's first substep lays every listed joint out in the lanes, by colour (layOutPackedJoints),
// each with room for all its slots (unless the last piece's layout stands: takeHandedJointRows);
// later substeps write a joint built again over its own rows and leave a kept one where it is.
void layOutJoints(JointPass& pass) {
    pass.packedEntry.assign(pass.joints.size(), -1);
    layOutPackedJoints(pass.packed, pass.rooms);
}

// Builds listed joint i's rows where its bodies stand now into its entry, which the frame's first
// substep lays out; its slot count into `slots`. False (the entry left empty) if a row came out
// non-finite. A joint of one row skips chapter 8's batch and is written straight into its room
// (writeDistanceJoint): the same rule, a tenth of the room.
bool buildListedJoint(const World& world, Real h, const JointFeedback& feedback, std::size_t i,
                      const JointFrame& frame, JointPass& pass, int& slots) {
    const int entry = static_cast<int>(i);
    const JointDesc& joint = world.joints[static_cast<std::size_t>(pass.joints[i])];
    JointImpulses& carried = pass.carried[i];
    if (joint.type == JointType::Distance) {  // one row
        if (!writeDistanceJoint(joint, frame, pass.entryA[i], pass.entryB[i], h, feedback, carried.slot[0], pass.bodies,
                                pass.slot, pass.packed, entry))
            return false;
        slots = 1;
        return true;
    }
    JointRowBatch& batch = pass.batch;
    const bool built = buildJointRowBatch(batch, joint, pass.joints[i], frame, pass.entryA[i], pass.entryB[i],
                                          pass.bodies, h, feedback, &carried, kPackedNeeds);
    if (!built || !writePackedJoint(batch, pass.bodies, pass.slot, pass.packed, entry)) return false;
    // Every slot carries its impulse clamped to this substep's bounds; the sweeps' own rows
    // overwrite theirs when the piece ends or the joint is built again (keepJointImpulses).
    for (int slot = 0; slot < batch.count; ++slot) carried.slot[slot] = batch.rows[slot].impulse;
    slots = batch.count;
    return true;
}

}  // namespace

const JointPass::BodyPose& placeJointBody(const World& world, const SolverBodies& bodies, JointPass& pass, std::size_t e) {
    JointPass::BodyPose& pose = pass.poses[e];
    if (pass.placedAt[e] == pass.substepStamp) return pose;
    pass.placedAt[e] = pass.substepStamp;
    const int slot = pass.slot[e];
    const int body = pass.worldBody[e];
    if (slot == 0) {
        pose.transform = world.bodies[static_cast<std::size_t>(body)].transform;
        pose.center = pass.bodies[e].center;
        return pose;
    }
    const SlotPose now = slotPose(bodies, slot);
    pose.transform.rotation = now.rotation;
    pose.transform.position = now.center - now.rotation * world.motionOf(body)->localCenter;
    pose.center = now.center;
    return pose;
}

namespace {

// [ch11-distance-kept]
// Whether listed distance joint i may keep last substep's row with its anchors now in `frame`:
// neither body has turned more than kJointRowsKeptTurn since the row was built, nor has the line
// between the anchors (the row's direction). Its error is then the line's own, exact, and only
// its Jacobian and effective mass are the build's.
bool keepsDistanceRow(const SolverBodies& bodies, JointPass& pass, std::size_t i, const JointDesc& joint,
                      const JointFrame& frame) {
    if (pass.packedEntry[i] < 0) return false;
    const PackedJoint& packedJoint = pass.packed.joints[i];
    if (packedJoint.rowCount != 1) return false;  // a row without mass or direction: built again
    if (!bodiesTurnedLittle(bodies, pass, i)) return false;
    JointRowLanes& row = pass.packed.groups[static_cast<std::size_t>(packedJoint.group)].rows[0];
    const int lane = packedJoint.lane;
    const Vec3 direction(row.linearB.x[lane], row.linearB.y[lane], row.linearB.z[lane]);  // the built direction
    const Vec3 gap = frame.anchorB - frame.anchorA;
    const Real length = gap.norm();
    // The sine of the line's turn from the built direction, squared, without dividing.
    if (!(gap.cross(direction).squaredNorm() <= kJointRowsKeptTurn * kJointRowsKeptTurn * length * length))
        return false;
    row.error[lane] = length - joint.length.value_or(length);
    return true;
}
// [ch11-distance-kept]

// Listed joint i's frame where its bodies stand now, by chapter 8's jointRowFrame.
JointFrame placedFrame(const World& world, const SolverBodies& bodies, JointPass& pass, std::size_t i, const JointDesc& joint) {
    const JointPass::BodyPose& a = placeJointBody(world, bodies, pass, static_cast<std::size_t>(pass.entryA[i]));
    const JointPass::BodyPose& b = placeJointBody(world, bodies, pass, static_cast<std::size_t>(pass.entryB[i]));
    return jointRowFrame(joint, a.transform, a.center, b.transform, b.center);
}

// Listed joint i keeps last substep's rows, their impulses the sweeps ended with, their errors
// moved (a distance joint's measured); the biases are made again from the errors.
void keepJoint(JointPass& pass, std::size_t i, const JointFeedback& feedback, Real h) {
    pass.rowCount += pass.packed.joints[i].slotCount;
    refreshPackedFeedback(pass.packed, static_cast<int>(i), feedback, h);
    ++pass.jointsKept;
}

// Listed joint i built (or left out) into its entry: the bookkeeping of a build.
void finishBuild(const SolverBodies& bodies, JointPass& pass, std::size_t i, bool built, int slots) {
    if (!built) {
        emptyPackedJoint(pass.packed, static_cast<int>(i));
        markPackedBuilt(pass.packed, static_cast<int>(i), false);
        ++pass.invalidSkipped;  // left out this substep; its impulses wait as they are
        return;
    }
    pass.rowCount += slots;
    pass.packedEntry[i] = static_cast<int>(i);
    markPackedBuilt(pass.packed, static_cast<int>(i), true, turnOf(bodies, pass.slot[static_cast<std::size_t>(pass.entryA[i])]),
                    turnOf(bodies, pass.slot[static_cast<std::size_t>(pass.entryB[i])]));
    ++pass.jointsBuilt;
}

// Listed joint i built alone, by chapter 8's batch (or a distance joint's own row).
void buildOne(const World& world, const SolverBodies& bodies, Real h, const JointFeedback& feedback, std::size_t i,
              const JointFrame& frame, JointPass& pass) {
    int slots = 0;
    const bool built = buildListedJoint(world, h, feedback, i, frame, pass, slots);
    finishBuild(bodies, pass, i, built, slots);
}

// Listed joint i waits in its lane for the group's build (buildQueuedLanes).
void queueLaneBuild(JointPass& pass, std::size_t i, const JointDesc& joint, const JointFrame& frame) {
    const PackedJoint& packed = pass.packed.joints[i];
    const auto g = static_cast<std::size_t>(packed.group);
    pass.lanesToBuild[g] |= 1u << packed.lane;
    LaneJoint& input = pass.laneJoints[g * kWideLanes + static_cast<std::size_t>(packed.lane)];
    input.joint = &joint;
    input.frame = frame;
    input.bodyA = &pass.bodies[static_cast<std::size_t>(pass.entryA[i])];
    input.bodyB = &pass.bodies[static_cast<std::size_t>(pass.entryB[i])];
    input.carried = &pass.carried[i];
}

// The queued lanes, a group at a time; a lane the group's build leaves is built alone.
void buildQueuedLanes(const World& world, const SolverBodies& bodies, Real h, const JointFeedback& feedback, JointPass& pass) {
    for (std::size_t g = 0; g < pass.lanesToBuild.size(); ++g) {
        const unsigned lanes = pass.lanesToBuild[g];
        if (lanes == 0) continue;
        pass.lanesToBuild[g] = 0;
        LaneJoint* inputs = &pass.laneJoints[g * kWideLanes];
        const unsigned left = buildJointLanes(pass.packed, static_cast<int>(g), inputs, lanes, feedback, h);
        const JointLaneGroup& group = pass.packed.groups[g];
        for (int lane = 0; lane < kWideLanes; ++lane) {
            if (!(lanes >> lane & 1u)) continue;
            const auto i = static_cast<std::size_t>(group.entry[lane]);
            if (left >> lane & 1u) {
                buildOne(world, bodies, h, feedback, i, inputs[lane].frame, pass);
                continue;
            }
            const LaneJoint& input = inputs[lane];
            for (int slot = 0; slot < input.slots; ++slot) pass.carried[i].slot[slot] = input.seated.slot[slot];
            finishBuild(bodies, pass, i, true, input.slots);
        }
    }
}

}  // namespace

// [ch11-joint-rows]
void buildJointRows(const World& world, const SolverBodies& bodies, Real h, bool firstSubstep, JointPass& pass) {
    pass.rowCount = 0;
    pass.invalidSkipped = 0;
    // The piece's first substep lays the joints out, each with room for all its slots, unless the
    // last piece's layout stands; later substeps write a joint built again over its own rows and
    // leave a kept one where it is.
    if (firstSubstep && !pass.laidOut) layOutJoints(pass);
    if (firstSubstep) sizeLaneQueue(pass);
    if (pass.joints.empty()) return;
    const JointFeedback feedback = fastJointFeedback(world.settings, h);
    ++pass.substepStamp;  // the poses made last substep are stale
    pass.poses.resize(pass.bodies.size());
    // The point joints that keep last substep's rows, a lane group at a time: those built (not left
    // out), whose rows follow their bodies' turns alone, and whose bodies have barely turned since;
    // on the piece's first substep, only those the last piece handed on (takeHandedJointRows).
    pass.keptLanes.assign(static_cast<std::size_t>(pass.packed.groupCount), 0u);
    const bool mayKeep = !firstSubstep || pass.laidOut;
    for (std::size_t g = 0; g < pass.keptLanes.size() && mayKeep; ++g) {
        const JointLaneGroup& group = pass.packed.groups[g];
        const unsigned handed = firstSubstep ? pass.handedLanes[g] : ~0u;
        const unsigned keepable = group.keepableLanes & group.builtLanes & handed;
        if (keepable) pass.keptLanes[g] = keepable & lanesTurnedAtMost(group, bodies.states.data(), kJointRowsKeptTurn);
    }
    listJointsNotKept(pass, mayKeep);
    for (const int listed : pass.notKept) {
        const auto i = static_cast<std::size_t>(listed);
        const JointDesc& joint = world.joints[static_cast<std::size_t>(pass.joints[i])];
        const bool distance = joint.type == JointType::Distance;
        const JointFrame frame = distance ? distanceFrame(bodies, pass, i) : placedFrame(world, bodies, pass, i, joint);
        if (mayKeep && (!firstSubstep || handedJoint(pass, i)) && distance && keepsDistanceRow(bodies, pass, i, joint, frame)) {
            keepJoint(pass, i, feedback, h);
            continue;
        }
        // Built again from the impulses its rows ended the last substep with.
        if (!firstSubstep) keepPackedImpulsesOf(pass.packed, static_cast<int>(i), pass.carried);
        pass.packedEntry[i] = -1;
        if (pass.laneBuild && buildsInLanes(joint.type)) {  // with its group's others, below
            queueLaneBuild(pass, i, joint, frame);
            continue;
        }
        buildOne(world, bodies, h, feedback, i, frame, pass);
    }
    buildQueuedLanes(world, bodies, h, feedback, pass);
    for (std::size_t g = 0; g < pass.keptLanes.size(); ++g)  // none on the frame's first substep
        if (pass.keptLanes[g] != 0)
            refreshPackedFeedbackLanes(pass.packed, static_cast<int>(g), pass.keptLanes[g], feedback, h);
}
// [ch11-joint-rows]

}  // namespace stepwise
