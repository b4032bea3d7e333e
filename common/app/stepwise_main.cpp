// The `stepwise` program: the CLI over every chapter of the course, with the Bullet peer for the
// benches when libbullet-dev was found (docs/peers.md).
#include "app/cli.h"
#include "app/peer.h"

#ifdef STEPWISE_HAVE_BULLET
#include "peers/bullet_peer.h"
#endif

int main(int argc, char** argv) {
#ifdef STEPWISE_HAVE_BULLET
    stepwise::setPeerEngine({stepwise::peers::bulletVersion(), [](const stepwise::World& world, long frames) {
                                 const stepwise::peers::BulletRun run = stepwise::peers::runBullet(world, frames);
                                 return stepwise::PeerRun{run.stepMs, run.finalPoses};
                             }});
#endif
    stepwise::Registry registry;
    stepwise::registerChapters(registry);
    return stepwise::runCli(argc, argv, registry);
}
