// The mass ratio along load paths (load_paths.h).
#include "12_planner/load_paths.h"

#include "10_skip_work/sleep.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

// [ch12-load-paths]
Real loadPathMassRatio(const World& world, const std::vector<int>& contactOrder, Real touchingRatio,
                       LoadPathSearch& search) {
    const Real g = world.settings.gravity.norm();
    if (!(g > 0)) return touchingRatio;
    const Vec3 up = -world.settings.gravity / g;
    // Higher first; at one height the lower index counts as the higher, the same rule in both places
    // below, so a body is always handled after everything resting on it. The heights are read
    // once, below: the sort compares each body many times.
    const std::vector<Real>& heights = search.height;
    const auto higher = [&](int a, int b) {
        const Real ha = heights[static_cast<std::size_t>(a)], hb = heights[static_cast<std::size_t>(b)];
        return ha != hb ? ha > hb : a < b;
    };
    // Bodies of one mass hand on only that mass, whatever rests on what: the ratio is 1 without
    // a search (a pyramid of like boxes, every frame).
    Real lightest = kRealMax, heaviest = 0;
    for (const int index : contactOrder) {
        const Contact& contact = world.contacts[static_cast<std::size_t>(index)];
        for (const int body : {contact.bodyA, contact.bodyB})
            if (isDynamicBody(world, body)) {
                const Real mass = world.motionOf(body)->mass;
                lightest = std::min(lightest, mass);
                heaviest = std::max(heaviest, mass);
            }
    }
    if (!(heaviest > lightest)) return 1;
    const std::size_t bodyCount = world.bodies.size();
    search.height.resize(bodyCount);
    for (std::size_t body = 0; body < bodyCount; ++body) search.height[body] = world.bodies[body].transform.position.dot(up);
    // Which body rests on which: a contact between two dynamic bodies whose normal is near the
    // vertical; the higher centre is the one on top.
    std::vector<int>& start = search.start;
    start.assign(bodyCount + 1, 0);
    const auto restsOn = [&](const Contact& contact, int& upper, int& lower) {
        if (contact.pointCount == 0 || !isDynamicBody(world, contact.bodyA) || !isDynamicBody(world, contact.bodyB))
            return false;
        if (std::abs(contact.normal.dot(up)) < kLoadNormalCosine) return false;
        const bool aOnTop = higher(contact.bodyA, contact.bodyB);
        upper = aOnTop ? contact.bodyA : contact.bodyB;
        lower = aOnTop ? contact.bodyB : contact.bodyA;
        return true;
    };
    int upper = 0, lower = 0;
    for (const int index : contactOrder)
        if (restsOn(world.contacts[static_cast<std::size_t>(index)], upper, lower)) ++start[static_cast<std::size_t>(upper) + 1];
    for (std::size_t body = 0; body < bodyCount; ++body) start[body + 1] += start[body];
    search.below.resize(static_cast<std::size_t>(start[bodyCount]));
    search.bodies.clear();
    std::vector<int>& fill = search.fill;
    fill.assign(start.begin(), start.end() - 1);
    for (const int index : contactOrder) {
        if (!restsOn(world.contacts[static_cast<std::size_t>(index)], upper, lower)) continue;
        if (fill[static_cast<std::size_t>(upper)] == start[static_cast<std::size_t>(upper)]) search.bodies.push_back(upper);
        search.below[static_cast<std::size_t>(fill[static_cast<std::size_t>(upper)]++)] = lower;
    }
    // From the top down, each body hands on the heaviest of itself and what rests on it.
    std::sort(search.bodies.begin(), search.bodies.end(), higher);
    search.heaviestAbove.assign(bodyCount, 0);
    Real ratio = 1;
    for (const int body : search.bodies) {
        const Real mass = world.motionOf(body)->mass;
        const Real handed = std::max(mass, search.heaviestAbove[static_cast<std::size_t>(body)]);
        for (int k = start[static_cast<std::size_t>(body)]; k < start[static_cast<std::size_t>(body) + 1]; ++k) {
            const auto lowerBody = static_cast<std::size_t>(search.below[static_cast<std::size_t>(k)]);
            search.heaviestAbove[lowerBody] = std::max(search.heaviestAbove[lowerBody], handed);
            ratio = std::max(ratio, handed / world.motionOf(static_cast<int>(lowerBody))->mass);
        }
    }
    return ratio;
}
// [ch12-load-paths]

}  // namespace stepwise
