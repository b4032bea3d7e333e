#include "09_debug/snapshot.h"

#include "05_sap/sweep_and_prune.h"
#include "math/same_bits.h"
#include "world/heap_bytes.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace stepwise {

namespace {

void putVec(const Vec3& v, Real out[3]) {
    for (int i = 0; i < 3; ++i) out[i] = v[i];
}
Vec3 getVec(const Real in[3]) { return Vec3(in[0], in[1], in[2]); }
void putQuat(const Quat& q, Real out[4]) {
    out[0] = q.x();
    out[1] = q.y();
    out[2] = q.z();
    out[3] = q.w();
}
Quat getQuat(const Real in[4]) { return Quat(in[3], in[0], in[1], in[2]); }

void saveStep(const World& world, StepScalars& out) {
    const StepState& step = world.step;
    out.substep = step.substep;
    out.substepCount = step.substepCount;
    out.contactsFoundAtSubstep = step.contactsFoundAtSubstep;
    out.solver = step.solver;
    out.contactPointsDropped = step.contactPointsDropped;
    out.manifoldsReused = step.manifoldsReused;
    out.manifoldsRebuilt = step.manifoldsRebuilt;
    out.ccdFastBodies = step.ccd.fastBodies;
    out.ccdToiEvents = step.ccd.toiEvents;
    out.ccdRootIterations = step.ccd.rootIterations;
    out.ccdBoundHit = step.ccd.boundHit;
    out.ccdTimeLost = step.ccd.timeLost;
    out.ccdStepsRun = step.ccd.stepsRun;
    out.ccdTotalToiEvents = step.ccd.totalToiEvents;
    out.ccdStepsBoundHit = step.ccd.stepsBoundHit;
    out.iterationPlan = step.iterationPlan;
    const BroadphaseState& broadphase = world.broadphase;
    out.sweepAxis = broadphase.axis;
    out.broadphaseUsed = broadphase.used;
    out.centreVariance = broadphase.centreVariance;
    out.fullSort = broadphase.fullSort;
    out.sweepSkipped = broadphase.sweepSkipped;
    out.sortMoves = broadphase.sortMoves;
    out.axisOverlaps = broadphase.axisOverlaps;
}

void restoreStep(const StepScalars& in, World& world) {
    StepState& step = world.step;
    step.substep = in.substep;
    step.substepCount = in.substepCount;
    step.contactsFoundAtSubstep = in.contactsFoundAtSubstep;
    step.solver = in.solver;
    step.contactPointsDropped = in.contactPointsDropped;
    step.manifoldsReused = in.manifoldsReused;
    step.manifoldsRebuilt = in.manifoldsRebuilt;
    step.velocitiesBeforeForces.clear();   // taken afresh at each substep
    CcdState& ccd = step.ccd;
    ccd.sweepStart.clear();                // taken afresh at each substep
    ccd.ghostBodies.clear();               // what the last step drew: the next one draws its own
    ccd.ghostPoses.clear();
    ccd.sweptBounds.clear();
    ccd.fastBodies = in.ccdFastBodies;
    ccd.toiEvents = in.ccdToiEvents;
    ccd.rootIterations = in.ccdRootIterations;
    ccd.boundHit = in.ccdBoundHit;
    ccd.timeLost = in.ccdTimeLost;
    ccd.stepsRun = in.ccdStepsRun;
    ccd.totalToiEvents = in.ccdTotalToiEvents;
    ccd.stepsBoundHit = in.ccdStepsBoundHit;
    step.iterationPlan = in.iterationPlan;
}

void saveContacts(const World& world, WorldSnapshot& out) {
    for (const Contact& contact : world.contacts) {
        ContactBits bits{};
        bits.bodyA = contact.bodyA;
        bits.bodyB = contact.bodyB;
        putVec(contact.normal, bits.normal);
        const int count = std::min(std::max(contact.pointCount, 0), 4);
        bits.pointCount = static_cast<std::uint8_t>(count);
        bits.referenceSide = static_cast<std::uint8_t>(contact.referenceSide);
        bits.missedSteps = static_cast<std::uint8_t>(std::min(std::max(contact.missedSteps, 0), 255));
        bits.flags = contact.builtPoseKnown ? 1 : 0;
        for (int i = 0; i < count; ++i) {
            const ContactPoint& point = contact.points[i];
            if (point.persisted) bits.flags = static_cast<std::uint8_t>(bits.flags | (2u << i));
            PointBits p{};
            putVec(point.localAnchorA, p.anchorA);
            putVec(point.localAnchorB, p.anchorB);
            p.depth = point.depth;
            p.featureId = point.featureId;
            p.normalImpulse = point.normalImpulse;
            p.tangentImpulse[0] = point.tangentImpulse[0];
            p.tangentImpulse[1] = point.tangentImpulse[1];
            p.normalMass = point.normalMass;
            out.points.push_back(p);
        }
        if (contact.builtPoseKnown) {
            BuiltPoseBits built{};
            putVec(contact.builtRelativePosition, built.relativePosition);
            putQuat(contact.builtRelativeRotation, built.relativeRotation);
            putVec(contact.builtLocalNormal, built.localNormal);
            out.builtPoses.push_back(built);
        }
        out.contacts.push_back(bits);
    }
}

void restoreContacts(const WorldSnapshot& in, World& world) {
    world.contacts.assign(in.contacts.size(), Contact{});
    std::size_t point = 0, built = 0;
    const int bodyCount = static_cast<int>(world.bodies.size());
    for (std::size_t c = 0; c < in.contacts.size(); ++c) {
        const ContactBits& bits = in.contacts[c];
        Contact& contact = world.contacts[c];
        if (bits.bodyA < 0 || bits.bodyB < 0 || bits.bodyA >= bodyCount || bits.bodyB >= bodyCount || bits.pointCount > 4)
            throw std::invalid_argument("snapshot: contact " + std::to_string(c) + " names a body or a point count the world does not have");
        contact.bodyA = bits.bodyA;
        contact.bodyB = bits.bodyB;
        contact.normal = getVec(bits.normal);
        contact.pointCount = bits.pointCount;
        contact.referenceSide = bits.referenceSide;
        contact.missedSteps = bits.missedSteps;
        contact.builtPoseKnown = (bits.flags & 1) != 0;
        if (point + bits.pointCount > in.points.size() || (contact.builtPoseKnown && built >= in.builtPoses.size()))
            throw std::invalid_argument("snapshot: contact " + std::to_string(c) + " has fewer points or poses than it counts");
        const Transform& poseA = world.bodies[static_cast<std::size_t>(bits.bodyA)].transform;
        const Transform& poseB = world.bodies[static_cast<std::size_t>(bits.bodyB)].transform;
        for (int i = 0; i < bits.pointCount; ++i) {
            const PointBits& p = in.points[point++];
            ContactPoint& out = contact.points[i];
            out.localAnchorA = getVec(p.anchorA);
            out.localAnchorB = getVec(p.anchorB);
            // The world points follow from the anchors; every reader refreshes them (or reads only
            // the depth) before using them.
            out.pointA = poseA.apply(out.localAnchorA);
            out.pointB = poseB.apply(out.localAnchorB);
            out.depth = p.depth;
            out.featureId = p.featureId;
            out.persisted = (bits.flags & (2u << i)) != 0;
            out.normalImpulse = p.normalImpulse;
            out.tangentImpulse[0] = p.tangentImpulse[0];
            out.tangentImpulse[1] = p.tangentImpulse[1];
            out.normalMass = p.normalMass;
        }
        if (contact.builtPoseKnown) {
            const BuiltPoseBits& pose = in.builtPoses[built++];
            contact.builtRelativePosition = getVec(pose.relativePosition);
            contact.builtRelativeRotation = getQuat(pose.relativeRotation);
            contact.builtLocalNormal = getVec(pose.localNormal);
        }
    }
}

/// World::pairs as flags on the records plus the pairs without one, when the list is in the
/// canonical order (strictly increasing, as every narrowphase writes it); else whole.
void savePairs(const World& world, WorldSnapshot& out) {
    out.pairs.clear();
    out.pairsWhole = !std::is_sorted(world.pairs.begin(), world.pairs.end()) ||
                     std::adjacent_find(world.pairs.begin(), world.pairs.end()) != world.pairs.end();
    if (out.pairsWhole) {
        out.pairs = world.pairs;
        return;
    }
    std::size_t c = 0;
    for (const BodyPair& pair : world.pairs) {
        while (c < world.contacts.size() && world.contacts[c].pair() < pair) ++c;
        if (c < world.contacts.size() && world.contacts[c].pair() == pair)
            out.contacts[c].flags = static_cast<std::uint8_t>(out.contacts[c].flags | 32u);
        else
            out.pairs.push_back(pair);
    }
}

void restorePairs(const WorldSnapshot& in, World& world) {
    world.pairs.clear();
    if (in.pairsWhole) {
        world.pairs = in.pairs;
        return;
    }
    std::size_t extra = 0;
    for (std::size_t c = 0; c < in.contacts.size(); ++c) {
        if ((in.contacts[c].flags & 32u) == 0) continue;
        const BodyPair pair{in.contacts[c].bodyA, in.contacts[c].bodyB};
        while (extra < in.pairs.size() && in.pairs[extra] < pair) world.pairs.push_back(in.pairs[extra++]);
        world.pairs.push_back(pair);
    }
    world.pairs.insert(world.pairs.end(), in.pairs.begin() + static_cast<std::ptrdiff_t>(extra), in.pairs.end());
}

void restoreBroadphase(const WorldSnapshot& in, World& world) {
    BroadphaseState& broadphase = world.broadphase;
    broadphase.axis = in.step.sweepAxis;
    broadphase.used = in.step.broadphaseUsed;
    broadphase.centreVariance = in.step.centreVariance;
    broadphase.fullSort = in.step.fullSort;
    broadphase.sweepSkipped = in.step.sweepSkipped;
    broadphase.sortMoves = in.step.sortMoves;
    broadphase.axisOverlaps = in.step.axisOverlaps;
    // The order is what the insertion sort starts from; the values are read again from the boxes
    // before it runs.
    broadphase.endpoints.resize(in.sweepOrder.size());
    for (std::size_t i = 0; i < in.sweepOrder.size(); ++i) broadphase.endpoints[i] = SweepEndpoint{0, in.sweepOrder[i]};
    // Chapter 10's grown boxes only let a step skip a sweep whose pairs it would find anyway:
    // without them the next step sweeps.
    broadphase.enlargedBounds.clear();
    broadphase.enlargedDynamic.clear();
    broadphase.enlargedPairs.clear();
    // The boxes are rebuilt every step; the ones drawn with the restored frame follow its poses.
    if (broadphase.endpoints.empty()) {
        broadphase.bounds.clear();
        broadphase.dynamic.clear();
    } else {
        computeBroadphaseBounds(world, broadphase.bounds, broadphase.dynamic);
    }
}

}  // namespace

void saveSnapshot(const World& world, WorldSnapshot& snapshot) {
    snapshot.frame = world.frame;
    snapshot.time = world.time;
    snapshot.settings = world.settings;
    saveStep(world, snapshot.step);
    snapshot.poses.resize(world.bodies.size());
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        putVec(world.bodies[i].transform.position, snapshot.poses[i].position);
        putQuat(world.bodies[i].transform.rotation, snapshot.poses[i].rotation);
    }
    snapshot.motions.resize(world.motions.size());
    snapshot.asleep.resize(world.motions.size());
    snapshot.pushes.clear();
    for (std::size_t i = 0; i < world.motions.size(); ++i) {
        const Motion& motion = world.motions[i];
        MotionBits& bits = snapshot.motions[i];
        putVec(motion.linearVelocity, bits.linear);
        putVec(motion.angularVelocity, bits.angular);
        bits.sleepTime = motion.sleepTime;
        snapshot.asleep[i] = motion.asleep ? 1 : 0;
        if (!sameBits(motion.force, Vec3(Vec3::Zero())) || !sameBits(motion.torque, Vec3(Vec3::Zero()))) {
            PushBits push{};
            push.motion = static_cast<std::int32_t>(i);
            putVec(motion.force, push.force);
            putVec(motion.torque, push.torque);
            snapshot.pushes.push_back(push);
        }
    }
    snapshot.sweepOrder.resize(world.broadphase.endpoints.size());
    for (std::size_t i = 0; i < world.broadphase.endpoints.size(); ++i)
        snapshot.sweepOrder[i] = world.broadphase.endpoints[i].body;
    snapshot.contacts.clear();
    snapshot.builtPoses.clear();
    snapshot.points.clear();
    saveContacts(world, snapshot);
    savePairs(world, snapshot);
    snapshot.jointImpulses = world.jointImpulses;
    snapshot.jointRows = world.step.jointRows;
    snapshot.jointRowsBytes = world.step.jointRowsBytes;
}

void restoreSnapshot(const WorldSnapshot& snapshot, World& world) {
    if (snapshot.poses.size() != world.bodies.size() || snapshot.motions.size() != world.motions.size() ||
        snapshot.asleep.size() != world.motions.size())
        throw std::invalid_argument("snapshot of " + std::to_string(snapshot.poses.size()) + " bodies and " +
                                    std::to_string(snapshot.motions.size()) + " moving ones cannot go into a world of " +
                                    std::to_string(world.bodies.size()) + " and " + std::to_string(world.motions.size()));
    if (!snapshot.jointImpulses.empty() && snapshot.jointImpulses.size() != world.joints.size())
        throw std::invalid_argument("snapshot: impulses of " + std::to_string(snapshot.jointImpulses.size()) +
                                    " joints for a world of " + std::to_string(world.joints.size()));
    world.frame = snapshot.frame;
    world.time = snapshot.time;
    world.settings = snapshot.settings;
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        world.bodies[i].transform.position = getVec(snapshot.poses[i].position);
        world.bodies[i].transform.rotation = getQuat(snapshot.poses[i].rotation);
    }
    for (std::size_t i = 0; i < world.motions.size(); ++i) {
        Motion& motion = world.motions[i];
        const MotionBits& bits = snapshot.motions[i];
        motion.linearVelocity = getVec(bits.linear);
        motion.angularVelocity = getVec(bits.angular);
        motion.sleepTime = bits.sleepTime;
        motion.asleep = snapshot.asleep[i] != 0;
        motion.force = Vec3::Zero();
        motion.torque = Vec3::Zero();
    }
    for (const PushBits& push : snapshot.pushes) {
        if (push.motion < 0 || static_cast<std::size_t>(push.motion) >= world.motions.size())
            throw std::invalid_argument("snapshot: a push on moving body " + std::to_string(push.motion) + " the world does not have");
        world.motions[static_cast<std::size_t>(push.motion)].force = getVec(push.force);
        world.motions[static_cast<std::size_t>(push.motion)].torque = getVec(push.torque);
    }
    for (const std::int32_t body : snapshot.sweepOrder)
        if (body < 0 || static_cast<std::size_t>(body) >= world.bodies.size())
            throw std::invalid_argument("snapshot: the sweep order names body " + std::to_string(body));
    restoreStep(snapshot.step, world);
    restoreContacts(snapshot, world);
    restoreBroadphase(snapshot, world);
    restorePairs(snapshot, world);
    world.candidatePairs.clear();   // found again by the next step's broadphase
    world.pairGaps.clear();         // a shortcut: a pair without a gap is measured again, same answer
    world.jointImpulses = snapshot.jointImpulses;
    world.step.jointRows = snapshot.jointRows;
    world.step.jointRowsBytes = snapshot.jointRowsBytes;
}

bool sameStructure(const World& a, const World& b) {
    if (a.bodies.size() != b.bodies.size() || a.motions.size() != b.motions.size() || a.joints.size() != b.joints.size() ||
        a.springs.size() != b.springs.size() || a.dampings.size() != b.dampings.size() ||
        a.kinematicPaths.size() != b.kinematicPaths.size())
        return false;
    for (std::size_t i = 0; i < a.motions.size(); ++i) {
        const Motion& x = a.motions[i];
        const Motion& y = b.motions[i];
        if (x.bodyIndex != y.bodyIndex || !sameBits(x.mass, y.mass) || !sameBits(x.inverseMass, y.inverseMass) ||
            !sameBits(x.localCenter, y.localCenter) || !sameBits(x.inertiaLocal, y.inertiaLocal) ||
            !sameBits(x.inverseInertiaLocal, y.inverseInertiaLocal) || x.integrator != y.integrator)
            return false;
    }
    for (std::size_t i = 0; i < a.bodies.size(); ++i)
        if (a.bodies[i].motionIndex != b.bodies[i].motionIndex || a.bodies[i].type != b.bodies[i].type ||
            a.bodies[i].shape.type != b.bodies[i].shape.type)
            return false;
    return true;
}

std::size_t snapshotBytes(const WorldSnapshot& snapshot) {
    return sizeof(WorldSnapshot) + capacityBytes(snapshot.poses) + capacityBytes(snapshot.motions) +
           capacityBytes(snapshot.asleep) + capacityBytes(snapshot.pushes) + capacityBytes(snapshot.sweepOrder) +
           capacityBytes(snapshot.contacts) + capacityBytes(snapshot.builtPoses) + capacityBytes(snapshot.points) +
           capacityBytes(snapshot.pairs) + capacityBytes(snapshot.jointImpulses) + snapshot.jointRowsBytes;
}

SnapshotSize snapshotSize(const WorldSnapshot& snapshot) {
    SnapshotSize size;
    size.bodies = snapshot.poses.size();
    size.bodyBytes = sizeBytes(snapshot.poses) + sizeBytes(snapshot.motions) + sizeBytes(snapshot.asleep) +
                     sizeBytes(snapshot.pushes) + sizeBytes(snapshot.sweepOrder);
    size.contactPoints = snapshot.points.size();
    size.contactBytes = sizeBytes(snapshot.contacts) + sizeBytes(snapshot.builtPoses) + sizeBytes(snapshot.points) +
                        sizeBytes(snapshot.pairs);
    size.fixedBytes = sizeof(WorldSnapshot);
    size.jointBytes = sizeBytes(snapshot.jointImpulses) + snapshot.jointRowsBytes;
    return size;
}

}  // namespace stepwise
