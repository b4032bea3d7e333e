#pragma once
// The chapter's jointed assemblies, built in code so the tests, the bench and the demo share
// them: a chain hanging from a fixed anchor, and a ragdoll.

#include "world/world.h"

#include <vector>

namespace stepwise {

struct ChainSpec {
    int links = 20;
    JointType joint = JointType::Distance;   // distance or ball_socket
    Real linkLength = Real(0.25);          // m between neighbouring joints
    Real linkRadius = Real(0.05);          // links are spheres
    Real linkMass = 1;                     // kg
    Real endMass = 0;                      // kg of the last link; 0: like the others
    Vec3 anchor = Vec3(0, 8, 0);           // the static anchor's position
    Vec3 direction = Vec3(0, -1, 0);       // the way the chain leaves the anchor at the start
    std::string prefix = "chain";
};

struct Chain {
    int anchorBody = -1;
    std::vector<int> links;                // body indices, from the anchor out
    std::vector<int> joints;               // joint indices, from the anchor out
    Real restLength = 0;                   // m, anchor to last link along the chain
};

/// A static anchor, then `links` spheres in a straight line along `direction`, each joined to the
/// one before (the first to the anchor) at their centres.
Chain addChain(World& world, const ChainSpec& spec);

/// How much longer the chain is than at rest, as a fraction: the sum over its joints of
/// the anchors' distance, minus the rest length, over the rest length.
Real chainStretch(const World& world, const Chain& chain);

// [ch08-ragdoll-spec]
struct RagdollSpec {
    Vec3 pelvis = Vec3(0, 1, 0);           // where the pelvis is (standing: feet at y = pelvis - 0.95)
    Quat orientation = Quat::Identity();   // the whole body turned about the pelvis
    Real mass = 70;                        // kg, shared out by human segment fractions
    /// N m at every joint (joint friction; Box2D's ragdoll does the same with zero-speed motors).
    /// Without it a pile never quite stops: a head keeps rocking in its neck's cone at 0.4 m/s
    /// after 8 s, a shin swings on its knee (tests/ch08/ragdoll_test.cpp).
    Real frictionTorque = Real(0.5);
    std::string prefix = "ragdoll";
};
// [ch08-ragdoll-spec]

struct Ragdoll {
    std::vector<int> bodies;               // pelvis, chest, head, arms (upper, fore) L R, legs (thigh, shin) L R
    std::vector<int> joints;
};

/// Eleven bodies (boxes for pelvis and chest, a sphere head, capsule limbs) standing with the arms
/// down: cone-twist joints at the spine, neck, shoulders and hips, hinges at elbows and knees, with
/// human-like limits and segment masses.
Ragdoll addRagdoll(World& world, const RagdollSpec& spec);

/// The largest joint error (position, m; angle, rad) over the given joints.
struct JointErrorSummary {
    Real position = 0;
    Real angle = 0;
};
JointErrorSummary largestJointError(const World& world, const std::vector<int>& joints);

}  // namespace stepwise
