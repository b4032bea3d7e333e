// The `stepwise` program: the CLI over every chapter of the course, with the Bullet peer for the
// benches when libbullet-dev was found (docs/peers.md), and `bench engine` (docs/engine_bench.md).
#include "app/cli.h"
#include "app/peer.h"

#ifdef STEPWISE_HAVE_BULLET
#include "peers/bullet_peer.h"
#endif
#ifdef STEPWISE_HAVE_ENGINE_BENCH
#include "engine/engine_bench.h"
#endif

int main(int argc, char** argv) {
#ifdef STEPWISE_HAVE_BULLET
    stepwise::setPeerEngine(stepwise::peers::bulletPeerEngine());
#endif
    stepwise::Registry registry;
    stepwise::registerChapters(registry);
#ifdef STEPWISE_HAVE_ENGINE_BENCH
    // The whole engine measured (bench/engine/): after the chapters, since it runs the last one's pipeline.
    registry.addBench(stepwise::engine_bench::engineBench());
#endif
    return stepwise::runCli(argc, argv, registry);
}
