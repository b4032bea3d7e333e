#pragma once
// A chapter's demo without a window (chNN_demo on builds without the DirectX 12 shell). Compiled
// once for every chapter: each demo's main only names its chapter, and links that chapter's
// registry (registerChapters), which this function calls.

namespace stepwise {

/// Runs one of the chapter's scenes headless, prints the summary and writes the report; the exit
/// code of the demo.
int runHeadlessDemo(int chapter, int argc, char** argv);

}  // namespace stepwise
