#pragma once
// The solver's unit of work: one scalar velocity constraint between two bodies.
//
// Every constraint this engine solves (a contact's normal, its two friction directions, and in
// chapter 8 every joint axis) is written as a row
//
//     J v = bias,   lower <= lambda <= upper
//
// where v = (vA, wA, vB, wB) stacks both bodies' velocities, J is the row's Jacobian, bias is the
// velocity the row asks for (0 for a resting contact, more to push out penetration or to bounce)
// and lambda is the impulse the row applies along J^T. The solver knows nothing else about where
// a row came from, so chapter 6 (warm starting) only sets `impulse` before solving and chapter 8
// (joints) only appends rows. The formulation is Erin Catto's, "Iterative Dynamics with Temporal
// Coherence" (GDC 2005) and "Fast and Simple Physics using Sequential Impulses" (GDC 2006).

#include "math/math.h"

namespace stepwise {

struct ConstraintRow {
    int bodyA = -1;                      // World body index
    int bodyB = -1;                      // World body index

    // Jacobian: J v = linearA.vA + angularA.wA + linearB.vB + angularB.wB.
    Vec3 linearA = Vec3::Zero();
    Vec3 angularA = Vec3::Zero();
    Vec3 linearB = Vec3::Zero();
    Vec3 angularB = Vec3::Zero();

    Real effectiveMass = 0;              // 1 / (J M^-1 J^T), kg (or kg m^2); 0 when no body can move
    Real bias = 0;                       // target of J v, m/s (or rad/s)

    // Bounds on the accumulated impulse. A row with boundRow >= 0 ignores lower/upper and is
    // bounded by plus or minus boundScale * rows[boundRow].impulse instead: a friction row is
    // bounded by mu times the impulse its normal row carries right now.
    Real lower = -kRealMax;
    Real upper = kRealMax;
    int boundRow = -1;
    Real boundScale = 0;

    Real impulse = 0;                    // accumulated this step, N s (or N m s)
};

/// The velocity state the solver reads and writes, one per World body. Static bodies have zero
/// inverse mass and inertia, so no row can move them; kinematic bodies have zero inverse mass
/// too but keep their velocity, which the rows see.
struct SolverBody {
    Vec3 linearVelocity = Vec3::Zero();   // of the centre of mass, m/s
    Vec3 angularVelocity = Vec3::Zero();  // rad/s
    Vec3 center = Vec3::Zero();           // centre of mass, world frame, m
    Real inverseMass = 0;                 // 1/kg
    Mat3 inverseInertia = Mat3::Zero();   // world axes, 1/(kg m^2)
};

}  // namespace stepwise
