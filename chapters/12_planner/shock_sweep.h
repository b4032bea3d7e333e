#pragma once
// The shock sweep as chapter 11's solve runs it (SolveExtension): in a frame whose plan asks for it
// (IterationPlan::shockPropagation), the contacts of slow bodies are grouped layer by layer from
// the supports up (shock_propagation.h), each lane of a block carries its group and which body
// it holds still, and after the last substep one relax sweep visits the groups in order with the
// lower body infinitely heavy (held_kernels.h).

#include "11_wide_solve/contact_solver.h"
#include "12_planner/iteration_plan.h"
#include "12_planner/shock_propagation.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace stepwise {

/// One block of the sweep's order: wideBlocks[block] (or scalarBlocks[block]), its lanes of one group.
struct ShockVisit {
    bool wide = false;
    std::size_t block = 0;
    int group = 0;
};

class ShockSweep : public SolveExtension {
public:
    /// `search`: the plan stage's, whose depths (supportDepth) give the sweep's layers.
    explicit ShockSweep(std::shared_ptr<const StackSearch> search) : search_(std::move(search)) {}
    void groupLanes(const World& world, ContactSolverScratch& scratch) override;
    void prepare(ContactSolverScratch& scratch) override;
    void finish(ContactSolverScratch& scratch, const ContactSolveParams& params) override;

private:
    void orderVisits(const ContactSolverScratch& scratch);

    std::shared_ptr<const StackSearch> search_;
    // Working memory, rebuilt every frame that sweeps: nothing in it outlives the frame.
    std::vector<int> slotDepth_, visitBuckets_;
    std::vector<std::uint8_t> slowSlot_;
    ShockOrder order_;
    std::vector<ShockVisit> visits_, visitScratch_;
};

}  // namespace stepwise
