#include "07_ccd/shots.h"

#include "world/enum_names.h"

#include <cmath>

namespace stepwise {

const char* toString(ShotShape shape) {
    static const Names<ShotShape> names = {{"sphere", ShotShape::Sphere}, {"box", ShotShape::Box}, {"hull", ShotShape::Hull}};
    return nameOf(names, shape);
}

Shot randomShot(Random& random, Real speed) {
    Shot shot;
    shot.shape = static_cast<ShotShape>(int(random.uniform() * 3) % 3);
    shot.size = random.uniformReal(Real(0.01), Real(0.05));
    shot.speed = speed;
    // Up to 30 degrees off the wall normal: x = cos(angle), the rest in a random direction.
    const Real angle = random.uniformReal(0, kPi / 6);
    const Real around = random.uniformReal(0, 2 * kPi);
    shot.direction = Vec3(math::cos(angle), math::sin(angle) * math::cos(around), math::sin(angle) * math::sin(around));
    shot.orientation = random.rotation();
    const Vec3 spinAxis = random.unitVector();  // one draw per statement
    shot.spin = spinAxis * random.uniformReal(0, 50);
    shot.stepsBeforeWall = random.uniformReal(Real(0.3), Real(1.7));
    return shot;
}

static Shape shotShape(const Shot& shot) {
    switch (shot.shape) {
        case ShotShape::Sphere: return Shape::sphere(shot.size);
        case ShotShape::Box: return Shape::box(Vec3(shot.size, Real(0.6) * shot.size, Real(0.8) * shot.size));
        case ShotShape::Hull: {
            // An irregular octahedron: six tips on the axes, at different distances.
            const Real s = shot.size;
            return Shape::convex({Vec3(s, 0, 0), Vec3(-Real(0.7) * s, 0, 0), Vec3(0, Real(0.8) * s, 0),
                                  Vec3(0, -Real(0.6) * s, 0), Vec3(0, 0, Real(0.9) * s), Vec3(0, 0, -s)});
        }
    }
    return Shape::sphere(shot.size);
}

World buildShot(const Shot& shot, CcdMode ccd) {
    World world = emptyWorld(std::string("shot-") + toString(shot.shape), Vec3::Zero());
    world.settings.ccd = ccd;
    BodyDef wall;
    wall.name = "wall";
    wall.type = BodyType::Static;
    wall.shape = Shape::box(Vec3(kWallHalfThickness, 50, 50));
    addBody(world, wall);

    BodyDef body;
    body.name = "shot";
    body.shape = shotShape(shot);
    body.transform.rotation = shot.orientation;
    // The centre starts so far back that the body's front (bounding radius ahead) meets the
    // wall's near face after stepsBeforeWall steps.
    const Real reach = boundingRadius(body.shape);
    const Real travel = shot.speed * world.settings.dt * shot.stepsBeforeWall;
    const Real back = (kWallHalfThickness + reach + travel) / shot.direction.x();
    body.transform.position = -back * shot.direction;
    body.linearVelocity = shot.speed * shot.direction;
    body.angularVelocity = shot.spin;
    addBody(world, body);
    return world;
}

bool tunnelled(const World& world) { return world.bodies[1].transform.position.x() > kWallHalfThickness; }

}  // namespace stepwise
