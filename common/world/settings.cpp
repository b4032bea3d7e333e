#include "world/settings.h"

namespace stepwise {

const std::vector<SettingUse>& settingUses() {
    static const std::vector<SettingUse> uses = {
        {"gravity", 1},        {"dt", 1},         {"substeps", 1},          {"integrator", 1},
        {"gyroscopic", 1},     {"solver", 4},     {"solver_iterations", 4}, {"baumgarte", 4},
        {"slop", 4},           {"restitution_threshold", 4},                {"broadphase", 5},
        {"warm_starting", 6},  {"stabilisation", 6},     {"contact_points", 6},  {"ccd", 7},
        {"contact_hertz", 6},  {"contact_damping_ratio", 6},                {"max_push_out_speed", 6},
        {"joint_hertz", 11},   {"joint_damping_ratio", 11},
        {"sleeping", 10},      {"sleep_speed", 10},      {"time_to_sleep", 10},  {"bounds_margin", 10},
        {"active_edges", 13},  {"plan_iterations", 12},
    };
    return uses;
}

int chapterReading(const std::string& key) {
    for (const SettingUse& use : settingUses())
        if (key == use.key) return use.chapter;
    return 0;
}

// The spellings match the scene format (docs/scene-format.md).
const Names<IntegratorKind> kIntegratorNames = {
    {"semi_implicit_euler", IntegratorKind::SemiImplicitEuler}, {"rk4", IntegratorKind::Rk4}, {"verlet", IntegratorKind::Verlet}};
const Names<GyroscopicMode> kGyroscopicNames = {
    {"off", GyroscopicMode::Off}, {"explicit", GyroscopicMode::Explicit}, {"implicit", GyroscopicMode::Implicit}};
const Names<BroadphaseMode> kBroadphaseNames = {
    {"auto", BroadphaseMode::Auto}, {"sap", BroadphaseMode::Sap}, {"brute", BroadphaseMode::Brute}};
const Names<CcdMode> kCcdNames = {{"auto", CcdMode::Auto}, {"on", CcdMode::On}, {"off", CcdMode::Off}};
const Names<SolverKind> kSolverNames = {{"gauss_seidel", SolverKind::GaussSeidel}, {"jacobi", SolverKind::Jacobi}};
const Names<Stabilisation> kStabilisationNames = {{"baumgarte", Stabilisation::Baumgarte},
                                                  {"relax", Stabilisation::Relax},
                                                  {"split_impulse", Stabilisation::SplitImpulse},
                                                  {"soft_step", Stabilisation::SoftStep}};

const char* toString(IntegratorKind kind) { return nameOf(kIntegratorNames, kind); }
const char* toString(GyroscopicMode mode) { return nameOf(kGyroscopicNames, mode); }
const char* toString(BroadphaseMode mode) { return nameOf(kBroadphaseNames, mode); }
const char* toString(CcdMode mode) { return nameOf(kCcdNames, mode); }
const char* toString(SolverKind kind) { return nameOf(kSolverNames, kind); }
const char* toString(Stabilisation stabilisation) { return nameOf(kStabilisationNames, stabilisation); }

}  // namespace stepwise
