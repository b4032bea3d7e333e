#include "10_speed/wide_solver.h"

#include "10_speed/contact_kernels.h"

namespace stepwise {

void prepareWide(std::vector<ManifoldBlock<kWideLanes>>& blocks, const SolverBodyState* states) {
    for (ManifoldBlock<kWideLanes>& block : blocks) prepareBlock(block, states);
}

void warmStartWide(std::vector<ManifoldBlock<kWideLanes>>& blocks, SolverBodyState* states) {
    for (ManifoldBlock<kWideLanes>& block : blocks) warmStartBlock(block, states);
}

void solveWide(std::vector<ManifoldBlock<kWideLanes>>& blocks, SolverBodyState* states, const ContactSolveParams& params,
               bool useBias) {
    for (ManifoldBlock<kWideLanes>& block : blocks) solveBlock(block, states, params, useBias);
}

void restitutionWide(std::vector<ManifoldBlock<kWideLanes>>& blocks, SolverBodyState* states, Real threshold) {
    for (ManifoldBlock<kWideLanes>& block : blocks) restitutionBlock(block, states, threshold);
}

const char* wideInstructionSet() {
#if defined(__AVX2__)
    return "avx2";
#else
    return "portable";
#endif
}

}  // namespace stepwise
