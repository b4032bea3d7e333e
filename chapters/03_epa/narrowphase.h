#pragma once
// The narrowphase of chapter 3: one contact (or an explicit "no contact") per pair of shapes.
// Pairs with a closed form (spheres, sphere-box, capsule-sphere, capsule-capsule) skip GJK and
// EPA; every other pair runs GJK (chapter 2) and, when it reports overlap, EPA.

#include "02_gjk/support.h"
#include "03_epa/epa.h"
#include "world/contact.h"
#include "world/shape.h"

#include <cstdint>

namespace stepwise {

struct ContactQuery {
    bool intersect = false;
    Real depth = 0;                   // > 0 overlap; < 0 minus the distance of a separated pair
    Vec3 normal = Vec3::UnitY();      // unit, from A towards B
    Vec3 pointA = Vec3::Zero();       // deepest point of A inside B (closest point when separated)
    Vec3 pointB = Vec3::Zero();       // deepest point of B inside A; pointA - pointB = depth*normal
    int gjkIterations = 0;            // both GJK runs (intersection, then distance) when separated
    int epaIterations = 0;
    std::uint32_t featureId = 0;      // touching features (world/contact.h), 0 when unknown
    const char* routine = "none";     // which routine answered, e.g. "gjk_epa", "sphere_box"
};

struct CollideOptions {
    EpaSettings epa;
    SupportMode supportMode = SupportMode::Extents;
    bool closedForms = true;          // false: every pair through GJK + EPA, round ones too (tests, bench)
    bool separationDistance = true;   // run GJK distance on separated pairs to fill depth
};

/// True when the pair has a closed-form routine (it never needs GJK or EPA).
bool hasClosedForm(ShapeType a, ShapeType b);

/// False for shapes no routine can answer: non-finite or non-positive sizes, a missing hull, and
/// the kinds that are not one convex set (compounds, meshes, height fields: chapter 13's).
bool isValidShape(const Shape& shape);

/// Contact between two placed shapes. Invalid input (bad shape, non-finite pose) gives
/// intersect = false, depth = 0 and routine "invalid": never NaN.
ContactQuery collideShapes(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                           const CollideOptions& options = CollideOptions{});

}  // namespace stepwise
