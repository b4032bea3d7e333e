// stepwise_figures <output dir>: draws every figure of the course site from the engine's code.
#include "figures.h"

#include "app/registry.h"

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: stepwise_figures <output dir>\n");
        return 2;
    }
    const std::string dir = argv[1];
    // Chapter 9's figures run the debugger, whose library also holds `stepwise record` and
    // `replay`; those ask for the course's registry, built here first.
    (void)stepwise::chapterRegistry();
    struct Figure {
        const char* file;
        bool (*draw)(const std::string&);
    };
    const Figure all[] = {{"fig-minkowski.svg", figures::drawMinkowski},
                          {"fig-ccd-advancement.svg", figures::drawCcdAdvancement},
                          {"fig-toi-loop.svg", figures::drawToiLoop},
                          {"fig-hinge-frame.svg", figures::drawHingeFrame},
                          {"fig-swing-twist.svg", figures::drawSwingTwist},
                          {"fig-ragdoll-limits.svg", figures::drawRagdollLimits},
                          {"fig-hit-tree.svg", figures::drawHitTree},
                          {"fig-rewind-timeline.svg", figures::drawRewindTimeline},
                          {"fig-ray-slabs.svg", figures::drawRaySlabs},
                          {"fig-integrator-phase.svg", figures::drawIntegratorPhase},
                          {"fig-integrator-energy.svg", figures::drawIntegratorEnergy},
                          {"fig-depth-reach.svg", figures::drawDepthReach},
                          {"fig-box-sphere-cases.svg", figures::drawBoxSphereCases},
                          {"fig-voronoi-regions.svg", figures::drawVoronoiRegions},
                          {"fig-epa-horizon.svg", figures::drawEpaHorizon},
                          {"fig-contact-arms.svg", figures::drawContactArms},
                          {"fig-friction-pyramid.svg", figures::drawFrictionPyramid},
                          {"fig-baumgarte-energy.svg", figures::drawBaumgarteEnergy},
                          {"fig-sweep-intervals.svg", figures::drawSweepIntervals},
                          {"fig-manifold-clipping.svg", figures::drawManifoldClipping},
                          {"fig-skip-grown-boxes.svg", figures::drawGrownBoxes},
                          {"fig-skip-cache-rule.svg", figures::drawCacheRule},
                          {"fig-skip-islands.svg", figures::drawIslands},
                          {"fig-wide-colouring.svg", figures::drawWideColouring},
                          {"fig-wide-lanes.svg", figures::drawWideLanes},
                          {"fig-wide-joints.svg", figures::drawWideJoints},
                          {"fig-planner-load.svg", figures::drawLoadCrossing},
                          {"fig-planner-shock-layers.svg", figures::drawShockLayers},
                          {"fig-worlds-tree.svg", figures::drawMeshTree},
                          {"fig-worlds-seam.svg", figures::drawSeamNormals},
                          {"fig-sweep-axis.svg", figures::drawSweepAxisChoice},
                          {"fig-manifold-reduction.svg", figures::drawManifoldReduction},
                          {"fig-impulse-arm.svg", figures::drawImpulseArm},
                          {"fig-complementarity.svg", figures::drawComplementarity}};
    for (const Figure& figure : all) {
        const std::string path = dir + "/" + figure.file;
        if (!figure.draw(path)) {
            std::fprintf(stderr, "error: could not write %s\n", path.c_str());
            return 1;
        }
    }
    return 0;
}
