// Swap chain and offscreen targets. The swap chain is a flip-model chain (required by D3D12)
// with one buffer per frame in flight; the offscreen path copies the image into a readback
// buffer with the row pitch D3D12 requires (256-byte aligned rows) and writes it with
// stb_image_write.
#include "targets.h"

#include <stb_image_write.h>

#include <cstring>
#include <vector>

namespace stepwise::render {

namespace {
constexpr float kClearColor[4] = {0.16f, 0.18f, 0.21f, 1.0f};
}

const float* clearColor() { return kClearColor; }

void TargetBase::createHeaps(ID3D12Device* device, int colorCount) {
    D3D12_DESCRIPTOR_HEAP_DESC rtvDesc = {};
    rtvDesc.Type = D3D12_DESCRIPTOR_HEAP_TYPE_RTV;
    rtvDesc.NumDescriptors = static_cast<UINT>(colorCount);
    check(device->CreateDescriptorHeap(&rtvDesc, __uuidof(ID3D12DescriptorHeap), rtvHeap_.putVoid()), "CreateDescriptorHeap(RTV)");
    D3D12_DESCRIPTOR_HEAP_DESC dsvDesc = {};
    dsvDesc.Type = D3D12_DESCRIPTOR_HEAP_TYPE_DSV;
    dsvDesc.NumDescriptors = 1;
    check(device->CreateDescriptorHeap(&dsvDesc, __uuidof(ID3D12DescriptorHeap), dsvHeap_.putVoid()), "CreateDescriptorHeap(DSV)");
}

D3D12_CPU_DESCRIPTOR_HANDLE TargetBase::rtvHandle(ID3D12Device* device, int index) const {
    D3D12_CPU_DESCRIPTOR_HANDLE handle = rtvHeap_->GetCPUDescriptorHandleForHeapStart();
    handle.ptr += static_cast<SIZE_T>(index) * device->GetDescriptorHandleIncrementSize(D3D12_DESCRIPTOR_HEAP_TYPE_RTV);
    return handle;
}

// One 2D texture in GPU memory: the depth buffer and the offscreen colour target differ only
// in format and usage.
static D3D12_HEAP_PROPERTIES defaultHeap() {
    D3D12_HEAP_PROPERTIES heap = {};
    heap.Type = D3D12_HEAP_TYPE_DEFAULT;
    return heap;
}

static D3D12_RESOURCE_DESC texture2DDesc(int width, int height, DXGI_FORMAT format, D3D12_RESOURCE_FLAGS flags) {
    D3D12_RESOURCE_DESC desc = {};
    desc.Dimension = D3D12_RESOURCE_DIMENSION_TEXTURE2D;
    desc.Width = static_cast<UINT64>(width);
    desc.Height = static_cast<UINT>(height);
    desc.DepthOrArraySize = 1;
    desc.MipLevels = 1;
    desc.Format = format;
    desc.SampleDesc.Count = 1;
    desc.Flags = flags;
    return desc;
}

void TargetBase::createDepth(ID3D12Device* device, int width, int height) {
    depth_.reset();
    const D3D12_HEAP_PROPERTIES heap = defaultHeap();
    const D3D12_RESOURCE_DESC desc =
        texture2DDesc(width, height, kDepthFormat, D3D12_RESOURCE_FLAG_ALLOW_DEPTH_STENCIL);
    D3D12_CLEAR_VALUE clear = {};
    clear.Format = kDepthFormat;
    clear.DepthStencil.Depth = 1.0f;
    check(device->CreateCommittedResource(&heap, D3D12_HEAP_FLAG_NONE, &desc, D3D12_RESOURCE_STATE_DEPTH_WRITE, &clear,
                                          __uuidof(ID3D12Resource), depth_.putVoid()),
          "CreateCommittedResource(depth)");
    device->CreateDepthStencilView(depth_.get(), nullptr, dsvHeap_->GetCPUDescriptorHandleForHeapStart());
}

SwapChainTarget::SwapChainTarget(Device& device, HWND window, int width, int height)
    : device_(device), width_(width > 0 ? width : 1), height_(height > 0 ? height : 1) {
    createHeaps(device.device(), kBufferCount);
    DXGI_SWAP_CHAIN_DESC1 desc = {};
    desc.Width = static_cast<UINT>(width_);
    desc.Height = static_cast<UINT>(height_);
    desc.Format = kColorFormat;
    desc.SampleDesc.Count = 1;
    desc.BufferUsage = DXGI_USAGE_RENDER_TARGET_OUTPUT;
    desc.BufferCount = kBufferCount;
    desc.SwapEffect = DXGI_SWAP_EFFECT_FLIP_DISCARD;
    Com<IDXGISwapChain1> chain;
    check(device.factory()->CreateSwapChainForHwnd(device.queue(), window, &desc, nullptr, nullptr, chain.put()),
          "CreateSwapChainForHwnd");
    check(chain->QueryInterface(__uuidof(IDXGISwapChain3), swapChain_.putVoid()), "QueryInterface(IDXGISwapChain3)");
    device.factory()->MakeWindowAssociation(window, DXGI_MWA_NO_ALT_ENTER);
    createBuffers();
}

void SwapChainTarget::createBuffers() {
    for (int i = 0; i < kBufferCount; ++i) {
        check(swapChain_->GetBuffer(static_cast<UINT>(i), __uuidof(ID3D12Resource), buffers_[i].putVoid()), "GetBuffer");
        device_.device()->CreateRenderTargetView(buffers_[i].get(), nullptr, rtvHandle(device_.device(), i));
    }
    createDepth(device_.device(), width_, height_);
}

void SwapChainTarget::resize(int width, int height) {
    if (width <= 0 || height <= 0 || (width == width_ && height == height_)) return;  // minimised: keep
    device_.waitIdle();
    for (auto& buffer : buffers_) buffer.reset();
    width_ = width;
    height_ = height;
    check(swapChain_->ResizeBuffers(kBufferCount, static_cast<UINT>(width), static_cast<UINT>(height), kColorFormat, 0),
          "ResizeBuffers");
    createBuffers();
}

TargetView SwapChainTarget::current() const {
    const int index = static_cast<int>(swapChain_->GetCurrentBackBufferIndex());
    return {buffers_[index].get(), rtvHandle(device_.device(), index), dsvHeap_->GetCPUDescriptorHandleForHeapStart(),
            D3D12_RESOURCE_STATE_PRESENT, width_, height_};
}

void SwapChainTarget::present(bool vsync) { check(swapChain_->Present(vsync ? 1 : 0, 0), "Present"); }

OffscreenTarget::OffscreenTarget(Device& device, int width, int height)
    : device_(device), width_(width), height_(height) {
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384) {
        throw std::runtime_error("offscreen size must be between 1x1 and 16384x16384");
    }
    ID3D12Device* d3d = device.device();
    createHeaps(d3d, 1);
    const D3D12_HEAP_PROPERTIES heap = defaultHeap();
    const D3D12_RESOURCE_DESC desc =
        texture2DDesc(width, height, kColorFormat, D3D12_RESOURCE_FLAG_ALLOW_RENDER_TARGET);
    D3D12_CLEAR_VALUE clear = {};
    clear.Format = kColorFormat;
    for (int i = 0; i < 4; ++i) clear.Color[i] = kClearColor[i];
    check(d3d->CreateCommittedResource(&heap, D3D12_HEAP_FLAG_NONE, &desc, D3D12_RESOURCE_STATE_COPY_SOURCE, &clear,
                                       __uuidof(ID3D12Resource), color_.putVoid()),
          "CreateCommittedResource(offscreen colour)");
    d3d->CreateRenderTargetView(color_.get(), nullptr, rtvHandle(d3d, 0));
    createDepth(d3d, width, height);
    UINT64 total = 0;
    d3d->GetCopyableFootprints(&desc, 0, 1, 0, &footprint_, nullptr, nullptr, &total);
    readback_ = createBuffer(d3d, D3D12_HEAP_TYPE_READBACK, static_cast<size_t>(total), D3D12_RESOURCE_STATE_COPY_DEST);
}

TargetView OffscreenTarget::view() const {
    return {color_.get(), rtvHandle(device_.device(), 0), dsvHeap_->GetCPUDescriptorHandleForHeapStart(),
            D3D12_RESOURCE_STATE_COPY_SOURCE, width_, height_};
}

void OffscreenTarget::recordReadback(ID3D12GraphicsCommandList* list) {
    D3D12_TEXTURE_COPY_LOCATION source = {};
    source.pResource = color_.get();
    source.Type = D3D12_TEXTURE_COPY_TYPE_SUBRESOURCE_INDEX;
    source.SubresourceIndex = 0;
    D3D12_TEXTURE_COPY_LOCATION destination = {};
    destination.pResource = readback_.get();
    destination.Type = D3D12_TEXTURE_COPY_TYPE_PLACED_FOOTPRINT;
    destination.PlacedFootprint = footprint_;
    list->CopyTextureRegion(&destination, 0, 0, 0, &source, nullptr);
}

uint32_t OffscreenTarget::pixel(int x, int y) const {
    D3D12_RANGE range = {0, static_cast<SIZE_T>(footprint_.Footprint.RowPitch) * static_cast<SIZE_T>(height_)};
    uint8_t* data = nullptr;
    check(readback_->Map(0, &range, reinterpret_cast<void**>(&data)), "Map(readback)");
    uint32_t value = 0;
    std::memcpy(&value, data + static_cast<size_t>(y) * footprint_.Footprint.RowPitch + static_cast<size_t>(x) * 4, 4);
    D3D12_RANGE nothingWritten = {0, 0};
    readback_->Unmap(0, &nothingWritten);
    return value;
}

void OffscreenTarget::savePng(const std::string& path) const {
    const size_t pitch = footprint_.Footprint.RowPitch;
    D3D12_RANGE range = {0, static_cast<SIZE_T>(pitch) * static_cast<SIZE_T>(height_)};
    uint8_t* data = nullptr;
    check(readback_->Map(0, &range, reinterpret_cast<void**>(&data)), "Map(readback)");
    // RGB without alpha: the image is opaque and PNGs of it stay smaller.
    std::vector<uint8_t> rgb(static_cast<size_t>(width_) * static_cast<size_t>(height_) * 3);
    for (int y = 0; y < height_; ++y) {
        const uint8_t* row = data + static_cast<size_t>(y) * pitch;
        for (int x = 0; x < width_; ++x) {
            for (int c = 0; c < 3; ++c) rgb[(static_cast<size_t>(y) * width_ + x) * 3 + c] = row[x * 4 + c];
        }
    }
    D3D12_RANGE nothingWritten = {0, 0};
    readback_->Unmap(0, &nothingWritten);
    if (!stbi_write_png(path.c_str(), width_, height_, 3, rgb.data(), width_ * 3)) {
        throw std::runtime_error("cannot write PNG '" + path + "'");
    }
}

}  // namespace stepwise::render
