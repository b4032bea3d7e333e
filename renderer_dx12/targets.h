#pragma once
// Where a frame is drawn: the window's swap chain, or an offscreen texture that is read back
// and written as a PNG (the --screenshot path the Linux CI runs under wine).

#include "device.h"

#include <string>

namespace stepwise::render {

constexpr DXGI_FORMAT kColorFormat = DXGI_FORMAT_R8G8B8A8_UNORM;
constexpr DXGI_FORMAT kDepthFormat = DXGI_FORMAT_D32_FLOAT;
/// The background every target is cleared to (RGBA).
const float* clearColor();

/// What the draw code needs to know about the current target.
struct TargetView {
    ID3D12Resource* color = nullptr;
    D3D12_CPU_DESCRIPTOR_HANDLE rtv = {};
    D3D12_CPU_DESCRIPTOR_HANDLE dsv = {};
    D3D12_RESOURCE_STATES idleState = D3D12_RESOURCE_STATE_PRESENT;  // state between frames
    int width = 0;
    int height = 0;
};

/// A colour texture (or swap-chain buffers) plus one depth buffer with their descriptor heaps.
class TargetBase {
protected:
    void createHeaps(ID3D12Device* device, int colorCount);
    void createDepth(ID3D12Device* device, int width, int height);
    D3D12_CPU_DESCRIPTOR_HANDLE rtvHandle(ID3D12Device* device, int index) const;

    Com<ID3D12DescriptorHeap> rtvHeap_;
    Com<ID3D12DescriptorHeap> dsvHeap_;
    Com<ID3D12Resource> depth_;
};

class SwapChainTarget : public TargetBase {
public:
    static constexpr int kBufferCount = Device::kFramesInFlight;
    SwapChainTarget(Device& device, HWND window, int width, int height);
    /// Recreates the buffers for a new client size (waits for the GPU first).
    void resize(int width, int height);
    TargetView current() const;
    void present(bool vsync);
    int width() const { return width_; }
    int height() const { return height_; }

private:
    void createBuffers();
    Device& device_;
    Com<IDXGISwapChain3> swapChain_;
    Com<ID3D12Resource> buffers_[kBufferCount];
    int width_ = 0;
    int height_ = 0;
};

class OffscreenTarget : public TargetBase {
public:
    OffscreenTarget(Device& device, int width, int height);
    TargetView view() const;
    /// Records the copy of the finished image into the readback buffer.
    void recordReadback(ID3D12GraphicsCommandList* list);
    /// After the GPU finished: writes the read-back image as an RGB PNG. Throws on failure.
    void savePng(const std::string& path) const;
    /// After the GPU finished: the RGBA pixel at (x, y).
    uint32_t pixel(int x, int y) const;

private:
    Device& device_;
    Com<ID3D12Resource> color_;
    Com<ID3D12Resource> readback_;
    D3D12_PLACED_SUBRESOURCE_FOOTPRINT footprint_ = {};
    int width_ = 0;
    int height_ = 0;
};

}  // namespace stepwise::render
