#pragma once
// Random worlds for the broadphase suite, in the layouts that trouble a sweep: spread out,
// coincident, a lattice of exactly touching boxes, all on one plane, one huge static ground
// under everything, far from the origin, at rest and fast. Seeded, the same on every platform.

#include "math/random.h"
#include "world/world.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace stepwise::test {

enum class Layout { Spread, Coincident, TouchingLattice, OnePlane, HugeGround, FarFromOrigin, Fast, Count };

inline const char* toString(Layout layout) {
    const char* const names[] = {"spread", "coincident", "touching lattice", "one plane", "huge ground", "far from origin", "fast"};
    return names[static_cast<int>(layout)];
}

inline Real uniformIn(Random& random, Real low, Real high) { return Real(random.uniform(low, high)); }

/// A whole number in [0, count).
inline int pick(Random& random, int count) { return std::min(count - 1, static_cast<int>(random.uniform() * count)); }

inline Shape randomShape(Random& random, Real size) {
    static const Shape diamond = Shape::convex({Vec3(Real(0.35), 0, 0), Vec3(Real(-0.35), 0, 0), Vec3(0, Real(0.5), 0),
                                                Vec3(0, Real(-0.5), 0), Vec3(0, 0, Real(0.35)), Vec3(0, 0, Real(-0.35))});
    switch (pick(random, 4)) {
        case 0: return Shape::sphere(size);
        case 1: return Shape::box(Vec3(size, size * Real(0.7), size * Real(0.5)));
        case 2: return Shape::capsule(size * Real(0.5), size);
        default: return diamond;
    }
}

/// A world of `count` bodies in the layout; body types mixed (mostly dynamic, some kinematic and
/// static) so the pair rule is exercised too.
inline World randomWorld(Random& random, Layout layout, int count) {
    World world;
    world.name = std::string("random ") + toString(layout);
    if (layout == Layout::HugeGround) {
        addStaticBox(world, "ground", Vec3(0, Real(-0.5), 0), Vec3(1000, Real(0.5), 1000));
    }
    const Vec3 offset = layout == Layout::FarFromOrigin ? Vec3(Real(9000), Real(-4000), Real(7000)) : Vec3::Zero();
    const int side = 1 + static_cast<int>(std::cbrt(static_cast<double>(count)));
    for (int i = 0; i < count; ++i) {
        BodyDef def;
        def.name = "b" + std::to_string(i);
        const int kind = pick(random, 10);
        def.type = kind == 0 ? BodyType::Static : kind == 1 ? BodyType::Kinematic : BodyType::Dynamic;
        def.shape = randomShape(random, uniformIn(random, Real(0.2), Real(1.5)));
        def.transform.rotation = random.rotation();
        Vec3 position(uniformIn(random, -10, 10), uniformIn(random, 0, 10), uniformIn(random, -10, 10));
        switch (layout) {
            case Layout::Coincident:
                def.shape = Shape::box(Vec3(Real(0.5), Real(0.5), Real(0.5)));
                def.transform.rotation = Quat::Identity();
                position = Vec3(1, 2, 3);
                break;
            case Layout::TouchingLattice:
                // Unit boxes one metre apart: every face flush with its neighbour's.
                def.shape = Shape::box(Vec3(Real(0.5), Real(0.5), Real(0.5)));
                def.transform.rotation = Quat::Identity();
                position = Vec3(static_cast<Real>(i % side), static_cast<Real>((i / side) % side), static_cast<Real>(i / (side * side)));
                break;
            case Layout::OnePlane: position.y() = 0; break;
            default: break;
        }
        def.transform.position = position + offset;
        if (def.type != BodyType::Static) {
            const Real speed = layout == Layout::Fast ? 200 : (pick(random, 3) == 0 ? 0 : 5);
            def.linearVelocity = Vec3(uniformIn(random, -1, 1), uniformIn(random, -1, 1), uniformIn(random, -1, 1)) * speed;
            def.angularVelocity = Vec3(uniformIn(random, -1, 1), uniformIn(random, -1, 1), uniformIn(random, -1, 1)) * speed;
        }
        addBody(world, def);
    }
    return world;
}

}  // namespace stepwise::test
