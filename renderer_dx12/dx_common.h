#pragma once
// Windows / Direct3D 12 headers for the demo shell, portable between MSVC and mingw-w64.
// mingw-w64 10's d3d12.h lacks PFN_D3D12_SERIALIZE_ROOT_SIGNATURE, which Dear ImGui's DX12
// backend uses; it is supplied here (CMake force-includes this header into the backend).

#ifndef NOMINMAX
#define NOMINMAX
#endif
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#include <windows.h>
#include <d3d12.h>
#include <d3d12sdklayers.h>
#include <d3dcompiler.h>
#include <dxgi1_4.h>

#include <stdexcept>
#include <string>

#if defined(__MINGW32__) && !defined(D3D12_SERIALIZE_ROOT_SIGNATURE_DEFINED)
#define D3D12_SERIALIZE_ROOT_SIGNATURE_DEFINED
typedef HRESULT(WINAPI* PFN_D3D12_SERIALIZE_ROOT_SIGNATURE)(const D3D12_ROOT_SIGNATURE_DESC* desc,
                                                             D3D_ROOT_SIGNATURE_VERSION version,
                                                             ID3DBlob** blob, ID3DBlob** errorBlob);
#endif

#ifdef __cplusplus
namespace stepwise::render {

/// The COM pointer the renderer uses (a tiny WRL::ComPtr: mingw and MSVC agree on it).
template <class T>
class Com {
public:
    Com() = default;
    ~Com() { reset(); }
    Com(const Com& other) : ptr_(other.ptr_) { if (ptr_) ptr_->AddRef(); }
    Com& operator=(const Com& other) {
        if (other.ptr_) other.ptr_->AddRef();
        reset();
        ptr_ = other.ptr_;
        return *this;
    }
    void reset() {
        if (ptr_) ptr_->Release();
        ptr_ = nullptr;
    }
    T* get() const { return ptr_; }
    T* operator->() const { return ptr_; }
    explicit operator bool() const { return ptr_ != nullptr; }
    /// For out-parameters: releases what was held.
    T** put() {
        reset();
        return &ptr_;
    }
    void** putVoid() { return reinterpret_cast<void**>(put()); }

private:
    T* ptr_ = nullptr;
};

/// Every failed Direct3D call ends up here: the call, and the HRESULT in hex.
[[noreturn]] void throwHresult(const char* what, HRESULT result);

inline void check(HRESULT result, const char* what) {
    if (FAILED(result)) throwHresult(what, result);
}

}  // namespace stepwise::render
#endif
