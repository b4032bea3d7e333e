// Exercise check for chapter 5 (`ctest -L ch05-exercise`): rewrite sweepEndpoints in
// chapters/05_sap/sweep_pairs.cpp from the page (the textbook form will do: one active list
// of body indices, the intervals that ended before the next lower end dropped from it, each
// opening interval tested against the rest), and run this. On random
// boxes, with intervals that touch exactly, coincide, or hold static and kinematic bodies, the
// sweep must find exactly the pairs brute force finds, and count the pairs it looked at.
#include "05_sap/sweep_and_prune.h"

#include "math/random.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace stepwise;

TEST_CASE("exercise: the sweep finds brute force's pairs and counts the axis overlaps", "[ch05-exercise]") {
    Random random(55);
    auto uniform = [&](double low, double high) { return static_cast<Real>(random.uniform(low, high)); };
    for (int trial = 0; trial < 300; ++trial) {
        const int count = static_cast<int>(random.uniform() * 80);
        std::vector<Aabb> bounds(static_cast<std::size_t>(count));
        std::vector<char> dynamic(static_cast<std::size_t>(count));
        for (int i = 0; i < count; ++i) {
            Aabb& box = bounds[static_cast<std::size_t>(i)];
            const Vec3 centre(uniform(-8, 8), uniform(-8, 8), uniform(-8, 8));
            const Vec3 half(uniform(0.1, 2), uniform(0.1, 2), uniform(0.1, 2));
            box.min = centre - half, box.max = centre + half;
            if (trial % 3 == 0) box.min = box.min.array().round(), box.max = box.min.array() + 1;  // touching cubes
            dynamic[static_cast<std::size_t>(i)] = random.uniform() < 0.75;
        }
        const int axis = trial % 3;
        std::vector<SweepEndpoint> ends;
        makeEndpoints(bounds, axis, ends);
        fullSortEndpoints(ends);
        std::vector<BodyPair> swept, brute;
        const long looked = sweepEndpoints(ends, bounds, dynamic, axis, swept);
        sortPairsCanonical(swept, count);
        bruteForcePairs(bounds, dynamic, brute);
        long expectedLooked = 0;
        for (int i = 0; i < count; ++i)
            for (int j = i + 1; j < count; ++j) {
                const Aabb& a = bounds[static_cast<std::size_t>(i)];
                const Aabb& b = bounds[static_cast<std::size_t>(j)];
                const bool onAxis = a.min[axis] <= b.max[axis] && b.min[axis] <= a.max[axis];
                if (onAxis && needsContact(dynamic[static_cast<std::size_t>(i)] != 0, dynamic[static_cast<std::size_t>(j)] != 0))
                    ++expectedLooked;
            }
        INFO("trial " << trial << ", " << count << " boxes, axis " << axis);
        REQUIRE(swept == brute);
        CHECK(looked == expectedLooked);
    }
}
