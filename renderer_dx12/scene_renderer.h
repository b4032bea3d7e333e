#pragma once
// Turns a DrawList into GPU work: three unit meshes drawn instanced (one draw call per mesh
// kind), one draw for all world-space triangles, one instanced draw for all lines and points.

#include "draw_list.h"
#include "targets.h"

namespace stepwise::render {

class SceneRenderer {
public:
    explicit SceneRenderer(Device& device);
    /// Records the draws into the device's open command list; the target is bound already.
    void record(Device& device, const TargetView& target, const FrameConstants& constants, const DrawList& list);

private:
    struct MeshRange {
        UINT indexCount = 0;
        UINT firstIndex = 0;
        INT baseVertex = 0;
    };
    template <class T>
    D3D12_VERTEX_BUFFER_VIEW upload(Device& device, const std::vector<T>& items);
    void drawMesh(Device& device, const MeshRange& range, const std::vector<MeshInstance>& instances);

    Pipelines pipelines_;
    Com<ID3D12Resource> staticBuffer_;  // unit meshes, quad corners, indices: written once
    D3D12_VERTEX_BUFFER_VIEW meshVertices_ = {};
    D3D12_VERTEX_BUFFER_VIEW quadCorners_ = {};
    D3D12_INDEX_BUFFER_VIEW indices_ = {};
    MeshRange cube_, sphere_, cylinder_, quad_;
};

}  // namespace stepwise::render
