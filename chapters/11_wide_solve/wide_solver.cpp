#include "11_wide_solve/wide_solver.h"

#include "11_wide_solve/contact_kernels.h"
#include "11_wide_solve/gyroscopic_pack.h"

namespace stepwise {

void fillWide(ManifoldBlock<kWideLanes>& block, const LaneInputs<kWideLanes>& inputs, Real carryScale, bool warm) {
    fillBlockFields(block, inputs, carryScale, warm);
}

void prepareWide(std::vector<ManifoldBlock<kWideLanes>>& blocks, const SolverBodyState* states) {
    for (ManifoldBlock<kWideLanes>& block : blocks) prepareBlock(block, states);
}

void warmStartWide(std::vector<ManifoldBlock<kWideLanes>>& blocks, SolverBodyState* states) {
    for (ManifoldBlock<kWideLanes>& block : blocks) warmStartBlock(block, states);
}

bool solveWide(std::vector<ManifoldBlock<kWideLanes>>& blocks, SolverBodyState* states, const ContactSolveParams& params,
               bool useBias) {
    bool deep = false;
    for (ManifoldBlock<kWideLanes>& block : blocks) deep = solveAnyBlock(block, states, params, useBias) || deep;
    return deep;
}

void restitutionWide(std::vector<ManifoldBlock<kWideLanes>>& blocks, SolverBodyState* states, Real threshold) {
    for (ManifoldBlock<kWideLanes>& block : blocks) restitutionBlock(block, states, threshold);
}

bool collideWide(std::vector<ManifoldBlock<kWideLanes>>& blocks, SolverBodyState* states, const ContactSolveParams& params) {
    bool struck = false;
    for (ManifoldBlock<kWideLanes>& block : blocks) struck = collideBlock(block, states, params) || struck;
    return struck;
}

void integratePositionsWide(SolverBodyState* states, int count, Real h, Real mostSpin, int firstDynamic) {
    int slot = 1;  // slot 0 never moves
    int slots[kWideLanes];
    for (; slot + kWideLanes <= count; slot += kWideLanes) {
        for (int lane = 0; lane < kWideLanes; ++lane) slots[lane] = slot + lane;
        integratePositionsPack<kWideLanes>(states, slots, h, mostSpin, firstDynamic);
    }
    for (; slot < count; ++slot) integratePositionsPack<1>(states, &slot, h, mostSpin, firstDynamic);
}

void gyroscopicStepWide(SolverBodyState* states, const std::vector<GyroscopicBody>& bodies, Real h) {
    const int count = static_cast<int>(bodies.size());
    int first = 0;
    for (; first + kWideLanes <= count; first += kWideLanes) gyroscopicStepPack<kWideLanes>(states, &bodies[first], h);
    for (; first < count; ++first) gyroscopicStepPack<1>(states, &bodies[first], h);
}

const char* wideInstructionSet() {
#if defined(__AVX512F__)
    return "avx512";
#elif defined(__AVX2__)
    return "avx2";
#else
    return "portable";
#endif
}

}  // namespace stepwise
