// stepwise_extremes: where the engine's accuracy ends, measured (docs/reliability.md). The docs
// build runs it with --quick and shows its tables; without --quick it runs the long forms.
//
//   stepwise_extremes [--quick] [--check] [--soak-frames N] [--only narrowphase|far|soak|ratios|sizes|speed]
//
// --check: exit 1 when the soak broke a promise (ctest reliability.soak runs the quick soak so).
// Each table says what was run and what held, in numbers, for this build's Real.
#include "extremes.h"

#include "app/registry.h"
#include "02_gjk/box_oracle.h"
#include "03_epa/narrowphase.h"
#include "world/world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <vector>

using namespace stepwise;
using namespace stepwise::extremes;

namespace stepwise::extremes {

const char* precision() { return sizeof(Real) == sizeof(double) ? "double" : "float"; }

// --- shared scene pieces --------------------------------------------------------------------

int addBox(World& world, const std::string& name, BodyType type, const Vec3& position, const Vec3& half,
           Real density) {
    BodyDef def;
    def.name = name;
    def.type = type;
    def.shape = Shape::box(half);
    def.transform.position = position;
    def.density = density;
    return addBody(world, def);
}

bool allFinite(const World& world) {
    for (const Motion& motion : world.motions) {
        const Body& body = world.bodies[std::size_t(motion.bodyIndex)];
        if (!body.transform.position.allFinite() || !motion.linearVelocity.allFinite()) return false;
    }
    return true;
}

}  // namespace stepwise::extremes

namespace {

Quat randomRotation(std::mt19937& random) {
    std::normal_distribution<double> gauss;
    Eigen::Vector4d q;
    for (int i = 0; i < 4; ++i) q[i] = gauss(random);  // one draw per statement: argument order is unspecified
    q.normalize();
    return Quat(Real(q.w()), Real(q.x()), Real(q.y()), Real(q.z())).normalized();
}

/// The spacing of Real numbers at magnitude x: what a position there cannot resolve.
double ulpAt(double x) {
    const Real value = Real(std::max(std::abs(x), 1.0));
    return double(std::nextafter(value, Real(2) * value) - value);
}

// --- 1. narrowphase on adversarial box pairs, against the exact SAT depth ---------------------

struct PairCase {
    const char* name;
    Vec3 halfA, halfB;
    double overlap;        // along the stacking axis, m
    double distance;       // of the pair from the origin, m
};

void narrowphaseTable(bool quick) {
    const PairCase cases[] = {
        {"cubes, overlap 1e-4 of size", Vec3(0.5, 0.5, 0.5), Vec3(0.5, 0.5, 0.5), 1e-4, 0},
        {"aligned faces, overlap 1e-6", Vec3(0.5, 0.5, 0.5), Vec3(0.5, 0.5, 0.5), 1e-6, 0},
        {"thin plates 1000:1, overlap 1e-4", Vec3(1, 0.001, 1), Vec3(1, 0.001, 1), 1e-4, 0},
        {"5 cm box on 100 m slab (1000:1)", Vec3(50, 0.5, 50), Vec3(0.025, 0.025, 0.025), 1e-3, 0},
        {"cubes, overlap 1e-4, 1 km out", Vec3(0.5, 0.5, 0.5), Vec3(0.5, 0.5, 0.5), 1e-4, 1000},
        {"cubes, overlap 1e-4, 10 km out", Vec3(0.5, 0.5, 0.5), Vec3(0.5, 0.5, 0.5), 1e-4, 10000},
    };
    const int trials = quick ? 300 : 5000;
    std::printf("\nNarrowphase (GJK + EPA) on adversarial box pairs, %s build, %d random orientations each.\n"
                "Error: |depth - exact SAT depth of the same Real-valued poses| (box_oracle.h, in double).\n"
                "Target: 1e-6 x the larger size + the spacing of Real positions at that distance.\n\n",
                precision(), trials);
    std::printf("%-34s %12s %12s %12s %10s %9s\n", "pair", "max error m", "median m", "target m", "normal deg",
                "> target");
    std::mt19937 random(13);
    for (const PairCase& pair : cases) {
        const double size = std::max(pair.halfA.maxCoeff(), pair.halfB.maxCoeff()) * 2;
        const double target = 1e-6 * size + ulpAt(pair.distance + size);
        std::vector<double> errors;
        double worstNormal = 0;
        int failures = 0;
        for (int trial = 0; trial < trials; ++trial) {
            // B sits on A's top face, off centre, overlapping by `overlap`; the pair as a whole
            // is turned at random and moved `distance` from the origin.
            const Quat turn = trial == 0 ? Quat::Identity() : randomRotation(random);
            std::uniform_real_distribution<double> slide(-0.5, 0.5);
            const double slideX = slide(random);  // one draw per statement: argument order is unspecified
            const double slideZ = slide(random);
            const Eigen::Vector3d offset(slideX * double(pair.halfA.x()), double(pair.halfA.y() + pair.halfB.y()) - pair.overlap,
                                         slideZ * double(pair.halfA.z()));
            const Eigen::Vector3d away = pair.distance * Eigen::Vector3d(0.6, 0.48, 0.64);
            Transform poseA, poseB;
            poseA.position = away.cast<Real>();
            poseA.rotation = turn;
            poseB.position = (away + turn.cast<double>() * offset).cast<Real>();
            poseB.rotation = turn;
            const ContactQuery query = collideShapes(Shape::box(pair.halfA), poseA, Shape::box(pair.halfB), poseB);
            const oracle::SatResult exact =
                oracle::boxSat(oracle::makeOracleBox(pair.halfA, poseA), oracle::makeOracleBox(pair.halfB, poseB));
            const double exactDepth = exact.overlap ? exact.depth : 0;
            const double error = std::abs((query.intersect ? double(query.depth) : 0) - exactDepth);
            errors.push_back(error);
            if (error > target) ++failures;
            const double cosine = std::clamp(query.normal.cast<double>().dot(exact.axis), -1.0, 1.0);
            if (exact.overlap) worstNormal = std::max(worstNormal, std::acos(cosine) * 180 / M_PI);
        }
        std::sort(errors.begin(), errors.end());
        std::printf("%-34s %12.3g %12.3g %12.3g %10.3g %4d/%-4d\n", pair.name, errors.back(), errors[errors.size() / 2],
                    target, worstNormal, failures, trials);
    }
}

// --- 2. a stack far from the origin, against the same stack at the origin ---------------------

/// Shifted by `offset` along x: a ground slab; a box and a ball resting on it; a box sliding to a
/// stop on friction; and, apart, a stack of three boxes.
World farScene(double offset, bool stack) {
    World world;
    world.name = "far";
    const Real slop = world.settings.slop;
    const auto at = [offset](double x, double y, double z) { return Vec3(Real(offset + x), Real(y), Real(z)); };
    addBox(world, "ground", BodyType::Static, at(0, -0.5, 0), Vec3(20, Real(0.5), 20));
    if (stack) {
        for (int level = 0; level < 3; ++level)
            addBox(world, "box" + std::to_string(level), BodyType::Dynamic, at(0, 0.5 + level - double(slop), 0),
                   Vec3(Real(0.5), Real(0.5), Real(0.5)));
        return world;
    }
    addBox(world, "resting-box", BodyType::Dynamic, at(-3, 0.5 - double(slop), 0), Vec3(Real(0.5), Real(0.5), Real(0.5)));
    BodyDef ball;
    ball.name = "resting-ball";
    ball.shape = Shape::sphere(Real(0.5));
    ball.transform.position = at(0, 0.5 - double(slop), 0);
    addBody(world, ball);
    const int slider = addBox(world, "sliding-box", BodyType::Dynamic, at(3, 0.5 - double(slop), -5),
                              Vec3(Real(0.5), Real(0.5), Real(0.5)));
    world.motionOf(slider)->linearVelocity = Vec3(0, 0, 3);
    return world;
}

/// Largest distance between a body's path at `offset` (shifted back) and at the origin, m.
double strayFromOrigin(double offset, long frames) {
    World reference = farScene(0, false);
    World world = farScene(offset, false);
    Pipeline referencePipeline = chapterRegistry().makePipeline(reference);
    Pipeline pipeline = chapterRegistry().makePipeline(world);
    double stray = 0;
    for (long frame = 0; frame < frames; ++frame) {
        referencePipeline.step(reference);
        pipeline.step(world);
        if (!allFinite(world)) return INFINITY;
        for (std::size_t i = 0; i < world.bodies.size(); ++i) {
            const Eigen::Vector3d shifted = world.bodies[i].transform.position.cast<double>() - Eigen::Vector3d(offset, 0, 0);
            stray = std::max(stray, (shifted - reference.bodies[i].transform.position.cast<double>()).norm());
        }
    }
    return stray;
}

/// The top box's height after `frames` frames: 2.5 m when the stack stands.
double stackTop(double offset, long frames) {
    World world = farScene(offset, true);
    Pipeline pipeline = chapterRegistry().makePipeline(world);
    for (long frame = 0; frame < frames; ++frame) pipeline.step(world);
    return double(world.bodies.back().transform.position.y());
}

void farTable(bool quick) {
    const long frames = quick ? 300 : 1200;
    std::printf("\nFar from the origin, %s build, %ld frames. Stray: how far any body's path strays from the same\n"
                "scene's path at the origin (shifted back); the scene holds a resting box, a resting ball and a box\n"
                "sliding to a stop. Stack: the top of three 1 m boxes at the end (2.5 m when standing).\n\n",
                precision(), frames);
    std::printf("%-12s %14s %14s %12s\n", "distance m", "Real spacing m", "max stray m", "stack top m");
    for (double offset : {0.0, 100.0, 1000.0, 3000.0, 10000.0, 30000.0, 100000.0})
        std::printf("%-12.0f %14.3g %14.3g %12.4f\n", offset, ulpAt(offset), strayFromOrigin(offset, frames),
                    stackTop(offset, frames));
}

// --- 3. the soak: a long run of a mixed scene ---------------------------------------------------

// AddressSanitizer keeps freed memory in a quarantine of up to 256 MiB before reusing it, so
// under it the resident size grows for reasons that are not the engine's: the promise on memory
// is checked only in builds without it (the float and double builds of the README's command).
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kMemoryMeasurable = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kMemoryMeasurable = false;
#else
constexpr bool kMemoryMeasurable = true;
#endif
#else
constexpr bool kMemoryMeasurable = true;
#endif

long residentKiB() {
    if (!kMemoryMeasurable) return -1;
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
    return -1;
}

World mixedScene() {
    World world;
    world.name = "soak";
    addBox(world, "ground", BodyType::Static, Vec3(0, Real(-0.5), 0), Vec3(20, Real(0.5), 20));
    // A pit: nothing thrown can leave it (a body rolling off the ground's edge would fall for
    // the rest of the run, and its fall would dominate every number below).
    addBox(world, "wall-east", BodyType::Static, Vec3(8, 2, 0), Vec3(Real(0.5), 2, Real(8.5)));
    addBox(world, "wall-west", BodyType::Static, Vec3(-8, 2, 0), Vec3(Real(0.5), 2, Real(8.5)));
    addBox(world, "wall-north", BodyType::Static, Vec3(0, 2, 8), Vec3(Real(7.5), 2, Real(0.5)));
    addBox(world, "wall-south", BodyType::Static, Vec3(0, 2, -8), Vec3(Real(7.5), 2, Real(0.5)));
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0, 1);
    int index = 0;
    for (int column = 0; column < 3; ++column)  // three stacks of four boxes
        for (int level = 0; level < 4; ++level)
            addBox(world, "stack" + std::to_string(index++), BodyType::Dynamic,
                   Vec3(Real(-4 + 3 * column), Real(0.5 + level) - world.settings.slop, -3), Vec3(Real(0.5), Real(0.5), Real(0.5)));
    for (int i = 0; i < 12; ++i) {  // spheres, capsules and hulls thrown in at random
        BodyDef def;
        def.name = "thrown" + std::to_string(i);
        const int kind = i % 3;
        def.shape = kind == 0   ? Shape::sphere(Real(0.2 + 0.3 * unit(random)))
                    : kind == 1 ? Shape::capsule(Real(0.2), Real(0.3 + 0.3 * unit(random)))
                                : Shape::convex({Vec3(0, 0, 0), Vec3(Real(0.6), 0, 0), Vec3(0, Real(0.6), 0),
                                                 Vec3(0, 0, Real(0.6)), Vec3(Real(0.4), Real(0.4), Real(0.4))});
        const double x = -5 + 10 * unit(random);  // one draw per statement: argument order is unspecified
        const double y = 2 + 4 * unit(random);
        const double z = -1 + 5 * unit(random);
        def.transform.position = Vec3(Real(x), Real(y), Real(z));
        def.transform.rotation = randomRotation(random);
        const double vx = 10 * unit(random) - 5;
        const double vz = 10 * unit(random) - 5;
        def.linearVelocity = Vec3(Real(vx), 0, Real(vz));
        def.material.restitution = Real(0.3);
        addBody(world, def);
    }
    return world;
}

/// Returns false when the soak broke a promise: a non-finite body, the energy above its start by
/// more than 1%, or resident memory grown by more than 10% after the first 1,000 frames.
bool soakTable(bool quick, long framesAsked) {
    const long frames = framesAsked > 0 ? framesAsked : quick ? 5000 : 100000;
    World world = mixedScene();
    Pipeline pipeline = chapterRegistry().makePipeline(world);
    const double startEnergy = computeEnergy(world).total();
    double highest = startEnergy;
    long memoryAfterWarmUp = 0, highestFrame = 0, fastestFrame = 0;
    double fastest = 0;
    std::string fastestBody, firstFall;
    long finite = 0;
    const auto start = std::chrono::steady_clock::now();
    for (long frame = 0; frame < frames; ++frame) {
        pipeline.step(world);
        if (!allFinite(world)) break;
        ++finite;
        for (const Body& body : world.bodies)
            if (firstFall.empty() && body.transform.position.y() < -1)
                firstFall = body.name + ", frame " + std::to_string(frame + 1);
        const double energy = computeEnergy(world).total();
        if (energy > highest) highest = energy, highestFrame = frame + 1;
        for (const Motion& motion : world.motions)
            if (double(motion.linearVelocity.norm()) > fastest)
                fastest = double(motion.linearVelocity.norm()), fastestBody = world.bodies[std::size_t(motion.bodyIndex)].name,
                fastestFrame = frame + 1;
        if (frame == 999) memoryAfterWarmUp = residentKiB();
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("\nSoak: %zu bodies (three stacks, spheres, capsules and hulls thrown into a walled pit) for %ld frames (%.0f s simulated), %s build.\n\n",
                world.bodies.size(), frames, double(frames) * double(world.settings.dt), precision());
    std::printf("%-40s %s\n", "frames with every body finite", (std::to_string(finite) + " of " + std::to_string(frames)).c_str());
    std::printf("%-40s %.4g J\n", "energy at the start", startEnergy);
    std::printf("%-40s %.4g J (frame %ld)\n", "highest energy during the run", highest, highestFrame);
    std::printf("%-40s %.4g m/s (%s, frame %ld)\n", "highest speed during the run", fastest, fastestBody.c_str(), fastestFrame);
    int fallen = 0;
    for (const Body& body : world.bodies) fallen += body.transform.position.y() < -1;
    std::printf("%-40s %d (first: %s)\n", "bodies below the ground at the end", fallen,
                firstFall.empty() ? "none" : firstFall.c_str());
    std::printf("%-40s %.4g J\n", "energy at the end", computeEnergy(world).total());
    if (kMemoryMeasurable)
        std::printf("%-40s %ld KiB -> %ld KiB\n", "resident memory, frame 1000 -> end", memoryAfterWarmUp, residentKiB());
    else
        std::printf("%-40s %s\n", "resident memory", "not checked under AddressSanitizer (its quarantine holds freed memory)");
    std::printf("%-40s %.3g ms\n", "mean step time", 1000 * seconds / double(std::max(finite, 1L)));
    const long memoryAtEnd = residentKiB();
    return finite == frames && highest <= startEnergy + 0.01 * std::abs(startEnergy) &&
           (memoryAfterWarmUp <= 0 || memoryAtEnd <= memoryAfterWarmUp + memoryAfterWarmUp / 10);
}

}  // namespace

int main(int argc, char** argv) {
    bool quick = false, check = false;
    long soakFrames = 0;  // 0: the form's own count
    std::string only;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--quick") quick = true;
        else if (argument == "--only" && i + 1 < argc) only = argv[++i];
        else if (argument == "--check") check = true;
        else if (argument == "--soak-frames" && i + 1 < argc) soakFrames = std::max(1L, std::atol(argv[++i]));
        else {
            std::fprintf(stderr, "usage: stepwise_extremes [--quick] [--check] [--soak-frames N] "
                                 "[--only narrowphase|far|soak|ratios|sizes|speed]\n");
            return 2;
        }
    }
    std::printf("stepwise_extremes, %s build%s\n", precision(), quick ? ", quick form (the docs build)" : "");
    if (only.empty() || only == "narrowphase") narrowphaseTable(quick);
    if (only.empty() || only == "far") farTable(quick);
    bool soakHeld = true;
    if (only.empty() || only == "soak") soakHeld = soakTable(quick, soakFrames);
    if (only.empty() || only == "ratios") ratiosTable(quick);
    if (only.empty() || only == "sizes") sizesTable(quick);
    if (only.empty() || only == "speed") speedTable(quick);
    if (check && !soakHeld) {
        std::fprintf(stderr, "stepwise_extremes: the soak broke a promise (non-finite, energy or memory; see above)\n");
        return 1;
    }
    return 0;
}
