// A height field's triangles from the grid: each triangle's corners are its cell's grid points,
// its front faces +y, and a box query finds exactly what brute force over every cell finds,
// holes skipped, box edges on cell lines included.
#include "13_worlds/height_field_cells.h"

#include "math/random.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace stepwise;

namespace {

/// A rows x columns field with random heights in [-1, 2] m and about `holeFraction` of the
/// heights NaN.
HeightField heightFieldCellsTestField(Random& random, int rows, int columns, Real cellSize, double holeFraction) {
    HeightField field;
    field.rows = rows;
    field.columns = columns;
    field.cellSize = cellSize;
    field.lowest = kRealMax;
    field.highest = -kRealMax;
    for (int i = 0; i < rows * columns; ++i) {
        const bool hole = random.uniform() < holeFraction;
        const Real height = random.uniformReal(-1, 2);
        field.heights.push_back(hole ? std::numeric_limits<Real>::quiet_NaN() : height);
        if (!hole) field.lowest = std::min(field.lowest, height), field.highest = std::max(field.highest, height);
    }
    return field;
}

Vec3 heightFieldCellsTestGridPoint(const HeightField& field, int row, int column) {
    return Vec3(Real(column) * field.cellSize, field.heights[row * field.columns + column], Real(row) * field.cellSize);
}

/// Every triangle whose cell has all four heights and whose cell box (its two triangles' six
/// corners) overlaps the box.
std::vector<int> heightFieldCellsTestBruteForce(const HeightField& field, const Aabb& box) {
    std::vector<int> found;
    const int count = 2 * (field.rows - 1) * (field.columns - 1);
    for (int t = 0; t < count; ++t) {
        const int cell = t / 2;
        Aabb cellBox;
        bool hole = false;
        for (int half = 0; half < 2; ++half) {
            Vec3 corners[3];
            heightFieldTriangle(field, 2 * cell + half, corners);
            for (const Vec3& corner : corners) {
                hole = hole || std::isnan(corner.y());
                cellBox.grow(corner);
            }
        }
        if (!hole && cellBox.overlaps(box)) found.push_back(t);
    }
    return found;
}

/// A random box over the field: sizes from a point to the whole field, and a third of them with
/// their x and z sides snapped onto cell lines, where touching must count.
Aabb heightFieldCellsTestBox(Random& random, const HeightField& field) {
    const Real width = Real(field.columns - 1) * field.cellSize, depth = Real(field.rows - 1) * field.cellSize;
    Aabb box;
    // One draw per statement: the order of a call's arguments is the compiler's.
    box.min.x() = random.uniformReal(-1, width + 1);
    box.min.y() = random.uniformReal(-2, 3);
    box.min.z() = random.uniformReal(-1, depth + 1);
    const Real size = random.uniform() < 0.2 ? 0 : random.uniformReal(0, random.uniform() < 0.1 ? width : 3 * field.cellSize);
    const Real height = random.uniformReal(0, 1);
    const Real stretch = random.uniformReal(0, 2);
    box.max = box.min + Vec3(size, height, size * stretch);
    if (random.uniform() < 0.33) {
        for (int axis : {0, 2}) {
            box.min[axis] = std::round(box.min[axis] / field.cellSize) * field.cellSize;
            box.max[axis] = std::round(box.max[axis] / field.cellSize) * field.cellSize;
        }
    }
    return box;
}

}  // namespace

TEST_CASE("each height field triangle has its cell's grid points as corners and its front facing +y", "[ch13]") {
    Random random(1311);
    const HeightField field = heightFieldCellsTestField(random, 5, 7, Real(0.75), 0);
    CHECK(heightFieldTriangleCount(field) == 2 * 4 * 6);
    for (int r = 0; r + 1 < field.rows; ++r) {
        for (int c = 0; c + 1 < field.columns; ++c) {
            const int cell = r * (field.columns - 1) + c;
            const Vec3 a = heightFieldCellsTestGridPoint(field, r, c);
            const Vec3 b = heightFieldCellsTestGridPoint(field, r, c + 1);
            const Vec3 below = heightFieldCellsTestGridPoint(field, r + 1, c);
            const Vec3 d = heightFieldCellsTestGridPoint(field, r + 1, c + 1);
            Vec3 first[3], second[3];
            heightFieldTriangle(field, 2 * cell, first);
            heightFieldTriangle(field, 2 * cell + 1, second);
            CHECK(first[0] == a);
            CHECK(first[1] == d);
            CHECK(first[2] == b);
            CHECK(second[0] == a);
            CHECK(second[1] == below);
            CHECK(second[2] == d);
            for (const Vec3* corners : {first, second}) {
                // Counter-clockwise seen from +y: the right-hand normal points up, whatever the
                // heights (its y is cellSize^2 exactly in exact arithmetic).
                const Vec3 normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
                CHECK(normal.y() > 0);
                CHECK(normal.y() == Approx(field.cellSize * field.cellSize));
            }
        }
    }
}

TEST_CASE("a height field query finds exactly the cells that overlap the box, holes skipped, as brute force does", "[ch13]") {
    Random random(1312);
    for (const Real cellSize : {Real(1), Real(0.3), Real(2.5)}) {
        for (const double holes : {0.0, 0.1, 0.4}) {
            INFO("cell size " << cellSize << ", holes " << holes);
            const HeightField field = heightFieldCellsTestField(random, 12, 17, cellSize, holes);
            int nonEmpty = 0;
            for (int q = 0; q < 400; ++q) {
                const Aabb box = heightFieldCellsTestBox(random, field);
                std::vector<int> found;
                queryHeightField(field, box, found);
                CHECK(std::is_sorted(found.begin(), found.end()));
                CHECK(std::adjacent_find(found.begin(), found.end()) == found.end());
                CHECK(found == heightFieldCellsTestBruteForce(field, box));
                for (int t : found) {
                    const int cell = t / 2;
                    CHECK(!heightFieldCellIsHole(field, cell / (field.columns - 1), cell % (field.columns - 1)));
                }
                if (!found.empty()) ++nonEmpty;
            }
            CHECK(nonEmpty > 40);    // the boxes did meet the surface (with 40 % of the heights holes,
            CHECK(nonEmpty < 400);   // nearly 90 % of the cells are) and some missed it
        }
    }
}

TEST_CASE("a height field query finds every triangle but the holes' under a box around all, none above or below", "[ch13]") {
    Random random(1313);
    const HeightField field = heightFieldCellsTestField(random, 9, 6, Real(0.5), 0.05);
    Aabb all;
    all.min = Vec3(-1, field.lowest, -1);
    all.max = Vec3(10, field.highest, 10);
    std::vector<int> found;
    queryHeightField(field, all, found);
    int cellsWithSurface = 0;
    for (int r = 0; r + 1 < field.rows; ++r) {
        for (int c = 0; c + 1 < field.columns; ++c) cellsWithSurface += heightFieldCellIsHole(field, r, c) ? 0 : 1;
    }
    CHECK(cellsWithSurface > 0);
    CHECK(found.size() == static_cast<size_t>(2 * cellsWithSurface));

    // Touching counts: a box whose top is the lowest height meets the cells around that
    // height, one whose bottom is the highest meets the cells around that one.
    for (const Real touch : {field.lowest, field.highest}) {
        Aabb flat = all;
        flat.min.y() = flat.max.y() = touch;
        std::vector<int> touched;
        queryHeightField(field, flat, touched);
        CHECK(!touched.empty());
    }

    std::vector<int> none;
    Aabb above = all, below = all, beside = all;
    above.min.y() = field.highest + Real(0.01);
    above.max.y() = field.highest + 1;
    below.min.y() = field.lowest - 1;
    below.max.y() = field.lowest - Real(0.01);
    beside.min.x() = 3;  // past the last column line, x = 2.5
    queryHeightField(field, above, none);
    queryHeightField(field, below, none);
    queryHeightField(field, beside, none);
    queryHeightField(field, Aabb(), none);  // empty: min > max
    Aabb notANumber = all;
    notANumber.max.z() = std::nan("");
    queryHeightField(field, notANumber, none);
    Aabb huge;
    huge.min = Vec3::Constant(-kRealMax);
    huge.max = Vec3(kRealMax, -kRealMax, kRealMax);  // everywhere in x and z, below everything in y
    queryHeightField(field, huge, none);
    CHECK(none.empty());
}

TEST_CASE("a height field query appends to the caller's list", "[ch13]") {
    Random random(1314);
    const HeightField field = heightFieldCellsTestField(random, 4, 4, 1, 0);
    std::vector<int> found = {-3};
    Aabb box;
    box.min = Vec3(Real(0.5), -5, Real(0.5));
    box.max = Vec3(Real(0.6), 5, Real(0.6));
    queryHeightField(field, box, found);
    REQUIRE(found.size() == 3);
    CHECK(found[0] == -3);
    CHECK(found[1] == 0);
    CHECK(found[2] == 1);
}
