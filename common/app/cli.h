#pragma once
// The `stepwise` command line (CLI11): run, scenes, bench, plus the commands chapters add.

#include "app/registry.h"

#include <functional>

namespace stepwise {

/// The exit code of a program or command whose input (options, scene, recording) is rejected.
constexpr int kExitBadInput = 2;

/// Runs `command` (a program's or a subcommand's body) and reports what it throws the way every
/// one of them does on standard error: a SceneError with its lines (printSceneError) and
/// kExitBadInput, any other error as one "error: ..." line and `otherErrorExit`.
int runReportingErrors(const std::function<int()>& command, int otherErrorExit);

/// Runs the CLI and returns the process exit code: 0 success, 1 a run failed (e.g. the state
/// became non-finite), 2 bad usage or bad input (with one message on stderr).
int runCli(int argc, char** argv, const Registry& registry);

}  // namespace stepwise
