#pragma once
// A height field's triangles, found from the grid alone. A height field needs no tree: the cells
// under a box are the ones whose column and row ranges the box covers, found by division, and a
// triangle is named by its cell and its half. Every query then checks each cell it visits
// against the box's heights too, which culls a box floating above the surface.
//
// Cell (r, c) has the corners a = (r, c), b = (r, c + 1), c' = (r + 1, c) and d = (r + 1, c + 1)
// at x = column * cellSize, z = row * cellSize. It is split along the diagonal from a to d into
// two triangles whose corners run counter-clockwise seen from +y, so both fronts face up:
//
//     half 0: (a, d, b)    the triangle on the side of row r's edge (a-b)
//     half 1: (a, c', d)   the triangle on the side of column c's edge (a-c')
//
// Triangle index = 2 * (r * (columns - 1) + c) + half. A cell with a NaN height at any of its
// four corners is a hole: neither of its triangles exists.

#include "world/shape.h"

#include <vector>

namespace stepwise {

/// Whether cell (row, column) is a hole: a NaN height at one of its corners. Cells outside the
/// grid count as holes (there is no surface there either).
bool heightFieldCellIsHole(const HeightField& field, int row, int column);

/// The number of triangles the grid names, holes included: 2 (rows - 1) (columns - 1).
int heightFieldTriangleCount(const HeightField& field);

/// Appends to `triangles` both triangles of every cell that is not a hole, whose x-z extent
/// overlaps the box and whose height range (its four corners') overlaps the box's y range
/// (body frame; touching counts), row by row, half 0 before half 1. It does not clear the list.
/// An empty box (min > max) or one with a NaN finds nothing.
void queryHeightField(const HeightField& field, const Aabb& box, std::vector<int>& triangles);

/// The corners of a triangle, body frame, in the order given above (counter-clockwise seen from
/// +y, so the front faces up). A hole's triangle gets its corners too, NaN heights and all.
void heightFieldTriangle(const HeightField& field, int triangle, Vec3 corners[3]);

}  // namespace stepwise
