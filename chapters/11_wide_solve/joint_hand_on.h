#pragma once
// The joints' rows handed from one piece of the fast solve to the next, and so from frame to frame.
// Within a piece a point joint keeps last substep's rows while its bodies have barely turned
// since they were built (kJointRowsKeptTurn); at rest that is almost every substep, so a piece
// that built every joint again on its first substep would spend most of its building there. A
// joint keeps its rows across the boundary too, on the same rule, when everything they were made
// from is as the last piece left it: its description, its bodies' poses bit for bit (nothing
// moved them between the solves), their masses, its impulses and the substep. Anything else
// builds it again, so a body a user moves, a motor a user turns up, a body that falls asleep or
// a new substep count costs one build and nothing more.
//
// The rows live in the World (StepState::jointRows), never in the pass: a copy of the World steps
// on exactly as the original (chapter 9's rewind relies on it). Copies share them until one steps
// on; that step copies them first (copy on write), a plain run never does.

#include "11_wide_solve/joint_pass.h"
#include "11_wide_solve/solver_data.h"
#include "world/world.h"

#include <vector>

namespace stepwise {

/// A joint's body as the piece left it: what its rows were made from, besides its turn.
struct HandedBody {
    int body = -1;
    Transform pose;
    Real inverseMass = 0;
    Vec3 localCenter = Vec3::Zero();
    Mat3 inverseInertiaLocal = Mat3::Zero();
};

// [ch11-handed-rows]
/// What the last piece left for the next: its rows in their lanes, each lane's turns at build made
/// relative to the poses it left (JointLaneGroup::builtA, builtB), and what they were made from.
struct HandedJointRows {
    PackedJointRows packed;
    std::vector<int> packedEntry;        // per listed joint: its entry, or -1 (left out)
    std::vector<int> joints;             // the listed joints (World::joints), in sweep order
    std::vector<JointRoom> rooms;        // the layout's
    std::vector<JointDesc> descs;        // per listed joint, as its rows were made from
    std::vector<JointImpulses> impulses; // per listed joint, as it left them in World::jointImpulses
    std::vector<HandedBody> bodies;      // per entry of the pass
    Real h = 0, jointHertz = 0, jointDampingRatio = 0;
    bool warmStarting = false;
};
// [ch11-handed-rows]

/// At a piece's start, after prepareJointPass: the rows the last piece left in the World, taken
/// into the pass (copied first if a copy of the World shares them). When the listed joints, their
/// bodies' slots and the substep are the last piece's, the layout stands (JointPass::laidOut) and
/// JointPass::handedLanes marks each joint whose description, bodies and impulses are as the last
/// piece left them: buildJointRows keeps its rows where its bodies have barely turned since.
void takeHandedJointRows(World& world, Real h, JointPass& pass);

/// At a piece's end, after the poses and impulses are back in the World: the pass's rows and what
/// they were made from into StepState::jointRows, each lane's turns at build made relative to the
/// poses now. The rows' errors must have moved with the piece's last substep (advanceJointErrors).
void handJointRowsOn(World& world, const SolverBodies& bodies, Real h, JointPass& pass);

}  // namespace stepwise
