#include "scene_renderer.h"

#include <cmath>
#include <cstring>

namespace stepwise::render {

namespace {

constexpr float kPiF = 3.14159265f;

struct MeshBuilder {
    std::vector<MeshVertex> vertices;
    std::vector<uint16_t> indices;

    void vertex(float px, float py, float pz, float nx, float ny, float nz) {
        vertices.push_back({{px, py, pz}, {nx, ny, nz}});
    }
    void quadIndices(int a, int b, int c, int d) {
        for (int i : {a, b, c, a, c, d}) indices.push_back(static_cast<uint16_t>(i));
    }
};

/// Unit cube [-1, 1]^3 with flat normals (4 vertices per face).
void addCube(MeshBuilder& mesh) {
    for (int axis = 0; axis < 3; ++axis) {
        for (int sign = -1; sign <= 1; sign += 2) {
            const int base = static_cast<int>(mesh.vertices.size());
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            for (int corner = 0; corner < 4; ++corner) {
                float p[3], n[3] = {0, 0, 0};
                p[axis] = static_cast<float>(sign);
                p[u] = (corner == 1 || corner == 2) ? 1.0f : -1.0f;
                p[v] = (corner >= 2) ? 1.0f : -1.0f;
                n[axis] = static_cast<float>(sign);
                mesh.vertex(p[0], p[1], p[2], n[0], n[1], n[2]);
            }
            mesh.quadIndices(base, base + 1, base + 2, base + 3);
        }
    }
}

/// Unit sphere as latitude/longitude rings.
void addSphere(MeshBuilder& mesh, int slices, int stacks) {
    const int base = static_cast<int>(mesh.vertices.size());
    for (int i = 0; i <= stacks; ++i) {
        const float theta = kPiF * static_cast<float>(i) / static_cast<float>(stacks);
        for (int j = 0; j <= slices; ++j) {
            const float phi = 2 * kPiF * static_cast<float>(j) / static_cast<float>(slices);
            const float x = std::sin(theta) * std::cos(phi), y = std::cos(theta), z = std::sin(theta) * std::sin(phi);
            mesh.vertex(x, y, z, x, y, z);
        }
    }
    for (int i = 0; i < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            const int a = base + i * (slices + 1) + j;
            mesh.quadIndices(a, a + 1, a + slices + 2, a + slices + 1);
        }
    }
}

/// Open unit cylinder of radius 1 along Y from -1 to 1 (capsules close it with spheres).
void addCylinder(MeshBuilder& mesh, int slices) {
    const int base = static_cast<int>(mesh.vertices.size());
    for (int j = 0; j <= slices; ++j) {
        const float phi = 2 * kPiF * static_cast<float>(j) / static_cast<float>(slices);
        const float x = std::cos(phi), z = std::sin(phi);
        mesh.vertex(x, -1, z, x, 0, z);
        mesh.vertex(x, 1, z, x, 0, z);
    }
    for (int j = 0; j < slices; ++j) mesh.quadIndices(base + 2 * j, base + 2 * j + 1, base + 2 * j + 3, base + 2 * j + 2);
}

}  // namespace

SceneRenderer::SceneRenderer(Device& device) : pipelines_(device.device()) {
    MeshBuilder mesh;
    auto range = [&](auto add) {
        MeshRange out;
        out.firstIndex = static_cast<UINT>(mesh.indices.size());
        out.baseVertex = static_cast<INT>(mesh.vertices.size());
        const size_t firstVertex = mesh.vertices.size();
        add();
        // Indices were written absolute; make them relative to the mesh's base vertex.
        for (size_t i = out.firstIndex; i < mesh.indices.size(); ++i) {
            mesh.indices[i] = static_cast<uint16_t>(mesh.indices[i] - firstVertex);
        }
        out.indexCount = static_cast<UINT>(mesh.indices.size()) - out.firstIndex;
        return out;
    };
    cube_ = range([&] { addCube(mesh); });
    sphere_ = range([&] { addSphere(mesh, 32, 16); });
    cylinder_ = range([&] { addCylinder(mesh, 32); });
    quad_.firstIndex = static_cast<UINT>(mesh.indices.size());
    for (uint16_t i : {0, 1, 2, 0, 2, 3}) mesh.indices.push_back(i);
    quad_.indexCount = 6;
    // Line corners: x = 0 at `from`, 1 at `to`; y = side.
    const float corners[4][2] = {{0, -1}, {1, -1}, {1, 1}, {0, 1}};

    const size_t vertexBytes = mesh.vertices.size() * sizeof(MeshVertex);
    const size_t cornerBytes = sizeof corners;
    const size_t indexBytes = mesh.indices.size() * sizeof(uint16_t);
    staticBuffer_ = createBuffer(device.device(), D3D12_HEAP_TYPE_UPLOAD, vertexBytes + cornerBytes + indexBytes,
                                 D3D12_RESOURCE_STATE_GENERIC_READ);
    uint8_t* mapped = nullptr;
    D3D12_RANGE nothingRead = {0, 0};
    check(staticBuffer_->Map(0, &nothingRead, reinterpret_cast<void**>(&mapped)), "Map(static meshes)");
    std::memcpy(mapped, mesh.vertices.data(), vertexBytes);
    std::memcpy(mapped + vertexBytes, corners, cornerBytes);
    std::memcpy(mapped + vertexBytes + cornerBytes, mesh.indices.data(), indexBytes);
    staticBuffer_->Unmap(0, nullptr);
    const D3D12_GPU_VIRTUAL_ADDRESS gpu = staticBuffer_->GetGPUVirtualAddress();
    meshVertices_ = {gpu, static_cast<UINT>(vertexBytes), sizeof(MeshVertex)};
    quadCorners_ = {gpu + vertexBytes, static_cast<UINT>(cornerBytes), sizeof(float) * 2};
    indices_ = {gpu + vertexBytes + cornerBytes, static_cast<UINT>(indexBytes), DXGI_FORMAT_R16_UINT};
}

template <class T>
D3D12_VERTEX_BUFFER_VIEW SceneRenderer::upload(Device& device, const std::vector<T>& items) {
    const size_t bytes = items.size() * sizeof(T);
    UploadSlice slice = device.allocate(bytes, 16);
    std::memcpy(slice.cpu, items.data(), bytes);
    return {slice.gpu, static_cast<UINT>(bytes), static_cast<UINT>(sizeof(T))};
}

void SceneRenderer::drawMesh(Device& device, const MeshRange& range, const std::vector<MeshInstance>& instances) {
    if (instances.empty()) return;
    const D3D12_VERTEX_BUFFER_VIEW views[2] = {meshVertices_, upload(device, instances)};
    device.list()->IASetVertexBuffers(0, 2, views);
    device.list()->DrawIndexedInstanced(range.indexCount, static_cast<UINT>(instances.size()), range.firstIndex,
                                        range.baseVertex, 0);
}

void SceneRenderer::record(Device& device, const TargetView& target, const FrameConstants& constants,
                           const DrawList& list) {
    ID3D12GraphicsCommandList* commands = device.list();
    const D3D12_VIEWPORT viewport = {0, 0, static_cast<float>(target.width), static_cast<float>(target.height), 0, 1};
    const D3D12_RECT scissor = {0, 0, target.width, target.height};
    commands->RSSetViewports(1, &viewport);
    commands->RSSetScissorRects(1, &scissor);
    commands->SetGraphicsRootSignature(pipelines_.rootSignature());
    commands->SetGraphicsRoot32BitConstants(0, sizeof(FrameConstants) / 4, &constants, 0);
    commands->IASetPrimitiveTopology(D3D_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    commands->IASetIndexBuffer(&indices_);

    commands->SetPipelineState(pipelines_.mesh());
    drawMesh(device, cube_, list.boxes);
    drawMesh(device, sphere_, list.spheres);
    drawMesh(device, cylinder_, list.cylinders);

    if (!list.triangles.empty()) {
        commands->SetPipelineState(pipelines_.triangles());
        const D3D12_VERTEX_BUFFER_VIEW view = upload(device, list.triangles);
        commands->IASetVertexBuffers(0, 1, &view);
        commands->DrawInstanced(static_cast<UINT>(list.triangles.size()), 1, 0, 0);
    }
    if (!list.lines.empty()) {
        commands->SetPipelineState(pipelines_.lines());
        const D3D12_VERTEX_BUFFER_VIEW views[2] = {quadCorners_, upload(device, list.lines)};
        commands->IASetVertexBuffers(0, 2, views);
        commands->DrawIndexedInstanced(quad_.indexCount, static_cast<UINT>(list.lines.size()), quad_.firstIndex, 0, 0);
    }
}

}  // namespace stepwise::render
