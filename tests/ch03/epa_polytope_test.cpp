// EPA's own machinery: the polytope stays a closed, consistently stitched surface around the
// origin; stepping one expansion at a time only ever improves the answer; odd seeds still work.
#include "03_epa/epa.h"
#include "ch03/random_pairs.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace stepwise;
using stepwise::Random;

namespace {

struct Case {
    Shape a, b;
    Transform poseA, poseB;
};

Case randomOverlap(Random& random, int kind) {
    Case c;
    const Vec3 half(Real(random.uniform(0.1, 1)), Real(random.uniform(0.1, 1)), Real(random.uniform(0.1, 1)));
    c.a = Shape::box(half);
    c.b = kind == 0 ? Shape::box(half.reverse()) : kind == 1 ? Shape::sphere(Real(random.uniform(0.2, 1)))
                                                 : Shape::capsule(Real(random.uniform(0.1, 0.5)), Real(random.uniform(0.1, 1)));
    c.poseA.rotation = random.rotation();
    c.poseB.rotation = random.rotation();
    c.poseB.position = Real(random.uniform(0, 0.6)) * random.unitVector();
    return c;
}

/// Every live face's neighbours are live, point back at it across the same edge reversed, and
/// every face's plane has the origin on its inner side (within round-off).
void checkPolytope(const EpaPolytope& polytope) {
    int live = 0;
    for (int f = 0; f < static_cast<int>(polytope.faces.size()); ++f) {
        const EpaFace& face = polytope.faces[f];
        if (face.removed) continue;
        ++live;
        CHECK(face.distance >= Real(-1e-5));
        CHECK(std::abs(face.normal.norm() - 1) < Real(1e-5));
        for (int edge = 0; edge < 3; ++edge) {
            const int neighbourIndex = face.neighbours[edge];
            REQUIRE(neighbourIndex >= 0);
            REQUIRE(neighbourIndex < static_cast<int>(polytope.faces.size()));
            const EpaFace& neighbour = polytope.faces[neighbourIndex];
            CHECK_FALSE(neighbour.removed);
            const int from = face.vertices[edge], to = face.vertices[(edge + 1) % 3];
            bool reversed = false;
            for (int j = 0; j < 3; ++j) {
                if (neighbour.vertices[j] == to && neighbour.vertices[(j + 1) % 3] == from) {
                    reversed = neighbour.neighbours[j] == f;
                }
            }
            CHECK(reversed);
        }
    }
    // A closed triangulated sphere: F = 2V - 4 over the vertices the live faces use.
    std::vector<int> used(polytope.vertices.size(), 0);
    for (const EpaFace& face : polytope.faces) {
        if (!face.removed) for (int v : face.vertices) used[v] = 1;
    }
    int vertexCount = 0;
    for (int flag : used) vertexCount += flag;
    CHECK(live == 2 * vertexCount - 4);
}

}  // namespace

TEST_CASE("The polytope stays closed and stitched, with the origin inside", "[ch03][epa]") {
    Random random(31u);
    EpaSettings settings;
    settings.keepPolytope = true;
    for (int i = 0; i < 300; ++i) {
        const Case c = randomOverlap(random, i % 3);
        const ConvexProxy a{&c.a, c.poseA}, b{&c.b, c.poseB};
        const GjkResult gjk = gjkIntersect(a, b);
        if (!gjk.intersect) continue;
        const EpaResult result = epaPenetration(a, b, gjk.simplex, settings);
        REQUIRE(result.exit != EpaExit::Degenerate);
        checkPolytope(result.polytope);
    }
}

TEST_CASE("Stepping EPA one expansion at a time only improves the answer", "[ch03][epa]") {
    Random random(32u);
    for (int i = 0; i < 100; ++i) {
        const Case c = randomOverlap(random, i % 3);
        const ConvexProxy a{&c.a, c.poseA}, b{&c.b, c.poseB};
        const GjkResult gjk = gjkIntersect(a, b);
        if (!gjk.intersect) continue;
        const EpaResult full = epaPenetration(a, b, gjk.simplex);
        Real previous = 0;
        for (int step = 0; step <= full.iterations; ++step) {
            EpaSettings settings;
            settings.maxExpansions = step;
            const EpaResult partial = epaPenetration(a, b, gjk.simplex, settings);
            CHECK(partial.iterations == step);
            CHECK(partial.exit == (step < full.iterations ? EpaExit::StepLimit : full.exit));
            // The closest face's distance is a lower bound that grows as the polytope does.
            CHECK(partial.depth >= previous - Real(1e-6));
            CHECK(partial.depth <= full.depth + Real(1e-6));
            previous = partial.depth;
        }
        CHECK(previous == full.depth);
    }
}

TEST_CASE("EPA grows any GJK simplex into a tetrahedron", "[ch03][epa]") {
    // Hand EPA only part of GJK's simplex (1, 2 or 3 of its points): the seed must still grow.
    Random random(33u);
    int compared = 0;
    for (int i = 0; i < 200; ++i) {
        const Case c = randomOverlap(random, 0);
        const ConvexProxy a{&c.a, c.poseA}, b{&c.b, c.poseB};
        const GjkResult gjk = gjkIntersect(a, b);
        if (!gjk.intersect || gjk.simplex.count != 4) continue;
        const EpaResult reference = epaPenetration(a, b, gjk.simplex);
        for (int keep = 1; keep <= 3; ++keep) {
            // Starting from a point of A - B that is not near the origin is no longer a valid
            // GJK seed (it need not hold the origin); the seed search must cope or give up cleanly.
            Simplex partial = gjk.simplex;
            partial.count = keep;
            const EpaResult result = epaPenetration(a, b, partial);
            REQUIRE(std::isfinite(result.depth));
            if (result.exit == EpaExit::Converged) {
                CHECK(result.depth == Approx(reference.depth).epsilon(1e-4));
                ++compared;
            }
        }
    }
    CHECK(compared > 100);
}

TEST_CASE("An empty or touching simplex gives a defined zero-depth answer", "[ch03][epa]") {
    const Shape box = Shape::box(Vec3::Ones());
    Transform poseB;
    poseB.position = Vec3(0, 2, 0);  // faces exactly touching
    const ConvexProxy a{&box, Transform{}}, b{&box, poseB};
    Simplex empty;
    const EpaResult none = epaPenetration(a, b, empty);
    CHECK(none.exit == EpaExit::Degenerate);
    CHECK(std::isfinite(none.depth));
    CHECK(none.depth <= Real(1e-6));
    CHECK(none.normal.y() == Approx(1));

    Simplex touching;
    touching.vertices[0] = minkowskiSupport(a, b, Vec3::UnitY());
    touching.count = 1;
    const EpaResult result = epaPenetration(a, b, touching);
    CHECK(std::isfinite(result.depth));
    CHECK(result.depth <= Real(1e-5));
    CHECK(result.normal.y() == Approx(1).margin(1e-3));
}
