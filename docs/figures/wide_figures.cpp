// Figures for chapter 11, computed by the engine's own colouring and block building: a small
// pyramid stepped by chapter 11's pipeline, its contacts coloured by colourContacts and packed into
// blocks by buildWideBlocks, as the solve does every frame; two ragdolls fallen on such a pyramid,
// their joints beside the colours.
#include "figures.h"

#include "08_joints/builders.h"
#include "10_skip_work/scenes.h"
#include "11_wide_solve/chapter.h"
#include "11_wide_solve/colouring.h"
#include "11_wide_solve/joint_pass.h"
#include "11_wide_solve/solve_steps.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace figures {

using namespace stepwise;

// Named, not anonymous: the unity build puts every figure file in one translation unit.
namespace wide_figures {

const char* const kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b",
                                "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"};

std::string colourOf(int colour) {
    return colour < 0 ? std::string("#000") : kPalette[colour % static_cast<int>(sizeof kPalette / sizeof kPalette[0])];
}

Point2 side(const Vec3& p) { return {static_cast<double>(p.x()), static_cast<double>(p.y())}; }

/// A small pyramid after two frames of chapter 11's step: every contact is in World::contacts.
World settledPyramid(int rows) {
    World world = buildPyramidRow(1, rows);
    Pipeline pipeline = makeChapter11Pipeline(world);
    for (int frame = 0; frame < 2; ++frame) pipeline.step(world);
    return world;
}

/// The frame's solver bodies and the contacts the solve takes, with their slots (what the solve
/// gathers before it colours).
void gatherForSolve(const World& world, ContactSolverScratch& scratch) {
    prepareBodies(world, scratch.bodies);
    scratch.contactOrder.clear();
    scratch.slotA.clear();
    scratch.slotB.clear();
    for (std::size_t i = 0; i < world.contacts.size(); ++i) {
        const Contact& contact = world.contacts[i];
        if (!usableContact(world, contact, scratch.bodies)) continue;
        scratch.contactOrder.push_back(static_cast<int>(i));
        scratch.slotA.push_back(scratch.bodies.slotOfBody[static_cast<std::size_t>(contact.bodyA)]);
        scratch.slotB.push_back(scratch.bodies.slotOfBody[static_cast<std::size_t>(contact.bodyB)]);
    }
}

bool isStatic(const World& world, int body) { return world.bodies[static_cast<std::size_t>(body)].type == BodyType::Static; }

/// The pyramid's boxes from the side, numbered by body index, and the ground as a grey band.
void drawPyramid(Svg& svg, const Viewport& view, const World& world) {
    svg.polygon(view, {{-3.6, 0}, {3.6, 0}, {3.6, -0.35}, {-3.6, -0.35}}, "fill:#ddd;stroke:#999");
    svg.text(view, {-3.5, -0.28}, "ground (slot 0)", "fill:#555;font-size:12px");
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        if (isStatic(world, static_cast<int>(i))) continue;
        const Transform& pose = world.bodies[i].transform;
        std::vector<Point2> outline;
        for (const Vec3& corner : {Vec3(-0.5, -0.5, 0), Vec3(0.5, -0.5, 0), Vec3(0.5, 0.5, 0), Vec3(-0.5, 0.5, 0)})
            outline.push_back(side(pose.apply(corner)));
        svg.polygon(view, outline, "fill:#f4f4f4;stroke:#aaa;stroke-width:1");
    }
}

/// Where a contact's edge runs: centre to centre between two boxes, centre to the points' mean on
/// the ground for a box on the ground.
void contactEnds(const World& world, const Contact& contact, Point2& from, Point2& to) {
    Vec3 middle = Vec3::Zero();
    for (int i = 0; i < contact.pointCount; ++i) middle += Real(0.5) * (contact.points[i].pointA + contact.points[i].pointB);
    middle /= static_cast<Real>(std::max(1, contact.pointCount));
    const auto end = [&](int body) {
        return isStatic(world, body) ? side(middle) : side(world.bodies[static_cast<std::size_t>(body)].transform.position);
    };
    from = end(contact.bodyA);
    to = end(contact.bodyB);
}

std::string boxLabel(const World& world, int body) { return isStatic(world, body) ? "G" : std::to_string(body); }

/// The colours' key from (x, y) down, a line of `step` pixels each; returns the last line's y.
double drawColourLegend(Svg& svg, double x, double y, double step, const std::vector<int>& counts) {
    svg.textAt({x, y}, "colour: contacts", "font-weight:bold");
    for (std::size_t colour = 0; colour < counts.size(); ++colour) {
        y += step;
        svg.rect(x, y - 12, 26, 12, colourOf(static_cast<int>(colour)));
        char line[80];
        std::snprintf(line, sizeof line, "colour %zu: %d", colour, counts[colour]);
        svg.textAt({x + 36, y}, line);
    }
    return y;
}

/// Each contact the solve takes as an edge in its colour (dashed black: the overflow); the count
/// of contacts in each colour.
std::vector<int> drawColouredContacts(Svg& svg, const Viewport& view, const World& world,
                                      const ContactSolverScratch& scratch, int width) {
    std::vector<int> counts;
    for (std::size_t i = 0; i < scratch.contactOrder.size(); ++i) {
        const Contact& contact = world.contacts[static_cast<std::size_t>(scratch.contactOrder[i])];
        const int colour = scratch.colours[i];
        if (colour >= static_cast<int>(counts.size())) counts.resize(static_cast<std::size_t>(colour) + 1, 0);
        if (colour >= 0) ++counts[static_cast<std::size_t>(colour)];
        Point2 from, to;
        contactEnds(world, contact, from, to);
        svg.line(view, from, to,
                 "stroke:" + colourOf(colour) + ";stroke-width:" + std::to_string(width) + ";stroke-linecap:round" +
                     (colour < 0 ? ";stroke-dasharray:6 4" : ""));
    }
    return counts;
}


bool colouringFigure(const std::string& path) {
    // A 5-row pyramid's contact graph: nodes are the boxes, edges their contacts, each edge in the
    // colour colourContacts gives it. The ground is slot 0 and blocks no colour.
    const World world = settledPyramid(5);
    ContactSolverScratch scratch;
    gatherForSolve(world, scratch);
    colourContacts(scratch.slotA, scratch.slotB, static_cast<int>(scratch.bodies.states.size()), scratch.colours,
                   scratch.colourBits);

    Svg svg(960, 490);
    const Viewport view{0, 45, 640, 440, {0, 2.35}, 80};
    drawPyramid(svg, view, world);
    const std::vector<int> counts = drawColouredContacts(svg, view, world, scratch, 5);
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        if (isStatic(world, static_cast<int>(i))) continue;
        const Point2 at = side(world.bodies[i].transform.position);
        svg.circle(view, at, 0.17, "fill:#fff;stroke:#333;stroke-width:1.5");
        svg.text(view, {at.x - (i < 10 ? 0.06 : 0.12), at.y - 0.07}, std::to_string(i), "font-size:13px");
    }
    char caption[200];
    std::snprintf(caption, sizeof caption, "a 5-row pyramid: %d moving bodies, %zu contacts, %zu colours",
                  static_cast<int>(scratch.bodies.states.size()) - 1, scratch.contactOrder.size(), counts.size());
    svg.textAt({10, 24}, caption, "fill:#333");
    double y = 80;
    y = drawColourLegend(svg, 660, y, 28, counts);
    y += 44;
    svg.textAt({660, y}, "No two edges of one colour", "fill:#555");
    svg.textAt({660, y + 20}, "meet at a box: a colour's", "fill:#555");
    svg.textAt({660, y + 40}, "contacts can be solved at once.", "fill:#555");
    svg.textAt({660, y + 70}, "The ground holds no colour:", "fill:#555");
    svg.textAt({660, y + 90}, "every bottom box takes colour 0.", "fill:#555");
    return svg.save(path);
}

bool lanesFigure(const std::string& path) {
    // The same pyramid's contacts as buildWideBlocks packs them: each colour cut into blocks of
    // kWideLanes lanes, the last one padded with empty lanes; a colour of one contact goes to the
    // overflow, solved one at a time after the blocks.
    const World world = settledPyramid(5);
    ContactSolverScratch scratch;
    gatherForSolve(world, scratch);
    const Real h = Real(1.0 / 60) / static_cast<Real>(std::max(1, world.settings.solverIterations));
    buildWideBlocks(world, scratch, solveParams(world.settings, h, Real(1.0 / 60)));
    std::vector<int> colourOfContact(world.contacts.size(), -1);
    for (std::size_t i = 0; i < scratch.contactOrder.size(); ++i)
        colourOfContact[static_cast<std::size_t>(scratch.contactOrder[i])] = scratch.colours[i];

    const double cell = std::min(52.0, 800.0 / kWideLanes), left = 130, top = 70, rowHeight = 38;
    const int rows = static_cast<int>(scratch.wideBlocks.size() + scratch.scalarBlocks.size());
    Svg svg(std::max(720.0, left + cell * kWideLanes + 30), top + rowHeight * (rows + 1) + 40);
    char caption[200];
    std::snprintf(caption, sizeof caption, "the 5-row pyramid's %zu contacts in blocks of %d lanes (this build's kWideLanes)",
                  scratch.contactOrder.size(), kWideLanes);
    svg.textAt({10, 24}, caption, "fill:#333");
    for (int lane = 0; lane < kWideLanes; ++lane)
        svg.textAt({left + cell * lane + cell / 2 - 5, top - 10}, std::to_string(lane), "fill:#555;font-size:12px");
    svg.textAt({left - 120, top - 10}, "lane", "fill:#555;font-size:12px");
    double y = top;
    const auto drawCell = [&](int lane, int contactIndex) {
        const double x = left + cell * lane;
        if (contactIndex < 0) {
            svg.rect(x + 1, y + 1, cell - 2, rowHeight - 2, "#eee");
            return;
        }
        const Contact& contact = world.contacts[static_cast<std::size_t>(contactIndex)];
        svg.rect(x + 1, y + 1, cell - 2, rowHeight - 2, colourOf(colourOfContact[static_cast<std::size_t>(contactIndex)]));
        const std::string label = boxLabel(world, contact.bodyA) + "-" + boxLabel(world, contact.bodyB);
        svg.textAt({x + 4, y + rowHeight / 2 + 4}, label, "fill:#fff;font-size:11px;font-weight:bold");
    };
    for (std::size_t block = 0; block < scratch.wideBlocks.size(); ++block, y += rowHeight) {
        const ManifoldBlock<kWideLanes>& b = scratch.wideBlocks[block];
        char name[64];
        std::snprintf(name, sizeof name, "block %zu", block);
        svg.textAt({left - 120, y + rowHeight / 2 + 5}, name);
        for (int lane = 0; lane < kWideLanes; ++lane) drawCell(lane, b.contactIndex[lane]);
    }
    for (const ManifoldBlock<1>& b : scratch.scalarBlocks) {
        svg.textAt({left - 120, y + rowHeight / 2 + 5}, "overflow");
        drawCell(0, b.contactIndex[0]);
        y += rowHeight;
    }
    svg.textAt({10, y + 30}, "Each cell is one contact (body-body, G the ground), coloured by its colour; grey lanes are empty.",
               "fill:#555;font-size:12px");
    return svg.save(path);
}

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


bool jointsFigure(const std::string& path) {
    const World world = ragdollsOnAPile();
    ContactSolverScratch scratch;
    gatherForSolve(world, scratch);
    const SolverBodies& bodies = scratch.bodies;
    colourContacts(scratch.slotA, scratch.slotB, static_cast<int>(bodies.states.size()), scratch.colours,
                   scratch.colourBits, bodies.firstDynamic);

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
    const std::vector<int> counts = drawColouredContacts(svg, view, world, scratch, 4);
    // The joints' lane groups, as the fast solve lays them out at the frame's first substep.
    JointPass pass;
    prepareJointPass(world, bodies, 1, pass);
    buildJointRows(world, bodies, world.settings.dt / Real(std::max(1, world.settings.solverIterations)), true, pass);
    for (std::size_t i = 0; i < pass.joints.size(); ++i) {
        const JointDesc& joint = world.joints[static_cast<std::size_t>(pass.joints[i])];
        const Vec3& a = world.bodies[static_cast<std::size_t>(joint.bodyA)].transform.position;
        const Vec3& b = world.bodies[static_cast<std::size_t>(joint.bodyB)].transform.position;
        svg.line(view, side(a), side(b), "stroke:#222;stroke-width:2;stroke-dasharray:3 3");
        svg.text(view, side((a + b) / 2), std::to_string(pass.packed.joints[i].group + 1), "fill:#a00;font-size:13px;font-weight:bold");
    }
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        if (isStatic(world, static_cast<int>(i))) continue;
        const bool box = world.bodies[i].name.rfind("ragdoll", 0) != 0;
        svg.circle(view, side(world.bodies[i].transform.position), box ? 0.12 : 0.06,
                   box ? "fill:#fff;stroke:#333;stroke-width:1.5" : "fill:#333;stroke:none");
    }
    char caption[200];
    std::snprintf(caption, sizeof caption,
                  "two ragdolls on a 3-row pyramid: %d moving bodies, %zu contacts in %zu colours, %zu joints in %d lane groups",
                  static_cast<int>(bodies.states.size()) - bodies.firstDynamic, scratch.contactOrder.size(), counts.size(),
                  world.joints.size(), pass.packed.groupCount);
    svg.textAt({10, 24}, caption, "fill:#333");
    double y = 80;
    y = drawColourLegend(svg, 700, y, 26, counts);
    y += 34;
    svg.textAt({700, y}, "- - -  a joint, numbered by its", "fill:#222");
    svg.textAt({700, y + 20}, "lane group: a group's joints", "fill:#555");
    svg.textAt({700, y + 40}, "share no moving body and are", "fill:#555");
    svg.textAt({700, y + 60}, "swept side by side, the groups", "fill:#555");
    svg.textAt({700, y + 80}, "in order, before the colours", "fill:#555");
    y += 40;
    svg.textAt({700, y + 70}, "open circles: boxes; dots:", "fill:#555");
    svg.textAt({700, y + 90}, "the ragdolls' limbs", "fill:#555");
    return svg.save(path);
}

}  // namespace wide_figures

bool drawWideColouring(const std::string& path) { return wide_figures::colouringFigure(path); }
bool drawWideLanes(const std::string& path) { return wide_figures::lanesFigure(path); }
bool drawWideJoints(const std::string& path) { return wide_figures::jointsFigure(path); }

}  // namespace figures
