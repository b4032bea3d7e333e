#pragma once
// `stepwise bench engine` (docs/engine_bench.md): the whole engine, as a user meets it, run on
// the reference suite (scenes/reference/) over a sweep of its knobs, each run scored against
// the known answer, beside Bullet when asked (--peer bullet) and built.

#include "app/registry.h"

namespace stepwise::engine_bench {

BenchEntry engineBench();

}  // namespace stepwise::engine_bench
