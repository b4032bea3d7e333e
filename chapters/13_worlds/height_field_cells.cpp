#include "13_worlds/height_field_cells.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

namespace {

Real fieldCellsHeight(const HeightField& field, int row, int column) { return field.heights[row * field.columns + column]; }

/// The grid point (row, column) at its height, body frame.
Vec3 fieldCellsPoint(const HeightField& field, int row, int column) {
    return Vec3(Real(column) * field.cellSize, fieldCellsHeight(field, row, column), Real(row) * field.cellSize);
}

/// The index of the cell line at or below `coordinate` / cellSize, clamped to [low, high]. The
/// clamp comes before the conversion: a box far outside the grid, or a NaN, must not overflow an
/// int. A NaN clamps to `low`; the exact tests that follow reject it anyway.
int fieldCellsClampedLine(Real coordinate, Real cellSize, int low, int high) {
    const Real cell = std::floor(coordinate / cellSize);
    if (!(cell >= Real(low))) return low;
    if (!(cell <= Real(high))) return high;
    return static_cast<int>(cell);
}

/// Whether the cell's x-z extent and its height range overlap the box: the same comparisons as
/// Aabb::overlaps on the box of the cell's four corners, so a caller checking with the triangles'
/// own corners gets the same answer.
bool fieldCellsOverlap(const HeightField& field, int row, int column, const Aabb& box) {
    const Real x0 = Real(column) * field.cellSize, x1 = Real(column + 1) * field.cellSize;
    const Real z0 = Real(row) * field.cellSize, z1 = Real(row + 1) * field.cellSize;
    if (!(x0 <= box.max.x() && box.min.x() <= x1 && z0 <= box.max.z() && box.min.z() <= z1)) return false;
    const Real h[4] = {fieldCellsHeight(field, row, column), fieldCellsHeight(field, row, column + 1),
                       fieldCellsHeight(field, row + 1, column), fieldCellsHeight(field, row + 1, column + 1)};
    const Real low = std::min(std::min(h[0], h[1]), std::min(h[2], h[3]));
    const Real high = std::max(std::max(h[0], h[1]), std::max(h[2], h[3]));
    return low <= box.max.y() && box.min.y() <= high;
}

}  // namespace

bool heightFieldCellIsHole(const HeightField& field, int row, int column) {
    if (row < 0 || column < 0 || row >= field.rows - 1 || column >= field.columns - 1) return true;
    for (int corner = 0; corner < 4; ++corner) {
        if (std::isnan(fieldCellsHeight(field, row + corner / 2, column + corner % 2))) return true;
    }
    return false;
}

int heightFieldTriangleCount(const HeightField& field) {
    if (field.rows < 2 || field.columns < 2) return 0;
    return 2 * (field.rows - 1) * (field.columns - 1);
}

void queryHeightField(const HeightField& field, const Aabb& box, std::vector<int>& triangles) {
    if (heightFieldTriangleCount(field) == 0) return;
    const int lastRow = field.rows - 2, lastColumn = field.columns - 2;
    // One cell more on each side than the division says: the exact test below decides, so a
    // box edge that lands on a cell line within round-off loses nothing.
    const int firstColumn = fieldCellsClampedLine(box.min.x(), field.cellSize, 0, lastColumn + 1) - 1;
    const int endColumn = fieldCellsClampedLine(box.max.x(), field.cellSize, -1, lastColumn) + 1;
    const int firstRow = fieldCellsClampedLine(box.min.z(), field.cellSize, 0, lastRow + 1) - 1;
    const int endRow = fieldCellsClampedLine(box.max.z(), field.cellSize, -1, lastRow) + 1;
    for (int row = std::max(firstRow, 0); row <= std::min(endRow, lastRow); ++row) {
        for (int column = std::max(firstColumn, 0); column <= std::min(endColumn, lastColumn); ++column) {
            if (heightFieldCellIsHole(field, row, column) || !fieldCellsOverlap(field, row, column, box)) continue;
            const int cell = row * (field.columns - 1) + column;
            triangles.push_back(2 * cell);
            triangles.push_back(2 * cell + 1);
        }
    }
}

void heightFieldTriangle(const HeightField& field, int triangle, Vec3 corners[3]) {
    const int cell = triangle / 2;
    const int row = cell / (field.columns - 1), column = cell % (field.columns - 1);
    const Vec3 a = fieldCellsPoint(field, row, column);
    const Vec3 d = fieldCellsPoint(field, row + 1, column + 1);
    corners[0] = a;
    if (triangle % 2 == 0) {
        corners[1] = d;
        corners[2] = fieldCellsPoint(field, row, column + 1);  // b
    } else {
        corners[1] = fieldCellsPoint(field, row + 1, column);  // c'
        corners[2] = d;
    }
}

}  // namespace stepwise
