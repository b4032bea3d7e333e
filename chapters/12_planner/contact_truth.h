#pragma once
// A check of the narrowphase from outside it: a contact reads the depth its two shapes overlap by,
// no deeper and no shallower. Each manifold's deepest point is compared with the pair's true
// overlap, found afresh by chapter 3's query (closed forms, or GJK and EPA) at the bodies' poses.
// A held face or a normal turned the wrong way shows up as depth the shapes do not have, which
// pushes apart bodies that rest together; a clip that cut off the deepest corner, or a record
// carried while a corner it does not hold swung in, shows up as overlap the contact does not see,
// into which the bodies sink unresisted (bench speed's two depth columns).

#include "12_planner/chapter.h"
#include "world/world.h"

namespace stepwise {

/// How far a world's contacts read from their shapes' true overlap, m (0 when none is off).
struct ContactDepthErrors {
    Real deeper = 0;     // the most a point reads deeper than its shapes overlap
    Real shallower = 0;  // the most a pair's shapes overlap beyond its contact's deepest point
};

/// Over the world's contacts between two convex shapes (compounds, meshes and height fields are
/// left out: their parts answer for them).
ContactDepthErrors contactDepthErrors(const World& world);

/// Chapter 12's step of a copy of `start` for `frames` frames with `options`, untimed, with a stage
/// between its contact search and its solve that checks every manifold at the poses it was found
/// at (contactDepthErrors): the worst of each side over the run.
ContactDepthErrors depthAgainstTrue(const World& start, const SpeedOptions& options, long frames);

}  // namespace stepwise
