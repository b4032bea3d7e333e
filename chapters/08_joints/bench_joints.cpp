#include "08_joints/benches.h"

#include "app/bench_util.h"

namespace stepwise {

BenchEntry jointsBench() { return BenchEntry{"joints", 8, "joint error against run time (to come)", {}, {}}; }

}  // namespace stepwise
