#include "world/settings.h"

namespace stepwise {

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

}  // namespace stepwise
