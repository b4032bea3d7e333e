#include "fuzz_input.h"

#include <cstdio>
#include <cstdlib>

namespace stepwise::fuzz {

void invariantFailed(const char* target, const char* what, double value, double limit) {
    std::fprintf(stderr, "%s: invariant failed: %s (value %.9g, limit %.9g)\n", target, what, value, limit);
    std::abort();
}

}  // namespace stepwise::fuzz
