#pragma once
// The DirectX 12 demo shell (demo_app.cpp), compiled once for every chapter. It calls
// registerChapters, which the chapter registry a demo links defines.

namespace stepwise::render {

/// Runs the demo of chapters 01..`chapter` (a window, or offscreen with --hidden/--screenshot);
/// the process's exit code.
int runDemoApp(int chapter, int argc, char** argv);

}  // namespace stepwise::render
