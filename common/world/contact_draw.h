#pragma once
// The one way contacts are drawn, in every demo: what a contact query found (chapter 3's
// stepper and gallery) and what the world holds after a step (the demo's "contacts" view, with
// the solver's impulses from chapter 4 on). Flags choose what shows.

#include "world/debug_draw.h"
#include "world/world.h"

namespace stepwise {

struct ContactDrawOptions {
    bool points = true;             // a red cube on each body's surface: the gap between them is the depth
    bool normals = true;            // a yellow arrow of fixed length along the normal, from B's point
    bool impulses = false;          // instead of the fixed arrow: the normal impulse (yellow) and the
                                    // friction impulse (orange) of the last solve, as mean forces
    Real markerHalfSize = Real(0.03);   // m
    Real normalLength = Real(0.6);      // m
    Real metresPerNewton = Real(0.05);  // arrow length per newton of mean force over a substep
};

/// One contact given by its two surface points and its unit normal (A towards B).
void drawContact(DebugDraw& draw, const Vec3& pointA, const Vec3& pointB, const Vec3& normal,
                 const ContactDrawOptions& options = {});

/// Every point of World::contacts; impulses are read from the points (zero before a solver runs).
void drawContacts(DebugDraw& draw, const World& world, const ContactDrawOptions& options = {});

}  // namespace stepwise
