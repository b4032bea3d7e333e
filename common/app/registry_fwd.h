#pragma once
// The registry's entry points without its definitions: what the file generated from the chapter
// list needs (cmake/StepwiseChapters.cmake). It includes nothing, so each chapter's generated
// registry compiles in a tenth of a second instead of parsing the world's headers (and Eigen's)
// for a few calls: 13 files in each of four builds.

namespace stepwise {

class Registry;

/// Generated from the chapter list: calls registerChapter01..NN for the program's chapters.
void registerChapters(Registry& registry);

/// Every chapter of the program, registered once on first use (tests, tools, fuzz targets).
const Registry& chapterRegistry();

/// The registry registerAll fills, made on the first call and kept (app/registry.cpp); the
/// generated chapterRegistry() passes its registerChapters. A program links one chapter registry.
const Registry& registryOnce(void (*registerAll)(Registry&));

}  // namespace stepwise
