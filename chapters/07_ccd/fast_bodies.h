#pragma once
// Which bodies need continuous collision. A body that moves less than half its own thinnest
// width in a step cannot pass through anything as thick as itself, and the speculative contacts
// of chapters 3 and 6 catch it; one that moves more may (Box2D v3 draws the same line: a body is
// "fast" past half its minimum extent per step). Bodies flagged `bullet` are always checked.

#include "07_ccd/sweep.h"

#include <string>

namespace stepwise {

// [ch07-fast-fraction]
/// A body is fast when its travel in a step exceeds this fraction of its smallest extent.
constexpr Real kFastTravelFraction = Real(0.5);
// [ch07-fast-fraction]

/// The thinnest width of the shape, m: a box's smallest edge, a sphere's or capsule's diameter,
/// a hull's smallest distance between a face plane and the farthest vertex behind it.
Real smallestExtent(const Shape& shape);

/// How far the body would travel in a step of dt with its velocities now, as a fraction of its
/// smallest extent (the planner's guess before any step has run). 0 for static bodies.
Real travelPerExtent(const World& world, int body, Real dt);

/// Whether the TOI loop checks this body's sweep: a dynamic bullet, or a dynamic body travelling
/// more than kFastTravelFraction of its smallest extent.
bool needsContinuousCollision(const Body& body, const Sweep& sweep);

/// What the planner decided for a scene, and why, in words for the run report.
struct CcdPlan {
    bool included = false;
    std::string reason;
};

/// settings.ccd "off": no stage; "on": always; "auto": when the scene has a dynamic bullet or a
/// body that already moves fast at the start (a body that becomes fast later needs `bullet` or
/// "on"; chapter 7's page says why the planner cannot see it coming).
CcdPlan planContinuousCollision(const World& world);

}  // namespace stepwise
