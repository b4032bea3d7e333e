#include "world/settings.h"

namespace stepwise {

const std::vector<SettingUse>& settingUses() {
    static const std::vector<SettingUse> uses = {
        {"gravity", 1},        {"dt", 1},         {"substeps", 1},          {"integrator", 1},
        {"gyroscopic", 1},     {"solver", 4},     {"solver_iterations", 4}, {"baumgarte", 4},
        {"slop", 4},           {"restitution_threshold", 4},                {"broadphase", 5},
        {"warm_starting", 6},  {"stabilisation", 6},     {"contact_points", 6},  {"ccd", 7},
        {"sleeping", 10},      {"sleep_speed", 10},      {"time_to_sleep", 10},
    };
    return uses;
}

int chapterReading(const std::string& key) {
    for (const SettingUse& use : settingUses())
        if (key == use.key) return use.chapter;
    return 0;
}

// The spellings match the scene format (docs/scene-format.md).
const char* toString(IntegratorKind kind) {
    switch (kind) {
        case IntegratorKind::SemiImplicitEuler: return "semi_implicit_euler";
        case IntegratorKind::Rk4: return "rk4";
        case IntegratorKind::Verlet: return "verlet";
    }
    return "?";
}

const char* toString(GyroscopicMode mode) {
    switch (mode) {
        case GyroscopicMode::Off: return "off";
        case GyroscopicMode::Explicit: return "explicit";
        case GyroscopicMode::Implicit: return "implicit";
    }
    return "?";
}

const char* toString(BroadphaseMode mode) {
    switch (mode) {
        case BroadphaseMode::Auto: return "auto";
        case BroadphaseMode::Sap: return "sap";
        case BroadphaseMode::Brute: return "brute";
    }
    return "?";
}

const char* toString(CcdMode mode) {
    switch (mode) {
        case CcdMode::Auto: return "auto";
        case CcdMode::On: return "on";
        case CcdMode::Off: return "off";
    }
    return "?";
}

const char* toString(SolverKind kind) {
    switch (kind) {
        case SolverKind::GaussSeidel: return "gauss_seidel";
        case SolverKind::Jacobi: return "jacobi";
    }
    return "?";
}

const char* toString(Stabilisation stabilisation) {
    switch (stabilisation) {
        case Stabilisation::Baumgarte: return "baumgarte";
        case Stabilisation::Relax: return "relax";
        case Stabilisation::SplitImpulse: return "split_impulse";
        case Stabilisation::SoftStep: return "soft_step";
    }
    return "?";
}

}  // namespace stepwise
