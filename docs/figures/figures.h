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
bool drawGrownBoxes(const std::string& path);      // chapter 10: grown boxes and the pairs kept
bool drawCacheRule(const std::string& path);       // chapter 10: pairs' motion against the cache rule
bool drawIslands(const std::string& path);         // chapter 10: islands asleep and waking
bool drawWideColouring(const std::string& path);   // chapter 11: a pyramid's contacts coloured
bool drawWideLanes(const std::string& path);       // chapter 11: the contacts in blocks of lanes
bool drawLoadCrossing(const std::string& path);    // chapter 12: a load crossing a column sweep by sweep
bool drawShockLayers(const std::string& path);     // chapter 12: a pyramid's depths and shock-sweep groups

}  // namespace figures
