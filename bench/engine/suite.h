#pragma once
// The reference suite on disk, and the sweep of configurations `stepwise bench engine` runs
// each scene with (docs/engine_bench.md).

#include "engine/reference.h"
#include "engine/runs.h"

#include <string>
#include <vector>

namespace stepwise::engine_bench {

struct ReferenceScene {
    std::string name;       // the file name without .json
    std::string path;
    World world;
    Sidecar sidecar;
};

/// Every NAME.json of `directory` with its NAME.expect.json, by group (groupNames()), then name. Throws SidecarError
/// naming the file for a missing directory or sidecar, a bad scene or a bad sidecar.
std::vector<ReferenceScene> loadReferenceScenes(const std::string& directory);

/// One way to run a scene: the engine with some knobs turned, or the peer with its own.
struct Configuration {
    std::string family;     // one curve of the plots: "iterations", "bullet substeps", ... ("other": single points)
    std::string name;       // "iterations 20"; "default" and "bullet default" are the defaults
    bool peer = false;
    EngineKnobs knobs;
    PeerKnobs peerKnobs;
};

/// The sweep: the defaults first, then each knob in turn, then the peer's when `withPeer`. Quick
/// (CI, the docs build): the defaults, one cheaper and one dearer configuration, the peer's defaults.
std::vector<Configuration> sweep(bool quick, bool withPeer);

}  // namespace stepwise::engine_bench
