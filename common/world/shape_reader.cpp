// The shape kinds of chapter 13 in scene files (docs/scene-format.md, "Shapes"): cylinder,
// compound, mesh (inline or a Wavefront OBJ file) and height field, read with the loader's rules:
// every value checked, every rejection naming its JSON path.
#include "world/json_reader.h"
#include "world/scene_limits.h"

#include <cmath>
#include <filesystem>
#include <sstream>

namespace stepwise {

namespace {

// Builds a shape whose factory may refuse it (ShapeError), naming the JSON value.
template <class Build>
Shape built(const JsonCursor& where, Build build) {
    try {
        return build();
    } catch (const ShapeError& error) {
        where.fail(error.what());
    }
}

int readIndex(const JsonCursor& cursor, std::size_t vertexCount) {
    const Real value = cursor.number();
    if (std::floor(value) != value || value < 0 || value >= Real(vertexCount))
        cursor.fail("must be a vertex index in [0, " + std::to_string(vertexCount) + ")");
    return static_cast<int>(value);
}

}  // namespace

Shape readCylinder(const JsonCursor& params) {
    params.expectObject({"radius", "half_height"});
    const Real radius = params.child("radius").positiveBetween(kMinShapeSize, kMaxShapeSize);
    return Shape::cylinder(radius, params.child("half_height").positiveBetween(kMinShapeSize, kMaxShapeSize));
}

Shape readCompound(const JsonCursor& params, const std::string& baseDirectory) {
    params.expectObject({"children"});
    const JsonCursor list = params.child("children");
    const std::size_t count = list.arraySizeAtMost(kMaxCompoundChildren);
    if (count == 0) list.fail("a compound needs at least one child");
    std::vector<CompoundChild> children(count);
    for (std::size_t i = 0; i < count; ++i) {
        const JsonCursor entry = list.element(i);
        entry.expectObject({"shape", "position", "orientation"});
        children[i].shape = readShape(entry.child("shape"), baseDirectory);
        if (!isConvexKind(children[i].shape.type))
            entry.child("shape").fail(std::string("a compound's child must be convex (box, sphere, capsule, convex, "
                                                  "cylinder), not a ") + toString(children[i].shape.type));
        if (auto v = entry.optional("position")) children[i].transform.position = v->vec3Within(kMaxShapeSize);
        if (auto v = entry.optional("orientation")) children[i].transform.rotation = v->unitQuaternion();
    }
    return built(list, [&] { return Shape::compoundOf(std::move(children)); });
}

Shape readMesh(const JsonCursor& params, const std::string& baseDirectory) {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles;
    if (params.has("obj")) {
        params.expectObject({"obj"});
        const JsonCursor file = params.child("obj");
        const std::filesystem::path named(file.nonEmptyString());
        const std::string path = named.is_absolute() ? named.string() : (std::filesystem::path(baseDirectory) / named).string();
        try {
            readObjFile(path, vertices, triangles);
        } catch (const SceneError& error) {
            file.fail(error.what());
        }
        if (triangles.empty()) file.fail("'" + path + "' has no faces");
        return built(file, [&] { return Shape::triangleMesh(std::move(vertices), std::move(triangles)); });
    }
    params.expectObject({"vertices", "triangles"});
    const JsonCursor vertexList = params.child("vertices");
    vertices.resize(vertexList.arraySizeAtMost(kMaxMeshVertices));
    for (std::size_t i = 0; i < vertices.size(); ++i) vertices[i] = vertexList.element(i).vec3Within(kMaxCoordinate);
    const JsonCursor triangleList = params.child("triangles");
    triangles.resize(triangleList.arraySizeAtMost(kMaxMeshTriangles));
    if (triangles.empty()) triangleList.fail("a mesh needs at least one triangle");
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const JsonCursor corners = triangleList.element(t);
        if (!corners.json().is_array() || corners.json().size() != 3) corners.fail("must be an array of 3 vertex indices [i, j, k]");
        for (std::size_t k = 0; k < 3; ++k) triangles[t][k] = readIndex(corners.element(k), vertices.size());
    }
    return built(triangleList, [&] { return Shape::triangleMesh(std::move(vertices), std::move(triangles)); });
}

Shape readHeightField(const JsonCursor& params) {
    params.expectObject({"rows", "columns", "cell_size", "heights"});
    const int rows = params.child("rows").integer(2, 1 << 16);
    const int columns = params.child("columns").integer(2, 1 << 16);
    const Real cellSize = params.child("cell_size").positiveBetween(kMinShapeSize, kMaxShapeSize);
    const JsonCursor list = params.child("heights");
    const std::size_t expected = static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns);
    if (expected > kMaxHeightSamples)
        params.fail("rows * columns is " + std::to_string(expected) + "; at most " + std::to_string(kMaxHeightSamples) +
                    " heights are supported");
    const std::size_t count = list.arraySizeAtMost(kMaxHeightSamples);
    if (count != expected)
        list.fail("has " + std::to_string(count) + " heights; rows * columns is " + std::to_string(expected));
    std::vector<Real> heights(count);
    for (std::size_t i = 0; i < count; ++i) {
        const JsonCursor height = list.element(i);
        // null is a hole (JSON has no NaN); any number must be finite and in range.
        heights[i] = height.json().is_null() ? std::numeric_limits<Real>::quiet_NaN() : height.within(kMaxCoordinate);
    }
    return built(list, [&] { return Shape::heightFieldOf(rows, columns, cellSize, std::move(heights)); });
}

void readObjFile(const std::string& path, std::vector<Vec3>& vertices, std::vector<std::array<int, 3>>& triangles) {
    std::istringstream text(readInputFile(path, "a mesh (OBJ) file"));
    std::string line;
    int lineNumber = 0;
    const auto fail = [&](const std::string& message) {
        throw SceneError(path + ":" + std::to_string(lineNumber), message);
    };
    while (std::getline(text, line)) {
        ++lineNumber;
        std::istringstream fields(line);
        std::string tag;
        fields >> tag;
        if (tag == "v") {
            double x = 0, y = 0, z = 0;
            if (!(fields >> x >> y >> z)) fail("a vertex needs three numbers: v x y z");
            const Vec3 vertex(static_cast<Real>(x), static_cast<Real>(y), static_cast<Real>(z));
            if (!vertex.allFinite() || vertex.cwiseAbs().maxCoeff() > kMaxCoordinate)
                fail("vertex coordinates must be finite and within " + std::to_string(double(kMaxCoordinate)));
            if (vertices.size() >= kMaxMeshVertices) fail("more than " + std::to_string(kMaxMeshVertices) + " vertices");
            vertices.push_back(vertex);
        } else if (tag == "f") {
            std::vector<int> corners;
            std::string corner;
            while (fields >> corner) {
                // "i", "i/t", "i//n" or "i/t/n": the vertex index is the first number; negative
                // counts back from the last vertex read.
                long index = 0;
                try {
                    index = std::stol(corner.substr(0, corner.find('/')));
                } catch (const std::exception&) {
                    fail("a face corner must start with a vertex index (got '" + corner + "')");
                }
                const long count = static_cast<long>(vertices.size());
                const long resolved = index < 0 ? count + index : index - 1;
                if (index == 0 || resolved < 0 || resolved >= count)
                    fail("face corner " + corner + " names no vertex read so far (" + std::to_string(count) + ")");
                corners.push_back(static_cast<int>(resolved));
            }
            if (corners.size() < 3) fail("a face needs at least three corners");
            for (std::size_t k = 1; k + 1 < corners.size(); ++k) {  // a fan over the polygon
                if (triangles.size() >= kMaxMeshTriangles) fail("more than " + std::to_string(kMaxMeshTriangles) + " triangles");
                triangles.push_back({corners[0], corners[k], corners[k + 1]});
            }
        }
    }
}

}  // namespace stepwise
