// Exercise check for chapter 11 (`ctest -L ch11-exercise`): rewrite colourContacts in
// chapters/11_wide_solve/colouring.cpp from the page (greedy, in the given order: each contact
// takes the lowest colour that neither of its moving bodies holds yet, or -1 when all kMaxColours
// are taken; slot 0, static or asleep, holds no colour) and run this. The colours must be the
// greedy ones exactly: the scalar and the wide solve read them, and the same input must always
// give the same colours.
#include "10_skip_work/scenes.h"
#include "11_wide_solve/chapter.h"
#include "11_wide_solve/colouring.h"
#include "math/random.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

using namespace stepwise;

namespace {

struct Graph {
    std::vector<int> slotA, slotB;
    int slotCount = 1;
};

/// Whether contacts i and j share a body that moves (slot 0 shared blocks nothing).
bool shareMovingBody(const Graph& graph, std::size_t i, std::size_t j) {
    for (const int a : {graph.slotA[i], graph.slotB[i]})
        for (const int b : {graph.slotA[j], graph.slotB[j]})
            if (a != 0 && a == b) return true;
    return false;
}

/// The rules the page states, checked contact by contact: a colour in range or the overflow; no
/// colour holds two contacts of one moving body; and each contact took the lowest colour free
/// when its turn came (every lower colour is held by an earlier contact of one of its bodies),
/// the overflow only when all kMaxColours were held.
void checkGreedyColours(const Graph& graph, const std::vector<int>& colours) {
    REQUIRE(colours.size() == graph.slotA.size());
    std::set<std::pair<int, int>> taken;  // (colour, moving slot)
    for (std::size_t i = 0; i < colours.size(); ++i) {
        INFO("contact " << i << " (slots " << graph.slotA[i] << ", " << graph.slotB[i] << ") has colour " << colours[i]);
        REQUIRE(colours[i] >= -1);
        REQUIRE(colours[i] < kMaxColours);
        if (colours[i] >= 0)
            for (const int slot : {graph.slotA[i], graph.slotB[i]})
                if (slot != 0) REQUIRE(taken.insert({colours[i], slot}).second);
        const int lowerColours = colours[i] >= 0 ? colours[i] : kMaxColours;
        for (int colour = 0; colour < lowerColours; ++colour) {
            bool held = false;
            for (std::size_t j = 0; j < i && !held; ++j) held = colours[j] == colour && shareMovingBody(graph, i, j);
            INFO("colour " << colour << " was free for it");
            CHECK(held);
        }
    }
}

Graph randomGraph(Random& random, int contacts, int slots, double staticShare) {
    Graph graph;
    graph.slotCount = slots;
    for (int i = 0; i < contacts; ++i) {
        const int a = random.uniform() < staticShare ? 0 : 1 + static_cast<int>(random.uniform() * (slots - 1));
        int b = 1 + static_cast<int>(random.uniform() * (slots - 1));
        if (b == a) b = b % (slots - 1) + 1;
        graph.slotA.push_back(a);
        graph.slotB.push_back(b);
    }
    return graph;
}

}  // namespace

TEST_CASE("exercise: random contact graphs get the greedy colours", "[ch11-exercise]") {
    Random random(11);
    std::vector<std::uint64_t> scratch;
    for (int trial = 0; trial < 200; ++trial) {
        // Few slots and many contacts crowd a body's colours (and reach the overflow); slot counts
        // past 64 need more than one word of bits per colour.
        const int slots = 3 + static_cast<int>(random.uniform() * (trial % 2 == 0 ? 12 : 300));
        const int contacts = static_cast<int>(random.uniform() * 400);
        const Graph graph = randomGraph(random, contacts, slots, 0.3);
        std::vector<int> colours;
        colourContacts(graph.slotA, graph.slotB, graph.slotCount, colours, scratch);
        INFO("trial " << trial << ": " << contacts << " contacts over " << slots << " slots");
        checkGreedyColours(graph, colours);
        std::vector<int> again;
        std::vector<std::uint64_t> fresh;
        colourContacts(graph.slotA, graph.slotB, graph.slotCount, again, fresh);
        CHECK(again == colours);  // the kept scratch changes nothing
    }
}

TEST_CASE("exercise: the ground blocks no colour, a crowded body overflows", "[ch11-exercise]") {
    std::vector<std::uint64_t> scratch;
    std::vector<int> colours;
    // 200 bodies on the ground (slot 0): all in colour 0, side by side.
    Graph ground;
    ground.slotCount = 201;
    for (int body = 1; body <= 200; ++body) ground.slotA.push_back(0), ground.slotB.push_back(body);
    colourContacts(ground.slotA, ground.slotB, ground.slotCount, colours, scratch);
    CHECK(colours == std::vector<int>(200, 0));
    // One body touching 30 others: colours 0 to 23, then the overflow.
    Graph star;
    star.slotCount = 40;
    for (int other = 1; other <= 30; ++other) star.slotA.push_back(35), star.slotB.push_back(other);
    colourContacts(star.slotA, star.slotB, star.slotCount, colours, scratch);
    for (int i = 0; i < 30; ++i) CHECK(colours[static_cast<std::size_t>(i)] == (i < kMaxColours ? i : -1));
    checkGreedyColours(star, colours);
}

TEST_CASE("exercise: a 20-row pyramid's contacts take a few colours and none overflows", "[ch11-exercise]") {
    World world = buildPyramidRow(1, 20);
    Pipeline pipeline = makeChapter11Pipeline(world);
    for (int frame = 0; frame < 2; ++frame) pipeline.step(world);
    Graph graph;
    std::vector<int> slotOf(world.bodies.size(), 0);
    for (const Motion& motion : world.motions) slotOf[static_cast<std::size_t>(motion.bodyIndex)] = graph.slotCount++;
    for (const Contact& contact : world.contacts) {
        graph.slotA.push_back(slotOf[static_cast<std::size_t>(contact.bodyA)]);
        graph.slotB.push_back(slotOf[static_cast<std::size_t>(contact.bodyB)]);
    }
    REQUIRE(graph.slotA.size() > 300);
    std::vector<int> colours;
    std::vector<std::uint64_t> scratch;
    colourContacts(graph.slotA, graph.slotB, graph.slotCount, colours, scratch);
    checkGreedyColours(graph, colours);
    CHECK(*std::min_element(colours.begin(), colours.end()) >= 0);
    CHECK(*std::max_element(colours.begin(), colours.end()) < 6);
}
