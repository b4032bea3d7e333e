// Chapter 11's joints in the solve's graph: two ragdolls fallen onto a small pyramid, stepped by
// chapter 11's pipeline, their contacts coloured by colourContacts as the solve colours them, and
// the joints the solve sweeps one at a time before the colours.
#include "figures.h"

#include "08_joints/builders.h"
#include "08_joints/scenes.h"
#include "10_skip_work/scenes.h"
#include "11_wide_solve/chapter.h"
#include "11_wide_solve/colouring.h"
#include "11_wide_solve/solve_steps.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace figures {

using namespace stepwise;

// Named, not anonymous: the unity build puts every figure file in one translation unit.
namespace joint_pass_figures {

const char* const kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b",
                                "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"};

std::string colourOf(int colour) {
    return colour < 0 ? std::string("#000") : kPalette[colour % static_cast<int>(sizeof kPalette / sizeof kPalette[0])];
}

Point2 side(const Vec3& p) { return {static_cast<double>(p.x()), static_cast<double>(p.y())}; }

/// A 3-row pyramid with two ragdolls dropped across it, after two seconds of chapter 11's step.
World ragdollsOnAPile() {
    World world = buildPyramidRow(1, 3);
    for (int i = 0; i < 2; ++i) {
        RagdollSpec spec;
        spec.prefix = "ragdoll" + std::to_string(i);
        // Lying across the pyramid in the picture's plane, one above the other.
        spec.pelvis = Vec3(Real(0.3) - Real(0.6) * static_cast<Real>(i), Real(3.4) + Real(0.7) * static_cast<Real>(i), 0);
        spec.orientation = Quat(Eigen::AngleAxis<Real>(i == 0 ? kPi / 2 : -kPi / 2, Vec3::UnitZ()));
        addRagdoll(world, spec);
    }
    world.settings.sleeping = false;
    Pipeline pipeline = makeChapter11Pipeline(world);
    for (int frame = 0; frame < 120; ++frame) pipeline.step(world);
    return world;
}

bool isStatic(const World& world, int body) { return world.bodies[static_cast<std::size_t>(body)].type == BodyType::Static; }

bool jointsGraphFigure(const std::string& path) {
    const World world = ragdollsOnAPile();
    SolverBodies bodies;
    prepareBodies(world, bodies);
    std::vector<int> order, slotA, slotB, colours;
    std::vector<std::uint64_t> bits;
    for (std::size_t i = 0; i < world.contacts.size(); ++i) {
        const Contact& contact = world.contacts[i];
        if (!usableContact(world, contact, bodies)) continue;
        order.push_back(static_cast<int>(i));
        slotA.push_back(bodies.slotOfBody[static_cast<std::size_t>(contact.bodyA)]);
        slotB.push_back(bodies.slotOfBody[static_cast<std::size_t>(contact.bodyB)]);
    }
    colourContacts(slotA, slotB, static_cast<int>(bodies.states.size()), colours, bits, bodies.firstDynamic);

    Svg svg(980, 520);
    Real lowX = 0, highX = 0, highY = 0;
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        if (isStatic(world, static_cast<int>(i))) continue;
        const Vec3& p = world.bodies[i].transform.position;
        lowX = std::min(lowX, p.x());
        highX = std::max(highX, p.x());
        highY = std::max(highY, p.y());
    }
    const double pixels = std::min(600.0 / std::max(1.0, double(highX - lowX) + 0.6), 420.0 / (double(highY) + 0.6));
    const Viewport view{0, 40, 680, 460, {double(lowX + highX) / 2, double(highY) / 2}, pixels};
    svg.polygon(view, {{double(lowX) - 0.5, 0}, {double(highX) + 0.5, 0}, {double(highX) + 0.5, -0.15}, {double(lowX) - 0.5, -0.15}},
                "fill:#ddd;stroke:#999");
    std::vector<int> counts;
    for (std::size_t i = 0; i < order.size(); ++i) {
        const Contact& contact = world.contacts[static_cast<std::size_t>(order[i])];
        const int colour = colours[i];
        if (colour >= static_cast<int>(counts.size())) counts.resize(static_cast<std::size_t>(colour) + 1, 0);
        if (colour >= 0) ++counts[static_cast<std::size_t>(colour)];
        Vec3 middle = Vec3::Zero();
        for (int k = 0; k < contact.pointCount; ++k) middle += Real(0.5) * (contact.points[k].pointA + contact.points[k].pointB);
        middle /= static_cast<Real>(std::max(1, contact.pointCount));
        const auto end = [&](int body) {
            return isStatic(world, body) ? side(middle) : side(world.bodies[static_cast<std::size_t>(body)].transform.position);
        };
        svg.line(view, end(contact.bodyA), end(contact.bodyB),
                 "stroke:" + colourOf(colour) + ";stroke-width:4;stroke-linecap:round" + (colour < 0 ? ";stroke-dasharray:6 4" : ""));
    }
    for (const JointDesc& joint : world.joints)
        svg.line(view, side(world.bodies[static_cast<std::size_t>(joint.bodyA)].transform.position),
                 side(world.bodies[static_cast<std::size_t>(joint.bodyB)].transform.position),
                 "stroke:#222;stroke-width:2;stroke-dasharray:3 3");
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        if (isStatic(world, static_cast<int>(i))) continue;
        const bool box = world.bodies[i].name.rfind("ragdoll", 0) != 0;
        svg.circle(view, side(world.bodies[i].transform.position), box ? 0.12 : 0.06,
                   box ? "fill:#fff;stroke:#333;stroke-width:1.5" : "fill:#333;stroke:none");
    }
    char caption[200];
    std::snprintf(caption, sizeof caption, "two ragdolls on a 3-row pyramid: %d moving bodies, %zu contacts in %zu colours, %zu joints",
                  static_cast<int>(bodies.states.size()) - bodies.firstDynamic, order.size(), counts.size(), world.joints.size());
    svg.textAt({10, 24}, caption, "fill:#333");
    double y = 80;
    svg.textAt({700, y}, "colour: contacts", "font-weight:bold");
    for (std::size_t colour = 0; colour < counts.size(); ++colour) {
        y += 26;
        svg.rect(700, y - 12, 26, 12, colourOf(static_cast<int>(colour)));
        char line[80];
        std::snprintf(line, sizeof line, "colour %zu: %d", colour, counts[colour]);
        svg.textAt({736, y}, line);
    }
    y += 34;
    svg.textAt({700, y}, "- - -  a joint: swept one at a", "fill:#222");
    svg.textAt({700, y + 20}, "time, before the colours, in", "fill:#555");
    svg.textAt({700, y + 40}, "every pass of every substep", "fill:#555");
    svg.textAt({700, y + 70}, "open circles: boxes; dots:", "fill:#555");
    svg.textAt({700, y + 90}, "the ragdolls' limbs", "fill:#555");
    return svg.save(path);
}

}  // namespace joint_pass_figures

bool drawWideJoints(const std::string& path) { return joint_pass_figures::jointsGraphFigure(path); }

}  // namespace figures
