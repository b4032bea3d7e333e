#include "13_worlds/triangle_edges.h"

#include "13_worlds/height_field_cells.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

namespace {

/// One triangle edge, keyed by its two vertex indices (lower first) so the triangles that share
/// it sort next to each other.
struct TriangleEdgeRecord {
    int low = 0, high = 0;
    int triangle = 0, edge = 0;
};

bool triangleEdgeRecordBefore(const TriangleEdgeRecord& a, const TriangleEdgeRecord& b) {
    if (a.low != b.low) return a.low < b.low;
    if (a.high != b.high) return a.high < b.high;
    if (a.triangle != b.triangle) return a.triangle < b.triangle;
    return a.edge < b.edge;
}

Vec3 triangleEdgesFaceCross(const TriangleMesh& mesh, int triangle) {
    const std::array<int, 3>& corners = mesh.triangles[triangle];
    const Vec3& a = mesh.vertices[corners[0]];
    return (mesh.vertices[corners[1]] - a).cross(mesh.vertices[corners[2]] - a);
}

std::vector<TriangleEdgeRecord> triangleEdgesSortedRecords(const TriangleMesh& mesh) {
    std::vector<TriangleEdgeRecord> records;
    records.reserve(3 * mesh.triangles.size());
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
        for (int k = 0; k < 3; ++k) {
            const int from = mesh.triangles[t][k], to = mesh.triangles[t][(k + 1) % 3];
            records.push_back({std::min(from, to), std::max(from, to), t, k});
        }
    }
    std::sort(records.begin(), records.end(), triangleEdgeRecordBefore);
    return records;
}

/// Sets both sides of an edge shared by exactly two triangles. The flag is computed once from the
/// first side and given to both: the rule is symmetric, and computing it twice could let round-off
/// disagree with itself.
void triangleEdgesPair(const TriangleMesh& mesh, const TriangleEdgeRecord& first, const TriangleEdgeRecord& second,
                       TriangleEdges& edges) {
    edges.neighbour[first.triangle][first.edge] = second.triangle;
    edges.neighbour[second.triangle][second.edge] = first.triangle;
    const std::array<int, 3>& corners = mesh.triangles[first.triangle];
    const int from = corners[first.edge], to = corners[(first.edge + 1) % 3];
    // Consistent windings run a shared edge in opposite directions.
    const bool consistent = mesh.triangles[second.triangle][(second.edge + 1) % 3] == from;
    const bool active = !consistent || isEdgeActive(triangleEdgesFaceCross(mesh, first.triangle),
                                                    triangleEdgesFaceCross(mesh, second.triangle),
                                                    mesh.vertices[to] - mesh.vertices[from]);
    edges.active[first.triangle][first.edge] = active;
    edges.active[second.triangle][second.edge] = active;
}

}  // namespace

bool isEdgeActive(const Vec3& faceNormal, const Vec3& neighbourNormal, const Vec3& edge) {
    const Real faceLength = faceNormal.norm(), neighbourLength = neighbourNormal.norm();
    if (!(faceLength > 0 && neighbourLength > 0)) return true;
    const Vec3 n1 = faceNormal / faceLength, n2 = neighbourNormal / neighbourLength;
    const Real cosBend = n1.dot(n2);
    if (cosBend < kBackToBackCos) return true;
    // Seen along the edge (in the first face's winding, its interior on the left from its front),
    // n1 turns towards n2 about +edge when the faces bend away from the body, convexly.
    const bool convex = n1.cross(n2).dot(edge) > 0;
    return convex && cosBend < kActiveEdgeCos;
}

TriangleEdges findTriangleEdges(const TriangleMesh& mesh) {
    const int count = static_cast<int>(mesh.triangles.size());
    TriangleEdges edges;
    edges.neighbour.assign(count, {-1, -1, -1});
    edges.active.assign(count, {true, true, true});
    const std::vector<TriangleEdgeRecord> records = triangleEdgesSortedRecords(mesh);
    for (size_t first = 0; first < records.size();) {
        size_t end = first + 1;
        while (end < records.size() && records[end].low == records[first].low && records[end].high == records[first].high) {
            ++end;
        }
        // One record: the boundary. Three or more: not a surface's edge. Both stay -1 and active.
        // A triangle with a repeated corner has an edge from a vertex to itself: no edge either.
        if (end - first == 2 && records[first].low != records[first].high) {
            triangleEdgesPair(mesh, records[first], records[first + 1], edges);
        }
        first = end;
    }
    return edges;
}

Vec3 correctedNormal(const Vec3 triangle[3], const std::array<bool, 3>& activeEdges, const Vec3& pointOnTriangle,
                     const Vec3& normal) {
    const Vec3 cross = (triangle[1] - triangle[0]).cross(triangle[2] - triangle[0]);
    const Real crossLength = cross.norm();
    if (!(crossLength > 0)) return normal;
    const Vec3 face = cross / crossLength;
    if (normal.dot(face) >= kSameNormalCos * normal.norm()) return normal;

    Real longest = 0;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, (triangle[(k + 1) % 3] - triangle[k]).norm());
    const Real band = kEdgeContactFraction * longest;
    bool onAnyEdge = false;
    for (int k = 0; k < 3; ++k) {
        // The distance from edge k into the triangle, in its plane: face x edge points inwards
        // for counter-clockwise corners. A point outside (round-off) is on the edge too.
        const Vec3 edge = triangle[(k + 1) % 3] - triangle[k];
        const Vec3 inward = face.cross(edge).normalized();
        const bool onEdge = (pointOnTriangle - triangle[k]).dot(inward) <= band;
        // On an active edge, or at a vertex one of whose edges is active: the normal is real.
        if (onEdge && activeEdges[k]) return normal;
        onAnyEdge = onAnyEdge || onEdge;
    }
    return onAnyEdge ? face : normal;
}

int heightFieldNeighbour(const HeightField& field, int triangle, int edge) {
    const int cell = triangle / 2, half = triangle % 2;
    const int row = cell / (field.columns - 1), column = cell % (field.columns - 1);
    if (heightFieldCellIsHole(field, row, column)) return -1;
    // Half 0 is (a, d, b): edge 0 the diagonal, edge 1 the column c + 1 line, edge 2 the row r
    // line. Half 1 is (a, c', d): edge 0 the column c line, edge 1 the row r + 1 line, edge 2
    // the diagonal. Across a line lies the other half of the next cell.
    static constexpr int kRowStep[2][3] = {{0, 0, -1}, {0, 1, 0}};
    static constexpr int kColumnStep[2][3] = {{0, 1, 0}, {-1, 0, 0}};
    const int nextRow = row + kRowStep[half][edge], nextColumn = column + kColumnStep[half][edge];
    if (heightFieldCellIsHole(field, nextRow, nextColumn)) return -1;
    return 2 * (nextRow * (field.columns - 1) + nextColumn) + (1 - half);
}

std::array<bool, 3> heightFieldActiveEdges(const HeightField& field, int triangle) {
    std::array<bool, 3> active = {true, true, true};
    Vec3 corners[3];
    heightFieldTriangle(field, triangle, corners);
    const Vec3 face = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
    for (int k = 0; k < 3; ++k) {
        const int neighbour = heightFieldNeighbour(field, triangle, k);
        if (neighbour < 0) continue;
        Vec3 other[3];
        heightFieldTriangle(field, neighbour, other);
        const Vec3 neighbourFace = (other[1] - other[0]).cross(other[2] - other[0]);
        active[k] = isEdgeActive(face, neighbourFace, corners[(k + 1) % 3] - corners[k]);
    }
    return active;
}

}  // namespace stepwise
