#pragma once
// The renderer's three pipelines (lit instanced meshes, lit triangles, screen-space thick
// lines) and the root signature they share: one block of root constants per frame.

#include "device.h"

namespace stepwise::render {

/// Per-frame constants, pushed as root constants (register b0). Keep in sync with kShaderSource.
struct FrameConstants {
    float viewProjRows[4][4];  // row-major view-projection: clip = rows * (world, 1)
    float cameraPosition[4];
    float lightDirection[4];   // unit vector towards the light
    float viewport[4];         // width px, height px, default line width px, near plane
};

/// Vertex of the unit meshes (cube, sphere, cylinder).
struct MeshVertex {
    float position[3];
    float normal[3];
};

/// One shaded instance of a unit mesh: world = rows * (scale * local) (rows hold rotation | position).
struct MeshInstance {
    float rows[3][4];
    float scale[4];
    float color[4];
};

/// A vertex of a world-space triangle (hulls, DebugDraw::triangle).
struct TriangleVertex {
    float position[3];
    float normal[3];
    float color[4];
};

/// One thick line (or, with from == to, a square point) expanded in the vertex shader.
struct LineInstance {
    float from[3];
    float to[3];
    float color[4];
    float widthPixels;  // 0: the frame's default line width
};

class Pipelines {
public:
    /// Compiles the HLSL with D3DCompile (at start-up, on Windows and under wine alike).
    explicit Pipelines(ID3D12Device* device);
    ID3D12RootSignature* rootSignature() const { return rootSignature_.get(); }
    ID3D12PipelineState* mesh() const { return mesh_.get(); }
    ID3D12PipelineState* triangles() const { return triangles_.get(); }
    ID3D12PipelineState* lines() const { return lines_.get(); }

private:
    Com<ID3D12RootSignature> rootSignature_;
    Com<ID3D12PipelineState> mesh_;
    Com<ID3D12PipelineState> triangles_;
    Com<ID3D12PipelineState> lines_;
};

}  // namespace stepwise::render
