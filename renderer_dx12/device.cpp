// Device set-up follows Microsoft's D3D12HelloWorld sample (DirectX-Graphics-Samples), reduced
// to what the demo needs: feature level 11_0 (all that wine's vkd3d and WARP promise), one
// direct queue, and a fence per frame in flight.
#include "device.h"

#include <cstdio>

namespace stepwise::render {

void throwHresult(const char* what, HRESULT result) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "%s failed (HRESULT 0x%08lx)", what, static_cast<unsigned long>(result));
    throw std::runtime_error(buffer);
}

Com<ID3D12Resource> createBuffer(ID3D12Device* device, D3D12_HEAP_TYPE heap, size_t bytes,
                                 D3D12_RESOURCE_STATES state) {
    D3D12_HEAP_PROPERTIES heapProps = {};
    heapProps.Type = heap;
    D3D12_RESOURCE_DESC desc = {};
    desc.Dimension = D3D12_RESOURCE_DIMENSION_BUFFER;
    desc.Width = bytes;
    desc.Height = 1;
    desc.DepthOrArraySize = 1;
    desc.MipLevels = 1;
    desc.SampleDesc.Count = 1;
    desc.Layout = D3D12_TEXTURE_LAYOUT_ROW_MAJOR;
    Com<ID3D12Resource> buffer;
    check(device->CreateCommittedResource(&heapProps, D3D12_HEAP_FLAG_NONE, &desc, state, nullptr,
                                          __uuidof(ID3D12Resource), buffer.putVoid()),
          "CreateCommittedResource(buffer)");
    return buffer;
}

void transition(ID3D12GraphicsCommandList* list, ID3D12Resource* resource,
                D3D12_RESOURCE_STATES from, D3D12_RESOURCE_STATES to) {
    if (from == to) return;
    D3D12_RESOURCE_BARRIER barrier = {};
    barrier.Type = D3D12_RESOURCE_BARRIER_TYPE_TRANSITION;
    barrier.Transition.pResource = resource;
    barrier.Transition.Subresource = D3D12_RESOURCE_BARRIER_ALL_SUBRESOURCES;
    barrier.Transition.StateBefore = from;
    barrier.Transition.StateAfter = to;
    list->ResourceBarrier(1, &barrier);
}

void UploadArena::reset() {
    used_ = 0;
    retired_.clear();
}

void UploadArena::grow(ID3D12Device* device, size_t atLeast) {
    if (buffer_) retired_.push_back(buffer_);
    capacity_ = capacity_ ? capacity_ : size_t(1) << 20;
    while (capacity_ < atLeast) capacity_ *= 2;
    buffer_ = createBuffer(device, D3D12_HEAP_TYPE_UPLOAD, capacity_, D3D12_RESOURCE_STATE_GENERIC_READ);
    D3D12_RANGE nothingRead = {0, 0};
    check(buffer_->Map(0, &nothingRead, reinterpret_cast<void**>(&mapped_)), "Map(upload)");
    used_ = 0;
}

UploadSlice UploadArena::allocate(ID3D12Device* device, size_t bytes, size_t alignment) {
    size_t offset = (used_ + alignment - 1) / alignment * alignment;
    if (!buffer_ || offset + bytes > capacity_) {
        grow(device, 2 * (bytes + alignment));
        offset = 0;
    }
    used_ = offset + bytes;
    return {mapped_ + offset, buffer_->GetGPUVirtualAddress() + offset};
}

Device::Device() {
    check(CreateDXGIFactory1(__uuidof(IDXGIFactory4), factory_.putVoid()), "CreateDXGIFactory1");
    // Debug layer only when asked: it is absent under wine and slows Windows down.
    if (GetEnvironmentVariableA("STEPWISE_D3D12_DEBUG", nullptr, 0) > 0) {
        Com<ID3D12Debug> debug;
        if (SUCCEEDED(D3D12GetDebugInterface(__uuidof(ID3D12Debug), debug.putVoid()))) debug->EnableDebugLayer();
    }
    Com<IDXGIAdapter1> adapter;
    if (SUCCEEDED(factory_->EnumAdapters1(0, adapter.put()))) {
        if (FAILED(D3D12CreateDevice(adapter.get(), D3D_FEATURE_LEVEL_11_0, __uuidof(ID3D12Device), device_.putVoid()))) {
            adapter.reset();
        }
    }
    if (!device_) {
        // No hardware device: WARP, Windows' software rasteriser.
        check(factory_->EnumWarpAdapter(__uuidof(IDXGIAdapter1), adapter.putVoid()), "EnumWarpAdapter");
        check(D3D12CreateDevice(adapter.get(), D3D_FEATURE_LEVEL_11_0, __uuidof(ID3D12Device), device_.putVoid()),
              "D3D12CreateDevice(feature level 11_0)");
    }
    DXGI_ADAPTER_DESC1 adapterDesc = {};
    if (adapter && SUCCEEDED(adapter->GetDesc1(&adapterDesc))) {
        char name[128] = {};
        WideCharToMultiByte(CP_UTF8, 0, adapterDesc.Description, -1, name, sizeof name - 1, nullptr, nullptr);
        adapterName_ = name;
    }

    D3D12_COMMAND_QUEUE_DESC queueDesc = {};
    queueDesc.Type = D3D12_COMMAND_LIST_TYPE_DIRECT;
    check(device_->CreateCommandQueue(&queueDesc, __uuidof(ID3D12CommandQueue), queue_.putVoid()), "CreateCommandQueue");
    for (Frame& frame : frames_) {
        check(device_->CreateCommandAllocator(D3D12_COMMAND_LIST_TYPE_DIRECT, __uuidof(ID3D12CommandAllocator),
                                              frame.allocator.putVoid()),
              "CreateCommandAllocator");
    }
    check(device_->CreateCommandList(0, D3D12_COMMAND_LIST_TYPE_DIRECT, frames_[0].allocator.get(), nullptr,
                                     __uuidof(ID3D12GraphicsCommandList), list_.putVoid()),
          "CreateCommandList");
    check(list_->Close(), "Close(command list)");
    check(device_->CreateFence(0, D3D12_FENCE_FLAG_NONE, __uuidof(ID3D12Fence), fence_.putVoid()), "CreateFence");
    fenceEvent_ = CreateEventA(nullptr, FALSE, FALSE, nullptr);
    if (!fenceEvent_) throw std::runtime_error("CreateEvent failed");

    D3D12_DESCRIPTOR_HEAP_DESC heapDesc = {};
    heapDesc.Type = D3D12_DESCRIPTOR_HEAP_TYPE_CBV_SRV_UAV;
    heapDesc.NumDescriptors = 1;
    heapDesc.Flags = D3D12_DESCRIPTOR_HEAP_FLAG_SHADER_VISIBLE;
    check(device_->CreateDescriptorHeap(&heapDesc, __uuidof(ID3D12DescriptorHeap), imguiHeap_.putVoid()),
          "CreateDescriptorHeap(ImGui)");
}

Device::~Device() {
    if (queue_ && fence_) waitIdle();
    if (fenceEvent_) CloseHandle(fenceEvent_);
}

void Device::waitFor(uint64_t value) {
    if (fence_->GetCompletedValue() >= value) return;
    check(fence_->SetEventOnCompletion(value, fenceEvent_), "SetEventOnCompletion");
    WaitForSingleObject(fenceEvent_, INFINITE);
}

void Device::beginFrame() {
    frameIndex_ = (frameIndex_ + 1) % kFramesInFlight;
    Frame& frame = frames_[frameIndex_];
    waitFor(frame.fenceValue);
    frame.upload.reset();
    check(frame.allocator->Reset(), "Reset(command allocator)");
    check(list_->Reset(frame.allocator.get(), nullptr), "Reset(command list)");
}

void Device::endFrame() {
    check(list_->Close(), "Close(command list)");
    ID3D12CommandList* lists[] = {list_.get()};
    queue_->ExecuteCommandLists(1, lists);
    const uint64_t value = nextFenceValue_++;
    check(queue_->Signal(fence_.get(), value), "Signal");
    frames_[frameIndex_].fenceValue = value;
}

void Device::waitIdle() {
    const uint64_t value = nextFenceValue_++;
    check(queue_->Signal(fence_.get(), value), "Signal");
    waitFor(value);
}

}  // namespace stepwise::render
