#include "golden_runs.h"

#include <algorithm>
#include <numeric>

namespace stepwise::reliability {

namespace {

// Seconds each scene's golden run took in the sanitizer build, the one build that shards the
// check (bench/results/golden-sanitizer-times.txt: one scene at a time, nice 19, a shared 2-core
// machine). Only the ratios matter: they decide which scenes share a shard. pyramid-20 alone is
// half of the total (chapter 6's substepped solve on 210 boxes), so it gets a shard to itself and
// no shard can be shorter than it.
struct SceneSeconds {
    const char* scene;
    double seconds;
};
constexpr SceneSeconds kSanitizerSeconds[] = {
    {"integrators-side-by-side", 0.5}, {"t-handle", 0.3}, {"projectile", 0.3},
    {"gjk-two-boxes", 0.2}, {"gjk-sphere-diamond", 0.2}, {"epa-step-by-step", 0.3},
    {"epa-contact-gallery", 0.5}, {"pgs-drop", 0.5}, {"pgs-bounce", 0.3},
    {"pgs-resting", 0.5}, {"pgs-friction", 1.5}, {"pgs-sphere-pit", 2.1},
    {"sap-stress", 16.6}, {"sap-stress-dense", 25.0}, {"stack-16", 17.9},
    {"pyramid-20", 518.5}, {"heavy-on-light", 7.3}, {"tower-heavy-below", 3.3},
    {"tower-heavy-above", 3.8}, {"card-house", 4.7}, {"stack-ramp", 2.1},
    {"ccd-gun", 5.8}, {"ccd-spinning-rod", 0.4}, {"ccd-head-on", 0.7},
    {"joints-sandbox", 16.9}, {"joints-gallery", 1.9}, {"joints-ragdoll-pile", 67.8},
    {"joints-platform", 1.7}, {"joints-rotator", 4.2}, {"debug-drop", 1.3},
    {"debug-hull-on-box", 2.3}, {"debug-tunnel", 0.2}, {"debug-jitter", 10.1},
    {"islands-pyramids", 98.9}, {"wide-pyramid", 1.8}, {"wide-ragdolls", 57.7},
    {"speed-pyramids", 3.8}, {"speed-pile", 99.4}, {"worlds-cylinders", 0.6},
    {"worlds-seams", 1.8}, {"worlds-terrain", 38.6}, {"worlds-mesh-terrain", 19.4},
    {"scenes/ball-on-box.json", 0.5}, {"scenes/falling-sphere.json", 0.2},
    {"scenes/joint-gallery.json", 0.4}, {"scenes/spring-pair.json", 0.3},
    {"scenes/two-box-stack.json", 0.3},
};

// A scene added since the table was measured: body counts do not predict the cost (2,100
// sleeping boxes take 4 s, 210 standing ones 518 s), so it counts as a middling scene until
// the table is measured again; the check still runs it, in whichever shard it lands.
constexpr double kUnmeasuredSeconds = 10.0;

}  // namespace

double goldenSceneSeconds(const std::string& scene) {
    for (const SceneSeconds& entry : kSanitizerSeconds)
        if (scene == entry.scene) return entry.seconds;
    return kUnmeasuredSeconds;
}

std::vector<int> goldenShards(const std::vector<std::string>& scenes, int shards) {
    std::vector<double> cost;
    for (const std::string& scene : scenes) cost.push_back(goldenSceneSeconds(scene));
    // Longest first, each to the shard with the least so far (ties: the lower index, so the
    // costliest scene opens shard 0); the stable sort keeps equal costs in table order, so
    // every process computes the same assignment.
    std::vector<std::size_t> order(scenes.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
    std::vector<double> load(std::size_t(std::max(shards, 1)), 0.0);
    std::vector<int> shardOf(scenes.size(), 0);
    for (const std::size_t scene : order) {
        const auto lightest = std::min_element(load.begin(), load.end()) - load.begin();
        shardOf[scene] = static_cast<int>(lightest);
        load[std::size_t(lightest)] += cost[scene];
    }
    return shardOf;
}

}  // namespace stepwise::reliability
