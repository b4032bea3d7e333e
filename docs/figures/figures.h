#pragma once
// The course's figures, each drawn by the engine's own code into an SVG file. The docs build
// runs `stepwise_figures <dir>`; the pages show the files with \image.

#include "svg.h"

#include <string>

namespace figures {

bool drawMinkowski(const std::string& path);        // chapter 2: A - B and a support point
bool drawVoronoiRegions(const std::string& path);   // chapter 2: a triangle's Voronoi regions
bool drawEpaHorizon(const std::string& path);       // chapter 3: the polytope and its horizon
bool drawContactArms(const std::string& path);      // chapter 4: the Jacobian's arms
bool drawFrictionPyramid(const std::string& path);  // chapter 4: friction pyramid against cone
bool drawBaumgarteEnergy(const std::string& path);  // chapter 4: Baumgarte's energy gain
bool drawSweepIntervals(const std::string& path);   // chapter 5: boxes, intervals, pairs
bool drawManifoldClipping(const std::string& path); // chapter 6: reference and incident face, clipping
bool drawCcdAdvancement(const std::string& path);   // chapter 7: conservative advancement's queries and bounds
bool drawToiLoop(const std::string& path);          // chapter 7: the sorted TOI loop on a timeline
bool drawHingeFrame(const std::string& path);       // chapter 8: a hinge's anchors, axes and angle
bool drawSwingTwist(const std::string& path);       // chapter 8: a cone-twist's cone, swing and twist
bool drawRagdollLimits(const std::string& path);    // chapter 8: the ragdoll's cones and hinge ranges
bool drawHitTree(const std::string& path);          // chapter 9: the hit result tree of debug-drop
bool drawRewindTimeline(const std::string& path);   // chapter 9: the history ring, a rewind, a speculative branch
bool drawRaySlabs(const std::string& path);         // chapter 9: the slab test of a ray against a box
bool drawIntegratorPhase(const std::string& path);  // chapter 1: the oscillator in phase space
bool drawIntegratorEnergy(const std::string& path); // chapter 1: the oscillator's energy over time
bool drawDepthReach(const std::string& path);       // chapter 3: the depth as the smallest reach of A - B
bool drawBoxSphereCases(const std::string& path);   // chapter 3: box-sphere, centre outside and inside
bool drawGrownBoxes(const std::string& path);      // chapter 10: grown boxes and the pairs kept
bool drawCacheRule(const std::string& path);       // chapter 10: pairs' motion against the cache rule
bool drawIslands(const std::string& path);         // chapter 10: islands asleep and waking
bool drawWideColouring(const std::string& path);   // chapter 11: a pyramid's contacts coloured
bool drawWideLanes(const std::string& path);       // chapter 11: the contacts in blocks of lanes
bool drawWideJoints(const std::string& path);      // chapter 11: ragdolls on a pile, contacts coloured, joints apart
bool drawLoadCrossing(const std::string& path);    // chapter 12: a load crossing a column sweep by sweep
bool drawShockLayers(const std::string& path);     // chapter 12: a pyramid's depths and shock-sweep groups
bool drawMeshTree(const std::string& path);        // chapter 13: a mesh's tree and the triangles a box finds
bool drawSeamNormals(const std::string& path);     // chapter 13: a corner at a seam, normals with the fix off and on

bool drawSweepAxisChoice(const std::string& path);  // chapter 5: intervals along x and along y
bool drawManifoldReduction(const std::string& path); // chapter 6: four of a patch's corners, feature ids
bool drawImpulseArm(const std::string& path);       // primer: effective mass along a face
bool drawComplementarity(const std::string& path);  // primer: a contact row and a friction row
}  // namespace figures
