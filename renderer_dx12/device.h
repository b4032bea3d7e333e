#pragma once
// The Direct3D 12 device, its one direct queue and command list, frame fences, and a per-frame
// upload arena for everything the CPU writes each frame (instances, lines, triangles).

#include "dx_common.h"

#include <cstdint>
#include <vector>

namespace stepwise::render {

/// A piece of upload memory valid for the current frame.
struct UploadSlice {
    void* cpu = nullptr;
    D3D12_GPU_VIRTUAL_ADDRESS gpu = 0;
};

/// Linear allocator over one persistently mapped upload buffer. It grows by replacing the
/// buffer; the old one is kept until the GPU has finished the frame that used it.
class UploadArena {
public:
    void reset();
    UploadSlice allocate(ID3D12Device* device, size_t bytes, size_t alignment = 256);

private:
    void grow(ID3D12Device* device, size_t atLeast);
    Com<ID3D12Resource> buffer_;
    std::vector<Com<ID3D12Resource>> retired_;
    uint8_t* mapped_ = nullptr;
    size_t capacity_ = 0;
    size_t used_ = 0;
};

class Device {
public:
    static constexpr int kFramesInFlight = 2;

    Device();
    ~Device();
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;

    ID3D12Device* device() const { return device_.get(); }
    ID3D12CommandQueue* queue() const { return queue_.get(); }
    IDXGIFactory4* factory() const { return factory_.get(); }
    ID3D12GraphicsCommandList* list() const { return list_.get(); }
    /// Shader-visible heap with one descriptor: Dear ImGui's font texture.
    ID3D12DescriptorHeap* imguiHeap() const { return imguiHeap_.get(); }
    const std::string& adapterName() const { return adapterName_; }

    /// Waits until the GPU is done with this frame slot, then opens the command list.
    void beginFrame();
    /// Closes and submits the command list and fences the frame slot.
    void endFrame();
    void waitIdle();
    UploadArena& upload() { return frames_[frameIndex_].upload; }
    UploadSlice allocate(size_t bytes, size_t alignment = 256) { return upload().allocate(device(), bytes, alignment); }

private:
    struct Frame {
        Com<ID3D12CommandAllocator> allocator;
        uint64_t fenceValue = 0;
        UploadArena upload;
    };
    void waitFor(uint64_t value);

    Com<IDXGIFactory4> factory_;
    Com<ID3D12Device> device_;
    Com<ID3D12CommandQueue> queue_;
    Com<ID3D12GraphicsCommandList> list_;
    Com<ID3D12Fence> fence_;
    Com<ID3D12DescriptorHeap> imguiHeap_;
    HANDLE fenceEvent_ = nullptr;
    Frame frames_[kFramesInFlight];
    int frameIndex_ = 0;
    uint64_t nextFenceValue_ = 1;
    std::string adapterName_;
};

/// A committed buffer or texture resource with a given heap type.
Com<ID3D12Resource> createBuffer(ID3D12Device* device, D3D12_HEAP_TYPE heap, size_t bytes,
                                 D3D12_RESOURCE_STATES state);
void transition(ID3D12GraphicsCommandList* list, ID3D12Resource* resource,
                D3D12_RESOURCE_STATES from, D3D12_RESOURCE_STATES to);

}  // namespace stepwise::render
