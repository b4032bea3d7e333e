#pragma once
// The wide path's three passes over the colour blocks. They live in their own file because it is
// the one built with the SIMD instruction set the build chose (STEPWISE_WIDE_ISA: AVX2 and FMA by
// default on x86-64, or AVX-512; chapters/CMakeLists.txt): the same templates as the scalar path
// (contact_kernels.h), compiled for the wide registers. Call the wide kernels through these
// functions only: a kernel over kWideLanes instantiated in another file would be built for the
// baseline instruction set there (lanes.h's STEPWISE_ISA keeps the two copies apart).

#include "11_wide_solve/solver_data.h"

#include <cstddef>
#include <vector>

namespace stepwise {

/// A wide block's fields from its lanes' gathered inputs (fillBlockFields).
void fillWide(ManifoldBlock<kWideLanes>& block, const LaneInputs<kWideLanes>& inputs, Real carryScale, bool warm);
/// Once per frame, after the blocks are filled: each block's effective masses (prepareBlock).
void prepareWide(std::vector<ManifoldBlock<kWideLanes>>& blocks, const SolverBodyState* states);
void warmStartWide(std::vector<ManifoldBlock<kWideLanes>>& blocks, SolverBodyState* states);
/// One sweep over every block; with `useBias`, whether a point lay deeper than the slop (anyPointDeep).
bool solveWide(std::vector<ManifoldBlock<kWideLanes>>& blocks, SolverBodyState* states, const ContactSolveParams& params,
               bool useBias);
void restitutionWide(std::vector<ManifoldBlock<kWideLanes>>& blocks, SolverBodyState* states, Real threshold);
/// One sweep of collideBlock over the blocks; whether any point was struck.
bool collideWide(std::vector<ManifoldBlock<kWideLanes>>& blocks, SolverBodyState* states, const ContactSolveParams& params);

/// Chapter 1's position step for slots 1 to count - 1, kWideLanes bodies at a time, each dynamic
/// body's (from `firstDynamic` on) spin held to `mostSpin` first (holdSpin's rule).
void integratePositionsWide(SolverBodyState* states, int count, Real h, Real mostSpin, int firstDynamic);

/// Chapter 1's implicit gyroscopic step for these bodies (gyroscopic_pack.h), kWideLanes at a time.
void gyroscopicStepWide(SolverBodyState* states, const std::vector<GyroscopicBody>& bodies, Real h);

/// The instruction set the wide file was built for: "avx2", "avx512" or "portable".
const char* wideInstructionSet();

}  // namespace stepwise
