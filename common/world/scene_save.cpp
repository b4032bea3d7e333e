// Scenes out: the inverse of loading, up to float round-off (scene_load.cpp reads them back).
#include "world/json_reader.h"
#include "world/scene.h"

#include <cmath>
#include <stdexcept>

namespace stepwise {
namespace {

Json meshToJson(const TriangleMesh& mesh) {
    Json vertices = Json::array(), triangles = Json::array();
    for (const Vec3& vertex : mesh.vertices) vertices.push_back(toJson(vertex));
    for (const auto& corners : mesh.triangles) triangles.push_back({corners[0], corners[1], corners[2]});
    return {{"mesh", {{"vertices", vertices}, {"triangles", triangles}}}};  // an OBJ's mesh is saved inline
}

Json heightFieldToJson(const HeightField& field) {
    Json heights = Json::array();
    for (const Real height : field.heights) heights.push_back(std::isnan(height) ? Json(nullptr) : tidyNumber(height));
    return {{"heightfield",
             {{"rows", field.rows}, {"columns", field.columns}, {"cell_size", tidyNumber(field.cellSize)}, {"heights", heights}}}};
}

Json shapeToJson(const Shape& shape);

Json compoundToJson(const CompoundShape& compound) {
    Json children = Json::array();
    for (const CompoundChild& child : compound.children)
        children.push_back({{"shape", shapeToJson(child.shape)},
                            {"position", toJson(child.transform.position)},
                            {"orientation", toJson(child.transform.rotation)}});
    return {{"compound", {{"children", children}}}};
}

Json shapeToJson(const Shape& shape) {
    switch (shape.type) {
    case ShapeType::Box: return {{"box", {{"half_extents", toJson(shape.halfExtents)}}}};
    case ShapeType::Sphere: return {{"sphere", {{"radius", tidyNumber(shape.radius)}}}};
    case ShapeType::Capsule:
        return {{"capsule", {{"radius", tidyNumber(shape.radius)}, {"half_height", tidyNumber(shape.halfHeight)}}}};
    case ShapeType::Cylinder:
        return {{"cylinder", {{"radius", tidyNumber(shape.radius)}, {"half_height", tidyNumber(shape.halfHeight)}}}};
    case ShapeType::Compound: return compoundToJson(*shape.compound);
    case ShapeType::Mesh: return meshToJson(*shape.mesh);
    case ShapeType::HeightField: return heightFieldToJson(*shape.heightField);
    case ShapeType::Convex: break;
    }
    Json vertices = Json::array();
    if (shape.hull)
        for (const Vec3& vertex : shape.hull->vertices) vertices.push_back(toJson(vertex));
    return {{"convex", {{"vertices", vertices}}}};
}

const std::string& bodyName(const World& world, int index) {
    if (index < 0 || std::size_t(index) >= world.bodies.size())
        throw std::invalid_argument("saveSceneToString: body index " + std::to_string(index) + " out of range");
    return world.bodies[std::size_t(index)].name;
}

Json settingsToJson(const Settings& s) {
    return {{"gravity", toJson(s.gravity)},
            {"dt", tidyNumber(s.dt)},
            {"substeps", s.substeps},
            {"solver_iterations", s.planIterations && s.solverIterations == Settings{}.solverIterations
                                      ? Json("auto") : Json(s.solverIterations)},
            {"plan_iterations", s.planIterations},
            {"baumgarte", tidyNumber(s.baumgarte)},
            {"slop", tidyNumber(s.slop)},
            {"warm_starting", s.warmStarting},
            {"broadphase", toString(s.broadphase)},
            {"ccd", toString(s.ccd)},
            {"integrator", toString(s.integrator)},
            {"gyroscopic", toString(s.gyroscopic)},
            {"solver", toString(s.solver)},
            {"restitution_threshold", tidyNumber(s.restitutionThreshold)},
            {"stabilisation", toString(s.stabilisation)},
            {"contact_points", s.manifoldContacts ? "manifold" : "one_point"},
            {"sleeping", s.sleeping},
            {"sleep_speed", tidyNumber(s.sleepSpeed)},
            {"time_to_sleep", tidyNumber(s.timeToSleep)},
            {"contact_hertz", tidyNumber(s.contactHertz)},
            {"contact_damping_ratio", tidyNumber(s.contactDampingRatio)},
            {"joint_hertz", tidyNumber(s.jointHertz)},
            {"joint_damping_ratio", tidyNumber(s.jointDampingRatio)},
            {"max_push_out_speed", tidyNumber(s.maxPushOutSpeed)},
            {"bounds_margin", tidyNumber(s.boundsMargin)},
            {"active_edges", s.activeEdges}};
}

Json bodyToJson(const World& world, std::size_t i) {
    const Body& body = world.bodies[i];
    Json out = {{"name", body.name}, {"type", toString(body.type)}, {"shape", shapeToJson(body.shape)},
                {"position", toJson(body.transform.position)}, {"orientation", toJson(body.transform.rotation)}};
    if (const Motion* motion = world.motionOf(int(i))) {
        out["velocity"] = toJson(motion->linearVelocity);
        out["angular_velocity"] = toJson(motion->angularVelocity);
        if (body.type == BodyType::Dynamic) out["mass"] = tidyNumber(motion->mass);
        if (motion->integrator) out["integrator"] = toString(*motion->integrator);
    }
    out["friction"] = tidyNumber(body.material.friction);
    out["restitution"] = tidyNumber(body.material.restitution);
    if (body.material.rollingResistance > 0) out["rolling_resistance"] = tidyNumber(body.material.rollingResistance);
    if (body.bullet) out["bullet"] = true;
    for (const KinematicPath& path : world.kinematicPaths)
        if (path.body == int(i))
            out["path"] = {{"amplitude", toJson(path.amplitude)}, {"period", tidyNumber(path.period)},
                           {"phase", tidyNumber(std::fmod(path.phase + 2 * kPi * Real(world.time) / path.period, 2 * kPi))}};
    return out;
}

Json jointToJson(const World& world, const JointDesc& joint) {
    const auto pair = [](const std::pair<Real, Real>& v) { return Json{tidyNumber(v.first), tidyNumber(v.second)}; };
    Json out = {{"type", toString(joint.type)}, {"a", bodyName(world, joint.bodyA)}, {"b", bodyName(world, joint.bodyB)},
                {"anchor_a", toJson(joint.localAnchorA)}, {"anchor_b", toJson(joint.localAnchorB)}};
    if (joint.collideConnected) out["collide_connected"] = true;
    const JointType type = joint.type;
    if (type == JointType::Distance && joint.length) out["length"] = tidyNumber(*joint.length);
    if (type == JointType::Distance && joint.springHertz > 0) {
        out["spring_hertz"] = tidyNumber(joint.springHertz);
        out["spring_damping_ratio"] = tidyNumber(joint.springDampingRatio);
    }
    const bool hasAxis = type == JointType::Hinge || type == JointType::ConeTwist || type == JointType::Slider;
    if (hasAxis) out["axis"] = toJson(joint.axis);
    if (hasAxis || type == JointType::Fixed) out["reference_rotation"] = toJson(joint.referenceRotation);
    if ((type == JointType::Hinge || type == JointType::Slider) && joint.limits) out["limits"] = pair(*joint.limits);
    if ((type == JointType::Hinge || type == JointType::Slider) && joint.motor)
        out["motor"] = {{"speed", tidyNumber(joint.motor->speed)},
                        {type == JointType::Hinge ? "max_torque" : "max_force", tidyNumber(joint.motor->maxForce)}};
    if (type == JointType::ConeTwist) {
        out["cone_angle"] = tidyNumber(joint.coneAngle);
        if (joint.twistLimits) out["twist_limits"] = pair(*joint.twistLimits);
    }
    if ((type == JointType::ConeTwist || type == JointType::Hinge) && joint.frictionTorque > 0)
        out["friction_torque"] = tidyNumber(joint.frictionTorque);
    return out;
}

/// The springs, then the dampings.
Json forcesToJson(const World& world) {
    Json forces = Json::array();
    for (const Spring& spring : world.springs) {
        Json out = {{"type", "spring"}, {"a", bodyName(world, spring.bodyA)}};
        if (spring.bodyB >= 0) out["b"] = bodyName(world, spring.bodyB);
        out["anchor_a"] = toJson(spring.localAnchorA);
        out["anchor_b"] = toJson(spring.anchorB);
        out["rest_length"] = tidyNumber(spring.restLength);
        out["stiffness"] = tidyNumber(spring.stiffness);
        out["damping"] = tidyNumber(spring.damping);
        forces.push_back(out);
    }
    for (const Damping& damping : world.dampings) {
        Json out = {{"type", "damping"}};
        if (damping.body >= 0) out["body"] = bodyName(world, damping.body);
        out["linear"] = tidyNumber(damping.linear);
        out["angular"] = tidyNumber(damping.angular);
        forces.push_back(out);
    }
    return forces;
}

}  // namespace

std::string saveSceneToString(const World& world) {
    Json scene = {{"format", "stepwise-scene"}, {"version", 1}, {"name", world.name}};
    scene["settings"] = settingsToJson(world.settings);
    Json bodies = Json::array();
    for (std::size_t i = 0; i < world.bodies.size(); ++i) bodies.push_back(bodyToJson(world, i));
    scene["bodies"] = bodies;
    Json joints = Json::array();
    for (const JointDesc& joint : world.joints) joints.push_back(jointToJson(world, joint));
    if (!joints.empty()) scene["joints"] = joints;
    const Json forces = forcesToJson(world);
    if (!forces.empty()) scene["forces"] = forces;
    return scene.dump(2) + "\n";
}

}  // namespace stepwise
