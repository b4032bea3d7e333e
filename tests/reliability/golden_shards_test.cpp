// The golden check's shards (golden_shards.cpp): every scene in exactly one, the same answer in
// every process, and the costliest scene first, alone when it outweighs an even share.
#include <catch2/catch.hpp>

#include "golden_runs.h"

#include "app/registry.h"

#include <algorithm>
#include <string>
#include <vector>

using namespace stepwise;
using namespace stepwise::reliability;

namespace {

// The golden table's scenes in its order: the built-in ones, then two files (one unmeasured).
std::vector<std::string> goldenSceneNames() {
    std::vector<std::string> names;
    for (const SceneEntry& entry : chapterRegistry().scenes()) names.push_back(entry.name);
    names.push_back("scenes/two-box-stack.json");
    names.push_back("scenes/not-measured-yet.json");
    return names;
}

}  // namespace

TEST_CASE("golden shards: every scene in one shard, dealt the same every time", "[reliability][golden]") {
    const std::vector<std::string> names = goldenSceneNames();
    REQUIRE(goldenShards(names, 1) == std::vector<int>(names.size(), 0));
    for (int shards = 2; shards <= 8; ++shards) {
        INFO(shards << " shards");
        const std::vector<int> shardOf = goldenShards(names, shards);
        REQUIRE(shardOf.size() == names.size());
        REQUIRE(shardOf == goldenShards(names, shards));
        for (const int shard : shardOf) REQUIRE((shard >= 0 && shard < shards));
    }
}

TEST_CASE("golden shards: the costliest scene opens shard 0, alone when it outweighs an even share", "[reliability][golden]") {
    const std::vector<std::string> names = goldenSceneNames();
    std::vector<double> cost;
    for (const std::string& name : names) cost.push_back(goldenSceneSeconds(name));
    const std::size_t costliest = std::size_t(std::max_element(cost.begin(), cost.end()) - cost.begin());
    double total = 0;
    for (const double seconds : cost) total += seconds;
    for (const int shards : {2, 4, 6}) {
        INFO(shards << " shards, costliest " << names[costliest]);
        const std::vector<int> shardOf = goldenShards(names, shards);
        REQUIRE(shardOf[costliest] == 0);
        if (cost[costliest] > total / shards)
            REQUIRE(std::count(shardOf.begin(), shardOf.end(), 0) == 1);
    }
}
