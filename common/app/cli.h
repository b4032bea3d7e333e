#pragma once
// The `stepwise` command line (CLI11): run, scenes, bench, plus the commands chapters add.

#include "app/registry.h"

namespace stepwise {

/// Runs the CLI and returns the process exit code: 0 success, 1 a run failed (e.g. the state
/// became non-finite), 2 bad usage or bad input (with one message on stderr).
int runCli(int argc, char** argv, const Registry& registry);

}  // namespace stepwise
