#pragma once
// The names an enum's values have in files, reports and messages, as one table per enum read in
// both directions: a loader turns a name into a value (JsonCursor::choice, which also lists the
// table in its rejection), toString turns a value into its name. One table, so the spelling a
// scene file is read with and the one it is written with cannot drift apart.

#include <utility>
#include <vector>

namespace stepwise {

template <class E>
using Names = std::vector<std::pair<const char*, E>>;

/// The name `names` gives `value`; `unknown` for a value the table does not list (a corrupt one).
template <class E>
const char* nameOf(const Names<E>& names, E value, const char* unknown = "?") {
    for (const auto& [name, listed] : names)
        if (listed == value) return name;
    return unknown;
}

}  // namespace stepwise
