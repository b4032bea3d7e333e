// Active edges against geometry built to have known answers: a tessellated floor's seams are
// inactive and its border active, a convex ridge is active and a valley is not, with the switch at
// kActiveEdgeAngle; a contact on a seam with a slanted normal gets the face normal back, one on a
// ridge keeps its own; a height field's grid adjacency agrees with the mesh's, holes and all.
#include "13_worlds/height_field_cells.h"
#include "13_worlds/triangle_edges.h"

#include "math/random.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

using namespace stepwise;

namespace {

/// A flat floor of n x n unit quads on y = 0, two triangles each, fronts up; `random` picks each
/// quad's diagonal, so both splits meet at the seams.
TriangleMesh triangleEdgesTestFloor(Random& random, int n) {
    TriangleMesh mesh;
    for (int r = 0; r <= n; ++r) {
        for (int c = 0; c <= n; ++c) mesh.vertices.emplace_back(Real(c), 0, Real(r));
    }
    for (int r = 0; r < n; ++r) {
        for (int c = 0; c < n; ++c) {
            const int a = r * (n + 1) + c, b = a + 1, below = a + n + 1, d = below + 1;
            if (random.uniform() < 0.5) {
                mesh.triangles.push_back({a, d, b});
                mesh.triangles.push_back({a, below, d});
            } else {
                mesh.triangles.push_back({a, below, b});
                mesh.triangles.push_back({b, below, d});
            }
        }
    }
    return mesh;
}

/// Two triangles sharing the edge from (0, 0, 0) to (0, 0, 1): the first flat on the -x side, the
/// second on the +x side turned down by `bendDegrees` about the edge (a ridge: convex) or up for
/// a negative bend (a valley: concave). The shared edge is edge 2 of the first, edge 0 of the
/// second.
TriangleMesh triangleEdgesTestFold(double bendDegrees) {
    const double bend = bendDegrees * 3.14159265358979323846 / 180;
    TriangleMesh mesh;
    mesh.vertices = {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(-1, 0, Real(0.5)),
                     Vec3(Real(std::cos(bend)), Real(-std::sin(bend)), Real(0.5))};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}};
    return mesh;
}

/// Whether the edge from `from` to `to` runs along the border of the rectangle [0, width] x
/// [0, depth] in x and z.
bool triangleEdgesTestAlongBorder(const Vec3& from, const Vec3& to, Real width, Real depth) {
    const bool alongX = from.z() == to.z() && (from.z() == 0 || from.z() == depth);
    const bool alongZ = from.x() == to.x() && (from.x() == 0 || from.x() == width);
    return alongX || alongZ;
}

void triangleEdgesTestCorners(const TriangleMesh& mesh, int triangle, Vec3 corners[3]) {
    for (int k = 0; k < 3; ++k) corners[k] = mesh.vertices[mesh.triangles[triangle][k]];
}

/// A field whose heights are flat in places, a little rough in others and steep in others, so its
/// edges come out both active and inactive, with about `holeFraction` of the heights holes.
HeightField triangleEdgesTestField(Random& random, int rows, int columns, double holeFraction) {
    HeightField field;
    field.rows = rows;
    field.columns = columns;
    field.cellSize = Real(0.5);
    for (int i = 0; i < rows * columns; ++i) {
        const double kind = random.uniform();
        Real height = 0;
        if (kind >= 0.4) height = kind < 0.7 ? random.uniformReal(Real(-0.01), Real(0.01)) : random.uniformReal(-1, 1);
        if (random.uniform() < holeFraction) height = std::numeric_limits<Real>::quiet_NaN();
        field.heights.push_back(height);
    }
    return field;
}

/// The field's surface as a mesh over the grid points (vertex r * columns + c), without the
/// holes' triangles; `fieldTriangle` maps each mesh triangle to the field's index.
TriangleMesh triangleEdgesTestFieldMesh(const HeightField& field, std::vector<int>& fieldTriangle) {
    TriangleMesh mesh;
    for (int r = 0; r < field.rows; ++r) {
        for (int c = 0; c < field.columns; ++c) {
            mesh.vertices.emplace_back(Real(c) * field.cellSize, field.heights[r * field.columns + c], Real(r) * field.cellSize);
        }
    }
    for (int r = 0; r + 1 < field.rows; ++r) {
        for (int c = 0; c + 1 < field.columns; ++c) {
            if (heightFieldCellIsHole(field, r, c)) continue;
            const int a = r * field.columns + c, b = a + 1, below = a + field.columns, d = below + 1;
            const int cell = r * (field.columns - 1) + c;
            mesh.triangles.push_back({a, d, b});
            fieldTriangle.push_back(2 * cell);
            mesh.triangles.push_back({a, below, d});
            fieldTriangle.push_back(2 * cell + 1);
        }
    }
    return mesh;
}

}  // namespace

TEST_CASE("a tessellated flat floor has every inner edge inactive and every border edge active", "[ch13]") {
    Random random(1321);
    const int n = 6;
    TriangleMesh floor = triangleEdgesTestFloor(random, n);
    // Also turned and moved far off: coplanar in exact arithmetic, not in float.
    TriangleMesh tilted = floor;
    const Quat turn = random.rotation();
    for (Vec3& v : tilted.vertices) v = turn * v + Vec3(300, -200, 100);
    for (const TriangleMesh* mesh : {&floor, &tilted}) {
        const TriangleEdges edges = findTriangleEdges(*mesh);
        REQUIRE(edges.neighbour.size() == mesh->triangles.size());
        int borderEdges = 0;
        for (int t = 0; t < static_cast<int>(mesh->triangles.size()); ++t) {
            for (int k = 0; k < 3; ++k) {
                // Judged on the untilted floor: an edge is on the border when it runs along it.
                const int from = floor.triangles[t][k], to = floor.triangles[t][(k + 1) % 3];
                const bool border = triangleEdgesTestAlongBorder(floor.vertices[from], floor.vertices[to], Real(n), Real(n));
                borderEdges += border ? 1 : 0;
                CHECK(edges.active[t][k] == border);
                const int other = edges.neighbour[t][k];
                CHECK((other == -1) == border);
                if (other < 0) continue;
                // The neighbour is across the same two vertices, and names this triangle back.
                int back = 0;
                for (int j = 0; j < 3; ++j) {
                    if (floor.triangles[other][j] == to && floor.triangles[other][(j + 1) % 3] == from) {
                        ++back;
                        CHECK(edges.neighbour[other][j] == t);
                    }
                }
                CHECK(back == 1);
            }
        }
        CHECK(borderEdges == 4 * n);
    }
}

TEST_CASE("an edge is active on a convex ridge bent beyond the tolerance and inactive in any valley", "[ch13]") {
    const double limit = double(kActiveEdgeAngle) * 180 / 3.14159265358979323846;
    for (const double bend : {0.0, 1e-4, 2.0, limit - 0.1, limit + 0.1, 30.0, 90.0, 170.0, 179.5, -1e-4, -2.0, -limit - 0.1,
                              -30.0, -90.0, -170.0, -179.5}) {
        INFO("bend " << bend << " degrees");
        const TriangleMesh mesh = triangleEdgesTestFold(bend);
        // The oracle is the geometry: the second triangle's far corner lies below the first's
        // plane on a ridge; past 179 degrees either way the two lie back to back.
        const Vec3 firstNormal = (mesh.vertices[2] - mesh.vertices[0]).cross(mesh.vertices[1] - mesh.vertices[0]);
        const bool convex = firstNormal.dot(mesh.vertices[3] - mesh.vertices[0]) < 0;
        const bool expected = (convex && std::abs(bend) > limit) || std::abs(bend) > 179;
        const TriangleEdges edges = findTriangleEdges(mesh);
        CHECK(edges.neighbour[0][2] == 1);
        CHECK(edges.neighbour[1][0] == 0);
        CHECK(edges.active[0][2] == expected);
        CHECK(edges.active[1][0] == expected);
        CHECK(edges.active[0][0]);  // the rest is border
        CHECK(edges.active[1][2]);
    }
}

TEST_CASE("an edge of three triangles or of two with opposite fronts is active", "[ch13]") {
    TriangleMesh fin = triangleEdgesTestFold(0);
    fin.vertices.emplace_back(0, 1, Real(0.5));
    fin.triangles.push_back({0, 1, 4});  // a third triangle standing on the shared edge
    const TriangleEdges three = findTriangleEdges(fin);
    CHECK(three.neighbour[0][2] == -1);
    CHECK(three.neighbour[1][0] == -1);
    CHECK(three.neighbour[2][0] == -1);
    CHECK((three.active[0][2] && three.active[1][0] && three.active[2][0]));

    // A ridge whose second triangle's front faces down: read with that winding it would look like
    // a valley, and be dropped.
    TriangleMesh flipped = triangleEdgesTestFold(30);
    flipped.triangles[1] = {0, 3, 1};
    const TriangleEdges opposite = findTriangleEdges(flipped);
    CHECK(opposite.neighbour[0][2] == 1);
    CHECK(opposite.neighbour[1][2] == 0);
    CHECK(opposite.active[0][2]);
    CHECK(opposite.active[1][2]);
}

TEST_CASE("a contact on a seam with a slanted normal gets the face normal back, one on a ridge keeps its own", "[ch13]") {
    Random random(1322);
    const int n = 3;
    const TriangleMesh floor = triangleEdgesTestFloor(random, n);
    const TriangleEdges edges = findTriangleEdges(floor);
    const Vec3 up(0, 1, 0);
    int seams = 0, borders = 0;
    for (int t = 0; t < static_cast<int>(floor.triangles.size()); ++t) {
        Vec3 corners[3];
        triangleEdgesTestCorners(floor, t, corners);
        const Vec3 centre = (corners[0] + corners[1] + corners[2]) / 3;
        for (int k = 0; k < 3; ++k) {
            const Vec3 middle = (corners[k] + corners[(k + 1) % 3]) / 2;
            // Slanted away from the triangle, back across its edge: the ghost's normal.
            const Vec3 slanted = ((middle - centre).normalized() + up).normalized();
            const Vec3 corrected = correctedNormal(corners, edges.active[t], middle, slanted);
            if (edges.active[t][k]) {
                ++borders;
                CHECK(corrected == slanted);
            } else {
                ++seams;
                CHECK(corrected == up);
            }
            // Inside the triangle, away from every edge: nothing to correct.
            CHECK(correctedNormal(corners, edges.active[t], centre, slanted) == slanted);
            // Already the face normal: returned as it came.
            CHECK(correctedNormal(corners, edges.active[t], middle, up) == up);
        }
    }
    CHECK(seams > 0);
    CHECK(borders == 4 * n);

    for (const double bend : {30.0, -30.0}) {
        const TriangleMesh fold = triangleEdgesTestFold(bend);
        const TriangleEdges foldEdges = findTriangleEdges(fold);
        Vec3 corners[3];
        triangleEdgesTestCorners(fold, 0, corners);
        const Vec3 secondNormal = (fold.vertices[1] - fold.vertices[0]).cross(fold.vertices[3] - fold.vertices[0]).normalized();
        const Vec3 between = (up + secondNormal).normalized();
        const Vec3 corrected = correctedNormal(corners, foldEdges.active[0], Vec3(0, 0, Real(0.5)), between);
        if (bend > 0) {
            CHECK(corrected == between);  // a ridge: the edge is real
        } else {
            CHECK(corrected == up);  // a valley: the faces push, not the edge
        }
    }
}

TEST_CASE("a contact at a vertex gets the face normal only when both its edges in the triangle are inactive", "[ch13]") {
    const Vec3 corners[3] = {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0)};
    const Vec3 slanted = Vec3(-1, 1, -1).normalized();
    const Vec3 up(0, 1, 0);
    // Vertex 0 lies on edges 0 (corner 0 to 1) and 2 (corner 2 to 0).
    CHECK(correctedNormal(corners, {false, false, false}, corners[0], slanted) == up);
    CHECK(correctedNormal(corners, {false, true, false}, corners[0], slanted) == up);
    CHECK(correctedNormal(corners, {true, false, false}, corners[0], slanted) == slanted);
    CHECK(correctedNormal(corners, {false, false, true}, corners[0], slanted) == slanted);
    // Within the band around an edge, relative to the triangle's size, the point is on it.
    const Real longest = std::sqrt(Real(2));
    const Vec3 onEdge0(0, 0, Real(0.5));
    const Vec3 band = kEdgeContactFraction * longest * Vec3(1, 0, 0);  // towards the inside
    CHECK(correctedNormal(corners, {false, true, true}, onEdge0 + Real(0.5) * band, slanted) == up);
    CHECK(correctedNormal(corners, {false, true, true}, onEdge0 - Real(0.5) * band, slanted) == up);
    CHECK(correctedNormal(corners, {false, true, true}, onEdge0 + 20 * band, slanted) == slanted);
    // The face normal comes back unit length and out of the front, on a triangle turned anywhere.
    Random random(1323);
    const Quat turn = random.rotation();
    const Vec3 turned[3] = {turn * corners[0], turn * corners[1], turn * corners[2]};
    const Vec3 corrected = correctedNormal(turned, {false, false, false}, turned[0], turn * slanted);
    CHECK((corrected - turn * up).norm() < 100 * kEpsilon);
}

TEST_CASE("a height field's edges match the mesh of the same surface, holes counting as border", "[ch13]") {
    Random random(1324);
    for (const double holes : {0.0, 0.08}) {
        INFO("holes " << holes);
        const HeightField field = triangleEdgesTestField(random, 11, 9, holes);
        std::vector<int> fieldTriangle;
        const TriangleMesh mesh = triangleEdgesTestFieldMesh(field, fieldTriangle);
        const TriangleEdges edges = findTriangleEdges(mesh);
        int active = 0, inactive = 0;
        for (int i = 0; i < static_cast<int>(mesh.triangles.size()); ++i) {
            const int t = fieldTriangle[i];
            const std::array<bool, 3> fieldActive = heightFieldActiveEdges(field, t);
            for (int k = 0; k < 3; ++k) {
                const int meshNeighbour = edges.neighbour[i][k];
                CHECK(heightFieldNeighbour(field, t, k) == (meshNeighbour < 0 ? -1 : fieldTriangle[meshNeighbour]));
                CHECK(fieldActive[k] == edges.active[i][k]);
                (fieldActive[k] ? active : inactive) += 1;
            }
        }
        CHECK(active > 20);
        CHECK(inactive > 20);
    }
}

TEST_CASE("a height field ridge is active along its crest and a valley is not", "[ch13]") {
    for (const Real sign : {Real(-1), Real(1)}) {
        HeightField field;
        field.rows = 5;
        field.columns = 7;
        field.cellSize = 1;
        for (int r = 0; r < field.rows; ++r) {
            for (int c = 0; c < field.columns; ++c) field.heights.push_back(sign * Real(0.5) * Real(std::abs(c - 3)));
        }
        for (int t = 0; t < heightFieldTriangleCount(field); ++t) {
            Vec3 corners[3];
            heightFieldTriangle(field, t, corners);
            const std::array<bool, 3> active = heightFieldActiveEdges(field, t);
            for (int k = 0; k < 3; ++k) {
                const Vec3& from = corners[k];
                const Vec3& to = corners[(k + 1) % 3];
                const bool border = triangleEdgesTestAlongBorder(from, to, 6, 4);
                const bool crest = from.x() == 3 && to.x() == 3;
                CHECK(active[k] == (border || (crest && sign < 0)));
            }
        }
    }
}
