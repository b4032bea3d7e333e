// Chapter 4 in the programs: its scenes (with the solver panel; the demo draws the impulses), its
// pipeline and its benches.
#include "app/panel.h"
#include "app/registry.h"

#include "04_pgs/benches.h"
#include "04_pgs/chapter.h"
#include "04_pgs/scenes.h"

namespace stepwise {

namespace {

const Material* firstDynamicMaterial(const World& world) {
    for (const Body& body : world.bodies)
        if (body.type == BodyType::Dynamic) return &body.material;
    return nullptr;
}

// The controls every chapter 4 scene shares. Restitution and friction are set on every body, so
// the pair values (max and sqrt of the product) equal the slider's.
void solverPanel(World& world, Panel& panel) {
    Settings& settings = world.settings;
    panel.sliderInt("iterations", settings.solverIterations, 1, 50);
    panel.sliderInt("substeps", settings.substeps, 1, 16);
    float beta = static_cast<float>(settings.baumgarte);
    if (panel.sliderFloat("Baumgarte beta", beta, 0.0f, 1.0f)) settings.baumgarte = static_cast<Real>(beta);
    float slopMm = static_cast<float>(settings.slop * 1000);
    if (panel.sliderFloat("slop (mm)", slopMm, 0.0f, 50.0f)) settings.slop = static_cast<Real>(slopMm) / 1000;
    const char* const solvers[] = {"Gauss-Seidel", "Jacobi"};
    int solver = settings.solver == SolverKind::Jacobi ? 1 : 0;
    if (panel.combo("solver", solver, solvers, 2)) settings.solver = solver == 1 ? SolverKind::Jacobi : SolverKind::GaussSeidel;

    if (const Material* material = firstDynamicMaterial(world)) {
        float restitution = static_cast<float>(material->restitution);
        if (panel.sliderFloat("restitution", restitution, 0.0f, 1.0f))
            for (Body& body : world.bodies) body.material.restitution = static_cast<Real>(restitution);
        float friction = static_cast<float>(material->friction);
        if (panel.sliderFloat("friction", friction, 0.0f, 1.5f))
            for (Body& body : world.bodies) body.material.friction = static_cast<Real>(friction);
    }
    int points = 0;
    for (const Contact& contact : world.contacts) points += contact.pointCount;
    panel.text("contact points carrying load: " + std::to_string(points));
    panel.text("arrows: yellow normal impulse, orange friction (as force, 0.05 m/N)");
}

void addChapter04Scenes(Registry& registry) {
    const char* const category = "Sequential impulses";
    const SceneViewFactory solverControls = statelessView({}, solverPanel);
    registry.addScene({"pgs-drop", 4, category, prose(R"(
        Boxes and spheres fall, bounce (two have restitution 0.5) and come to rest; try Jacobi and few
        iterations)"),
        buildDropScene, solverControls});
    registry.addScene({"pgs-bounce", 4, category, prose(R"(
        Balls with restitution 0.3, 0.6, 0.9 and 1 bounce to about e^2 of their drop height; e = 1 keeps its
        height)"),
        [] { return buildBounceScene(); }, solverControls});
    registry.addScene({"pgs-resting", 4, category, prose(R"(
        The ball rests still at the slop depth; the box, held by one contact point, rocks and wanders
        (chapter 6 fixes it); the 1 kg ball under the 10 kg one is pressed deeper than the slop (no warm
        starting yet: try 20 iterations))"),
        buildRestingScene, solverControls});
    registry.addScene({"pgs-friction", 4, category, prose(R"(
        At 8 substeps the box on the ramp steeper than atan(mu) slides and the one on the gentler ramp stays
        (at 1 substep its rocking corner walks it down); the ball slides, then rolls at 5/7 of its speed)"),
        [] { return buildFrictionScene(); }, solverControls});
    registry.addScene({"pgs-sphere-pit", 4, category, prose(R"(
        Forty balls settle into a pile: many coupled contacts; compare Gauss-Seidel with Jacobi)"),
        [] { return buildSpherePitScene(); }, solverControls});
}

}  // namespace

void registerChapter04(Registry& registry) {
    registry.addChapter({4, addChapter04Scenes, [](const World& world) { return makeChapter04Pipeline(world); },
                         {solverBench(), restingBench()}});
}

}  // namespace stepwise
