#include "01_integrators/oscillator.h"

#include <cmath>

namespace stepwise {

Eigen::Vector3d Oscillator::exactPosition(double t) const {
    return anchor.cast<double>() + offset.cast<double>() * math::cos(omega * t) +
           velocity.cast<double>() * (math::sin(omega * t) / omega);
}

int addOscillator(World& world, const Oscillator& oscillator) {
    BodyDef def;
    def.shape = Shape::sphere(Real(0.1));
    def.transform.position = oscillator.anchor + oscillator.offset;
    def.linearVelocity = oscillator.velocity;
    def.mass = oscillator.mass;
    Spring spring;
    spring.bodyA = addBody(world, def);
    spring.anchorB = oscillator.anchor;
    spring.stiffness = Real(oscillator.omega * oscillator.omega * oscillator.mass);
    world.springs.push_back(spring);
    return spring.bodyA;
}

}  // namespace stepwise
