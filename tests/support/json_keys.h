#pragma once
// The keys of a JSON object in their written order, for the tests that check a document's layout
// (the run report's, the documented CLI outputs'). Needs only nlohmann::json, so the CLI checker
// (tests/cli/docs_examples.cpp), which links no engine, can use it too.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace stepwise::test {

inline std::vector<std::string> keysOf(const nlohmann::ordered_json& object) {
    std::vector<std::string> keys;
    for (const auto& item : object.items()) keys.push_back(item.key());
    return keys;
}

}  // namespace stepwise::test
