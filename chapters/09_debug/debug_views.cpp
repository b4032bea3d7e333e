#include "09_debug/debug_views.h"

#include "02_gjk/chapter.h"
#include "02_gjk/scenes.h"
#include "03_epa/epa.h"
#include "08_joints/joint_view.h"
#include "world/contact_draw.h"

#include <algorithm>

namespace stepwise {

namespace {

bool validBody(const World& world, int body) { return body >= 0 && body < static_cast<int>(world.bodies.size()); }

constexpr Color kSelection = colors::kWhite;
constexpr Color kSimplex = colors::kMagenta;
constexpr Color kEpaFace = colors::kBlue;

/// A triangle that may have collapsed to a segment or a point on one shape (a vertex meeting a
/// face): drawn as what it is.
void drawFeature(DebugDraw& draw, const Vec3& a, const Vec3& b, const Vec3& c, Color color) {
    const Real size = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()});
    if (size < Real(1e-6)) {
        draw.point(a, 10, color);
        return;
    }
    if ((b - a).cross(c - a).norm() > Real(1e-6) * size * size) {
        draw.triangle(a, b, c, color);
        draw.triangle(a, c, b, color);   // both sides: the face is seen from inside the other body too
    }
    draw.line(a, b, color);
    draw.line(b, c, color);
    draw.line(c, a, color);
}

}  // namespace

// [ch09-diagnose]
PairDiagnosis diagnosePair(const World& world, int bodyA, int bodyB) {
    PairDiagnosis diagnosis;
    if (!validBody(world, bodyA) || !validBody(world, bodyB) || bodyA == bodyB) return diagnosis;
    const Body& a = world.bodies[static_cast<std::size_t>(bodyA)];
    const Body& b = world.bodies[static_cast<std::size_t>(bodyB)];
    diagnosis.bodyA = bodyA;
    diagnosis.bodyB = bodyB;
    const ConvexProxy proxyA = makeProxy(a), proxyB = makeProxy(b);
    const GjkResult gjk = gjkIntersect(proxyA, proxyB);
    diagnosis.overlapping = gjk.intersect;
    diagnosis.simplex = gjk.simplex;
    diagnosis.minkowskiPoints = minkowskiPoints(a, b, SupportMode::Extents);
    if (gjk.intersect) {
        const EpaResult epa = epaPenetration(proxyA, proxyB, gjk.simplex);
        diagnosis.hasEpaFace = epa.exit != EpaExit::Degenerate;
        std::copy(epa.closestFace, epa.closestFace + 3, diagnosis.epaFace);
        diagnosis.normal = epa.normal;
        diagnosis.depth = epa.depth;
    } else {
        const GjkDistanceResult distance = gjkDistance(proxyA, proxyB);
        diagnosis.simplex = distance.simplex;
        diagnosis.depth = -distance.distance;
        if (distance.distance > 0) diagnosis.normal = (distance.pointB - distance.pointA) / distance.distance;
    }
    return diagnosis;
}
// [ch09-diagnose]

BodyPair chosenPair(const World& world, const HitTree& tree, const HitSelection& selection, int selectedBody) {
    if (selection.pair >= 0 && selection.pair < static_cast<int>(tree.pairs.size())) {
        const HitPair& pair = tree.pairs[static_cast<std::size_t>(selection.pair)];
        return BodyPair{pair.bodyA, pair.bodyB};
    }
    if (validBody(world, selectedBody)) {
        for (const HitPair& pair : tree.pairs)
            if (pair.bodyA == selectedBody || pair.bodyB == selectedBody) return BodyPair{pair.bodyA, pair.bodyB};
    }
    if (!tree.pairs.empty()) return BodyPair{tree.pairs.front().bodyA, tree.pairs.front().bodyB};
    if (world.bodies.size() >= 2) return BodyPair{0, 1};
    return BodyPair{};
}

std::vector<char> wireframeBodies(const World& world, int selectedBody, const HitTree& tree, const HitSelection& selection) {
    std::vector<char> wire(world.bodies.size(), 0);
    const auto wireIfMoving = [&](int body) {
        if (world.bodies[static_cast<std::size_t>(body)].type != BodyType::Static) wire[static_cast<std::size_t>(body)] = 1;
    };
    if (validBody(world, selectedBody)) {
        wire[static_cast<std::size_t>(selectedBody)] = 1;
        for (const HitPair& pair : tree.pairs)
            if (pair.bodyA == selectedBody || pair.bodyB == selectedBody) {
                wireIfMoving(pair.bodyA);
                wireIfMoving(pair.bodyB);
            }
    }
    if (selection.pair >= 0 && selection.pair < static_cast<int>(tree.pairs.size())) {
        const HitPair& pair = tree.pairs[static_cast<std::size_t>(selection.pair)];
        wire[static_cast<std::size_t>(pair.bodyA)] = wire[static_cast<std::size_t>(pair.bodyB)] = 1;
    }
    return wire;
}

Vec3 minkowskiAnchor(const World& world, const PairDiagnosis& diagnosis) {
    Aabb moving;
    for (const Body& body : world.bodies)
        if (body.type != BodyType::Static) moving.grow(computeAabb(body.shape, body.transform));
    if (!(moving.min.array() <= moving.max.array()).all()) moving = Aabb{Vec3::Zero(), Vec3::Zero()};
    Aabb difference;
    for (const Vec3& point : diagnosis.minkowskiPoints) difference.grow(point);
    const Real reach = (difference.min.array() <= difference.max.array()).all() ? -difference.min.x() : Real(1);
    return Vec3(moving.max.x() + reach + Real(1), moving.center().y(), moving.center().z());
}

void drawDebugViews(DebugDraw& draw, const World& world, const DebugViews& views, int selectedBody,
                    const HitTree& tree, const HitSelection& selection) {
    // Bodies: the selection wireframes, so an overlap between them stays visible; the rest solid.
    const std::vector<char> wire = views.wireframeSelection ? wireframeBodies(world, selectedBody, tree, selection)
                                                            : std::vector<char>(world.bodies.size(), 0);
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        const Body& body = world.bodies[i];
        const Color color = bodyTypeColor(world, static_cast<int>(i));
        if (wire[i]) drawBody(draw, body, static_cast<int>(i) == selectedBody ? kSelection : color, Fill::Wire);
        else if (views.colliders) drawBody(draw, body, color, Fill::Solid);
    }

    if (views.bounds)
        for (const Body& body : world.bodies) {
            const Aabb box = computeAabb(body.shape, body.transform);
            draw.box(Transform{box.center(), Quat::Identity()}, box.extents(), colors::kCyan, Fill::Wire);
        }
    if (views.joints)
        for (const JointDesc& joint : world.joints) drawJoint(draw, world, joint);

    if (views.contactPoints || views.contactNormals) {
        ContactDrawOptions options;
        options.points = views.contactPoints;
        options.normals = views.contactNormals;
        drawContacts(draw, world, options);
    }
    if (const HitPoint* point = selectedPoint(tree, selection)) {
        const HitManifold& manifold =
            tree.pairs[static_cast<std::size_t>(selection.pair)].manifolds[static_cast<std::size_t>(selection.manifold)];
        const Vec3 half = Vec3::Constant(Real(0.05));
        draw.box(Transform{point->pointA, Quat::Identity()}, half, kSelection, Fill::Solid);
        draw.box(Transform{point->pointB, Quat::Identity()}, half, kSelection, Fill::Solid);
        draw.arrow(point->pointB, point->pointB + Real(0.8) * manifold.normal, kSelection);
    }

    if (!views.epaFace && !views.gjkSimplex && !views.minkowski) return;
    const BodyPair pair = chosenPair(world, tree, selection, selectedBody);
    const PairDiagnosis diagnosis = diagnosePair(world, pair.bodyA, pair.bodyB);
    if (diagnosis.bodyA < 0) return;
    const SupportPoint* face = diagnosis.epaFace;
    if (views.epaFace && diagnosis.hasEpaFace) {
        drawFeature(draw, face[0].onA, face[1].onA, face[2].onA, kEpaFace);
        drawFeature(draw, face[0].onB, face[1].onB, face[2].onB, kEpaFace);
    }
    if (!views.gjkSimplex && !views.minkowski) return;
    const Vec3 anchor = minkowskiAnchor(world, diagnosis);
    const Real mark = Real(0.15);
    for (int axis = 0; axis < 3; ++axis)
        draw.line(anchor - mark * Vec3::Unit(axis), anchor + mark * Vec3::Unit(axis), colors::kWhite);
    draw.text(anchor + Vec3(0, -mark, 0), "origin of A - B", colors::kWhite);
    if (views.minkowski) {
        const Color hullColor = diagnosis.overlapping ? colors::kRed : colors::kGreen;
        for (const Vec3& point : diagnosis.minkowskiPoints) draw.point(anchor + point, 4, colors::kGrey);
        try {
            draw.hull(Transform{anchor, Quat::Identity()}, buildConvexHull(diagnosis.minkowskiPoints), hullColor, Fill::Wire);
        } catch (const HullError&) {
            // A flat difference has no hull; its points still show it.
        }
        if (views.epaFace && diagnosis.hasEpaFace)
            drawFeature(draw, anchor + face[0].w, anchor + face[1].w, anchor + face[2].w, kEpaFace);
    }
    if (views.gjkSimplex) {
        const Simplex& simplex = diagnosis.simplex;
        for (int i = 0; i < simplex.count; ++i) {
            draw.point(anchor + simplex.vertices[i].w, 8, kSimplex);
            for (int j = i + 1; j < simplex.count; ++j)
                draw.line(anchor + simplex.vertices[i].w, anchor + simplex.vertices[j].w, kSimplex);
        }
    }
}

}  // namespace stepwise
