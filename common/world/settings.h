#pragma once
// Every tuning constant of a world, in one struct, with its unit. Scene files set them through
// the "settings" object (see docs/scene-format.md); the defaults follow the scene contract.

#include "math/math.h"
#include "world/enum_names.h"

#include <string>
#include <vector>

namespace stepwise {

enum class IntegratorKind { SemiImplicitEuler, Rk4, Verlet };
enum class GyroscopicMode { Off, Explicit, Implicit };
enum class BroadphaseMode { Auto, Sap, Brute };
enum class CcdMode { Auto, On, Off };
enum class SolverKind { GaussSeidel, Jacobi };
/// How the contact solve removes penetration (chapter 6): chapter 4's Baumgarte bias in the
/// velocities; the same followed by a relax pass without bias after the positions moved;
/// split impulses (the correction in pseudo-velocities that never reach the real ones); or
/// Box2D v3's soft step (soft contacts, a relax pass, restitution at the end).
enum class Stabilisation { Baumgarte, Relax, SplitImpulse, SoftStep };

struct Settings {
    Vec3 gravity = Vec3(0, Real(-9.81), 0);          // m/s^2
    Real dt = Real(1.0 / 60.0);                       // s per frame
    int substeps = 1;                                 // stage passes per frame
    int solverIterations = 10;                        // velocity iterations per substep
    // solver_iterations "auto" (the default, and 10 written out): chapter 12's planner may change
    // the count from solverIterations; any other number in the scene file (false here) is used as
    // it stands, unless the file's plan_iterations says otherwise.
    bool planIterations = true;
    Real baumgarte = Real(0.2);                       // fraction of the position error fed back per step
    Real slop = Real(0.005);                          // m of penetration left uncorrected
    Real restitutionThreshold = Real(1.0);            // m/s closing speed below which contacts do not bounce
    bool warmStarting = true;
    Stabilisation stabilisation = Stabilisation::Relax;  // chapter 6 on
    bool manifoldContacts = true;                     // chapter 6 on: up to 4 points per pair; false: one
    BroadphaseMode broadphase = BroadphaseMode::Auto;
    CcdMode ccd = CcdMode::Auto;
    IntegratorKind integrator = IntegratorKind::SemiImplicitEuler;
    GyroscopicMode gyroscopic = GyroscopicMode::Implicit;
    SolverKind solver = SolverKind::GaussSeidel;
    // Sleeping (chapter 10): islands whose bodies all stayed slow for timeToSleep stop being
    // solved and integrated until something wakes them (Box2D v3 and Jolt use 0.05 m/s and 0.5 s).
    bool sleeping = true;
    Real sleepSpeed = Real(0.05);                     // m/s: slow below it, at the centre and at the bounding radius
    Real timeToSleep = Real(0.5);                     // s every body of an island must stay slow
    // Contact stiffness of the soft step (chapter 6): contacts are springs of this frequency and
    // damping ratio (twice the frequency against a body that cannot move), at most a quarter of
    // the substep rate (Box2D v3's defaults: 30 Hz, ratio 10).
    Real contactHertz = Real(30);                     // Hz
    Real contactDampingRatio = Real(10);              // 1: critically damped
    // Joint stiffness of the fast solve (chapter 11): the joints' position feedback is a spring of
    // this frequency and damping ratio, at most a quarter of the substep rate. The default is that
    // quarter at 20 substeps of a 60 Hz frame: as stiff as any planned count up to 20 allows
    // (Box2D v3 defaults to 60 Hz and ratio 2). A higher ratio keeps more of a row's impulse each
    // sweep (impulse scale 5% against 10% at 150 Hz): a limb pinned between contacts yields less
    // to them, and every seed of the 100-ragdoll field settles within 2 degrees at 5. Its price:
    // half the bias rate, so a fast-swinging chain's joints part further while it swings hardest
    // (bench/results/joint-damping.txt).
    Real jointHertz = Real(300);                      // Hz
    Real jointDampingRatio = Real(5);                 // 1: critically damped
    Real maxPushOutSpeed = Real(3);                   // m/s: the fastest a penetration is pushed out (chapter 6)
    Real boundsMargin = Real(0.1);                    // m each box grows before a sweep (chapter 10's grown boxes)
    // Chapter 13: a contact on a mesh or height field triangle takes only normals the triangle's
    // neighbours allow (no bump at a seam between triangles); false shows the bump (the A/B).
    bool activeEdges = true;
};

/// A setting and the chapter whose stage first reads it. A scene file may set any of them, but
/// the demo shows a control, and a run counts a setting, only from that chapter on; before,
/// the demo and the run summary say "not used until chapter N".
struct SettingUse {
    const char* key;   // the scene-format key: "warm_starting"
    int chapter;
};

/// Every setting, in scene-format order, with the chapter that reads it.
const std::vector<SettingUse>& settingUses();
/// The chapter that first reads `key` (0 for an unknown key).
int chapterReading(const std::string& key);

/// The names scene files give each choice (docs/scene-format.md): the loader reads them, toString
/// writes them.
extern const Names<IntegratorKind> kIntegratorNames;
extern const Names<GyroscopicMode> kGyroscopicNames;
extern const Names<BroadphaseMode> kBroadphaseNames;
extern const Names<CcdMode> kCcdNames;
extern const Names<SolverKind> kSolverNames;
extern const Names<Stabilisation> kStabilisationNames;

const char* toString(IntegratorKind kind);
const char* toString(GyroscopicMode mode);
const char* toString(BroadphaseMode mode);
const char* toString(CcdMode mode);
const char* toString(SolverKind kind);
const char* toString(Stabilisation stabilisation);

}  // namespace stepwise
