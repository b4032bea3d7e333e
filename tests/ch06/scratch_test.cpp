#include "06_manifolds/scenes.h"
#include "world/scene.h"
#include "06_manifolds/stacking_study.h"
#include <catch2/catch.hpp>
#include <cstdio>
#include <string>
using namespace stepwise;
TEST_CASE("scratch", "[.scratch]") {
    struct Item { const char* name; World (*build)(); };
    Item items[] = {{"stack16", +[] { return buildBoxStack(16); }}, {"pyramid20", +[] { return buildPyramid(20); }},
                    {"heavy", +[] { return buildHeavyOnLight(); }}, {"towerBelow", +[] { return buildMassTower(true); }},
                    {"towerAbove", +[] { return buildMassTower(false); }}, {"ramp", +[] { return buildStickingRamp(); }},
                    {"stagger", +[] { World w = buildBoxStack(16); for (std::size_t i = 1; i < w.bodies.size(); ++i) w.bodies[i].transform.position.x() += Real(0.02) * Real(i % 2); return w; }},
                    {"shrink", +[] { World w = buildBoxStack(16); for (std::size_t i = 1; i < w.bodies.size(); ++i) if (i % 2) w.bodies[i].shape.halfExtents = Vec3(Real(0.45), Real(0.5), Real(0.45)); return w; }},
                    {"stack8", +[] { return buildBoxStack(8); }},
                    {"twobox", +[] { return loadSceneFile("scenes/two-box-stack.json"); }}};
    for (Stabilisation s : {Stabilisation::Baumgarte, Stabilisation::Relax, Stabilisation::SplitImpulse, Stabilisation::SoftStep})
        for (bool warm : {true, false})
            for (const Item& item : items) {
                if (std::getenv("ONLY") && std::string(std::getenv("ONLY")).find(item.name) == std::string::npos) continue;
                if (std::getenv("STABS") && std::string(std::getenv("STABS")).find(toString(s)) == std::string::npos) continue;
                if (std::getenv("WARMONLY") && !warm) continue;
                StackingConfig config;
                config.stabilisation = s;
                config.warmStarting = warm;
                if (const char* it = std::getenv("ITER")) config.iterations = std::atoi(it);
                if (const char* it = std::getenv("SUB")) config.substeps = std::atoi(it);
                const StackingMeasure m = measureStacking(item.build(), config, 10);
                std::printf("%-13s warm %d %-10s drift %8.4f sink %8.4f perContact %8.4f excess %8.4f pen %8.4f top %7.3f->%7.3f %s %.3f ms\n",
                            toString(s), warm, item.name, m.maxDrift, m.maxSink, m.maxSinkPerContact, m.maxSinkExcess,
                            m.maxPenetration, m.topHeightStart, m.topHeightEnd, m.stood ? "stood" : "FELL", m.stepMs);
                std::fflush(stdout);
            }
}
