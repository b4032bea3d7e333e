// Fuzz target: the reader of `stepwise collide` queries (chapter 3), fed any bytes. A query
// that reads must give one finite result per pair, and its results must print as JSON.
#include "fuzz_input.h"

#include "03_epa/collide_command.h"
#include "world/scene.h"

#include <cstddef>
#include <cstdint>
#include <string>

using namespace stepwise;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::vector<CollidePair> pairs;
    try {
        pairs = parseCollidePairs(text, "fuzz.json");
    } catch (const SceneError&) {
        return 0;
    }
    std::vector<ContactQuery> results;
    for (std::size_t i = 0; i < pairs.size() && i < 16; ++i) {
        const CollidePair& pair = pairs[i];
        const ContactQuery query = collideShapes(pair.shapeA, pair.poseA, pair.shapeB, pair.poseB);
        const bool finite = std::isfinite(query.depth) && query.normal.allFinite() && query.pointA.allFinite() &&
                            query.pointB.allFinite();
        STEPWISE_FUZZ_CHECK("fuzz_collide_query", finite, query.depth, 0);
        results.push_back(query);
    }
    const std::string json = collideResultsToJson(results);
    STEPWISE_FUZZ_CHECK("fuzz_collide_query", json.find("null") == std::string::npos, 0, 0);
    return 0;
}
