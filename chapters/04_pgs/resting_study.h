#pragma once
// The resting-contact study: a body dropped 1 cm (or `drop`) onto the ground, stepped by the
// chapter 4 pipeline, with its penetration (measured by chapter 3's narrowphase, apart from
// the stages), tilt and position after every frame. The suite's resting claims and
// `stepwise bench resting` run this one study.

#include "04_pgs/chapter.h"

#include <string>
#include <vector>

namespace stepwise {

enum class RestingSubject {
    Ball,    // a 1 kg ball of radius 0.5 m
    Box,     // a 1 kg box of half size 0.5 m, held by one contact point
    Stack,   // a 1 kg ball of radius 0.4 m under a 10 kg one: the light ball is measured
};

struct RestingSetup {
    RestingSubject subject = RestingSubject::Ball;
    StepOrder order = StepOrder::SplitIntegration;
    int substeps = 1;
    Real drop = Real(0.01);   // m between the body's bottom and the ground at the start
};

struct RestingRun {
    std::string label;              // "box, one point", "ball, integrate first", ...
    std::vector<double> depth;      // m into the body below, per frame
    std::vector<double> tilt;       // rad between the body's up axis and +Y, per frame
    std::vector<Vec3> position;     // the body's centre, per frame

    double minDepth(int fromFrame) const;
    double maxDepth(int fromFrame) const;
    /// Horizontal distance the body travelled from `fromFrame` to the last frame, m.
    double drift(int fromFrame) const;
};

RestingRun runRestingStudy(const RestingSetup& setup, int frames);

}  // namespace stepwise
