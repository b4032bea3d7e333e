// HLSL kept inside what wine 8's D3DCompile accepts (docs/renderer.md): no user function
// calls, no discard, no [unroll], no structured buffers, no SampleLevel. Lighting is inlined
// in each pixel shader; instancing goes through a second vertex stream.
#include "shaders.h"

#include <cstring>

namespace stepwise::render {

namespace {

const char kShaderSource[] = R"hlsl(
// step() without step(), which wine 8's compiler lacks: 1 when x > edge, else 0.
#define STEP(edge, x) saturate(((x) - (edge)) * 1e20)

cbuffer Frame : register(b0) {
    float4 vpRow0; float4 vpRow1; float4 vpRow2; float4 vpRow3;
    float4 cameraPos;
    float4 lightDir;
    float4 viewport;
};

struct Lit { float4 pos : SV_Position; float3 normal : NORMAL; float3 world : TEXCOORD0; float4 color : COLOR; };
struct Flat { float4 pos : SV_Position; float4 color : COLOR; };

struct MeshIn {
    float3 pos : POSITION; float3 normal : NORMAL;
    float4 row0 : TEXCOORD0; float4 row1 : TEXCOORD1; float4 row2 : TEXCOORD2;
    float4 scale : TEXCOORD3; float4 color : TEXCOORD4;
};
Lit vsMesh(MeshIn v) {
    float3 local = v.pos * v.scale.xyz;
    float4 world = float4(dot(v.row0.xyz, local) + v.row0.w, dot(v.row1.xyz, local) + v.row1.w,
                          dot(v.row2.xyz, local) + v.row2.w, 1.0);
    float3 n = v.normal / max(abs(v.scale.xyz), 1e-6);
    Lit o;
    o.pos = float4(dot(vpRow0, world), dot(vpRow1, world), dot(vpRow2, world), dot(vpRow3, world));
    o.normal = float3(dot(v.row0.xyz, n), dot(v.row1.xyz, n), dot(v.row2.xyz, n));
    o.world = world.xyz;
    o.color = v.color;
    return o;
}

struct TriangleIn { float3 pos : POSITION; float3 normal : NORMAL; float4 color : COLOR; };
Lit vsTriangle(TriangleIn v) {
    float4 world = float4(v.pos, 1.0);
    Lit o;
    o.pos = float4(dot(vpRow0, world), dot(vpRow1, world), dot(vpRow2, world), dot(vpRow3, world));
    o.normal = v.normal;
    o.world = v.pos;
    o.color = v.color;
    return o;
}

float4 psLit(Lit i) : SV_Target {
    float3 n = normalize(i.normal);
    float3 toEye = cameraPos.xyz - i.world;
    n = n * (2.0 * STEP(0.0, dot(n, toEye)) - 1.0);  // two-sided: face the eye
    float diffuse = saturate(dot(n, lightDir.xyz));
    float sky = 0.5 + 0.5 * n.y;
    float3 rgb = i.color.rgb * (0.30 + 0.20 * sky + 0.55 * diffuse);
    return float4(saturate(rgb), i.color.a);
}

struct LineIn {
    float2 corner : TEXCOORD0;
    float3 a : TEXCOORD1; float3 b : TEXCOORD2; float4 color : COLOR; float width : TEXCOORD3;
};
Flat vsLine(LineIn v) {
    float4 pa = float4(v.a, 1.0);
    float4 pb = float4(v.b, 1.0);
    float4 ca = float4(dot(vpRow0, pa), dot(vpRow1, pa), dot(vpRow2, pa), dot(vpRow3, pa));
    float4 cb = float4(dot(vpRow0, pb), dot(vpRow1, pb), dot(vpRow2, pb), dot(vpRow3, pb));
    // Clip each end to the near plane (ternaries and branches are avoided: wine's compiler).
    float nearW = viewport.w;
    float behindA = 1.0 - STEP(nearW, ca.w);
    float behindB = 1.0 - STEP(nearW, cb.w);
    float4 ca2 = lerp(ca, lerp(ca, cb, saturate((nearW - ca.w) / max(cb.w - ca.w, 1e-6))), behindA);
    float4 cb2 = lerp(cb, lerp(cb, ca, saturate((nearW - cb.w) / max(ca.w - cb.w, 1e-6))), behindB);
    float2 halfSize = viewport.xy * 0.5;
    float2 sa = ca2.xy / ca2.w * halfSize;
    float2 sb = cb2.xy / cb2.w * halfSize;
    float2 d = sb - sa;
    float lengthSquared = dot(d, d);
    float2 dir = lerp(float2(1.0, 0.0), normalize(d + float2(1e-7, 0.0)), STEP(1e-8, lengthSquared));
    float2 side = float2(-dir.y, dir.x);
    float width = lerp(viewport.z, v.width, STEP(0.000001, v.width));
    float4 c = lerp(ca2, cb2, STEP(0.5, v.corner.x));
    float2 offset = (side * v.corner.y + dir * (v.corner.x * 2.0 - 1.0)) * (width * 0.5);
    c.xy += offset / halfSize * c.w;
    Flat o;
    o.pos = c;
    o.color = v.color;
    return o;
}

float4 psFlat(Flat i) : SV_Target { return i.color; }
)hlsl";

Com<ID3DBlob> compile(const char* entry, const char* target) {
    Com<ID3DBlob> code;
    Com<ID3DBlob> errors;
    const HRESULT result = D3DCompile(kShaderSource, std::strlen(kShaderSource), "stepwise_shaders.hlsl", nullptr,
                                      nullptr, entry, target, D3DCOMPILE_OPTIMIZATION_LEVEL3, 0, code.put(), errors.put());
    if (FAILED(result)) {
        std::string message = std::string("D3DCompile(") + entry + ") failed";
        if (errors) message += ": " + std::string(static_cast<const char*>(errors->GetBufferPointer()), errors->GetBufferSize());
        throw std::runtime_error(message);
    }
    return code;
}

D3D12_GRAPHICS_PIPELINE_STATE_DESC baseDesc(ID3D12RootSignature* root) {
    D3D12_GRAPHICS_PIPELINE_STATE_DESC desc = {};
    desc.pRootSignature = root;
    D3D12_RENDER_TARGET_BLEND_DESC& blend = desc.BlendState.RenderTarget[0];
    blend.BlendEnable = TRUE;
    blend.SrcBlend = D3D12_BLEND_SRC_ALPHA;
    blend.DestBlend = D3D12_BLEND_INV_SRC_ALPHA;
    blend.BlendOp = D3D12_BLEND_OP_ADD;
    blend.SrcBlendAlpha = D3D12_BLEND_ONE;
    blend.DestBlendAlpha = D3D12_BLEND_INV_SRC_ALPHA;
    blend.BlendOpAlpha = D3D12_BLEND_OP_ADD;
    blend.LogicOp = D3D12_LOGIC_OP_NOOP;
    blend.RenderTargetWriteMask = D3D12_COLOR_WRITE_ENABLE_ALL;
    desc.SampleMask = UINT_MAX;
    desc.RasterizerState.FillMode = D3D12_FILL_MODE_SOLID;
    desc.RasterizerState.CullMode = D3D12_CULL_MODE_NONE;  // hull and triangle winding is not trusted
    desc.RasterizerState.DepthClipEnable = TRUE;
    desc.DepthStencilState.DepthEnable = TRUE;
    desc.DepthStencilState.DepthWriteMask = D3D12_DEPTH_WRITE_MASK_ALL;
    desc.DepthStencilState.DepthFunc = D3D12_COMPARISON_FUNC_LESS_EQUAL;
    desc.PrimitiveTopologyType = D3D12_PRIMITIVE_TOPOLOGY_TYPE_TRIANGLE;
    desc.NumRenderTargets = 1;
    desc.RTVFormats[0] = DXGI_FORMAT_R8G8B8A8_UNORM;
    desc.DSVFormat = DXGI_FORMAT_D32_FLOAT;
    desc.SampleDesc.Count = 1;
    return desc;
}

D3D12_INPUT_ELEMENT_DESC element(const char* semantic, UINT index, DXGI_FORMAT format, UINT slot, UINT offset,
                                 bool perInstance) {
    return {semantic, index, format, slot, offset,
            perInstance ? D3D12_INPUT_CLASSIFICATION_PER_INSTANCE_DATA : D3D12_INPUT_CLASSIFICATION_PER_VERTEX_DATA,
            perInstance ? 1u : 0u};
}

Com<ID3D12PipelineState> create(ID3D12Device* device, D3D12_GRAPHICS_PIPELINE_STATE_DESC desc, const char* vs,
                                const char* ps, const D3D12_INPUT_ELEMENT_DESC* elements, UINT count) {
    Com<ID3DBlob> vertexShader = compile(vs, "vs_5_0");
    Com<ID3DBlob> pixelShader = compile(ps, "ps_5_0");
    desc.VS = {vertexShader->GetBufferPointer(), vertexShader->GetBufferSize()};
    desc.PS = {pixelShader->GetBufferPointer(), pixelShader->GetBufferSize()};
    desc.InputLayout = {elements, count};
    Com<ID3D12PipelineState> state;
    check(device->CreateGraphicsPipelineState(&desc, __uuidof(ID3D12PipelineState), state.putVoid()),
          "CreateGraphicsPipelineState");
    return state;
}

}  // namespace

Pipelines::Pipelines(ID3D12Device* device) {
    D3D12_ROOT_PARAMETER constants = {};
    constants.ParameterType = D3D12_ROOT_PARAMETER_TYPE_32BIT_CONSTANTS;
    constants.Constants.ShaderRegister = 0;
    constants.Constants.Num32BitValues = sizeof(FrameConstants) / 4;
    constants.ShaderVisibility = D3D12_SHADER_VISIBILITY_ALL;
    D3D12_ROOT_SIGNATURE_DESC rootDesc = {};
    rootDesc.NumParameters = 1;
    rootDesc.pParameters = &constants;
    rootDesc.Flags = D3D12_ROOT_SIGNATURE_FLAG_ALLOW_INPUT_ASSEMBLER_INPUT_LAYOUT;
    Com<ID3DBlob> blob;
    Com<ID3DBlob> errors;
    check(D3D12SerializeRootSignature(&rootDesc, D3D_ROOT_SIGNATURE_VERSION_1, blob.put(), errors.put()),
          "D3D12SerializeRootSignature");
    check(device->CreateRootSignature(0, blob->GetBufferPointer(), blob->GetBufferSize(), __uuidof(ID3D12RootSignature),
                                      rootSignature_.putVoid()),
          "CreateRootSignature");

    const DXGI_FORMAT f2 = DXGI_FORMAT_R32G32_FLOAT, f3 = DXGI_FORMAT_R32G32B32_FLOAT, f4 = DXGI_FORMAT_R32G32B32A32_FLOAT;
    const D3D12_INPUT_ELEMENT_DESC meshLayout[] = {
        element("POSITION", 0, f3, 0, 0, false),  element("NORMAL", 0, f3, 0, 12, false),
        element("TEXCOORD", 0, f4, 1, 0, true),   element("TEXCOORD", 1, f4, 1, 16, true),
        element("TEXCOORD", 2, f4, 1, 32, true),  element("TEXCOORD", 3, f4, 1, 48, true),
        element("TEXCOORD", 4, f4, 1, 64, true)};
    mesh_ = create(device, baseDesc(rootSignature_.get()), "vsMesh", "psLit", meshLayout, 7);

    const D3D12_INPUT_ELEMENT_DESC triangleLayout[] = {element("POSITION", 0, f3, 0, 0, false),
                                                       element("NORMAL", 0, f3, 0, 12, false),
                                                       element("COLOR", 0, f4, 0, 24, false)};
    triangles_ = create(device, baseDesc(rootSignature_.get()), "vsTriangle", "psLit", triangleLayout, 3);

    const D3D12_INPUT_ELEMENT_DESC lineLayout[] = {
        element("TEXCOORD", 0, f2, 0, 0, false), element("TEXCOORD", 1, f3, 1, 0, true),
        element("TEXCOORD", 2, f3, 1, 12, true), element("COLOR", 0, f4, 1, 24, true),
        element("TEXCOORD", 3, DXGI_FORMAT_R32_FLOAT, 1, 40, true)};
    lines_ = create(device, baseDesc(rootSignature_.get()), "vsLine", "psFlat", lineLayout, 5);
}

}  // namespace stepwise::render
