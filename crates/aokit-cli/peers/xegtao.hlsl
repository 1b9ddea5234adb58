// aokit's wrapper around XeGTAO (Intel; MIT licence; https://github.com/GameTechDev/XeGTAO),
// compiled at run time against the user's own XeGTAO.h and XeGTAO.hlsli by glslangValidator
// (docs/peers.md). It holds what an integration supplies: resource bindings, thread groups and
// entry points, and the engine hooks, which read aokit's G-buffer.
//
// Defines from the harness (src/peer/compile.rs):
//   AOKIT_SLICES, AOKIT_STEPS  slices and steps per side of the main pass (its quality level);
//                              main_pass exists only with them.

// XeGTAO.hlsli takes its saturate from the engine's shared header, and its 16-bit 3x3 matrix
// type (only in the bent-normal path, which aokit leaves off) is one glslang lacks.
#define VA_SATURATE saturate
#define min16float3x3 float3x3

#include "XeGTAO.h"

// Each entry point's bindings run from 0 without gaps (the table in Rust is src/peer/gpu.rs,
// `binding`): wgpu's Vulkan backend numbers a layout's bindings by their rank, and SPIR-V
// passed through to the driver keeps its own numbers, so the two must agree.
[[vk::binding(0, 0)]] cbuffer AokitGtaoConstants
{
    GTAOConstants g_consts;
};
[[vk::binding(1, 0)]] SamplerState g_point_clamp;

#include "XeGTAO.hlsli"

// Prefilter: the renderer's depth buffer in, five MIPs of view depth out.
[[vk::binding(2, 0)]] Texture2D<float> g_raw_depth;
[[vk::binding(3, 0)]] [[spv::format_r16f]] RWTexture2D<lpfloat> g_depth_mip0;
[[vk::binding(4, 0)]] [[spv::format_r16f]] RWTexture2D<lpfloat> g_depth_mip1;
[[vk::binding(5, 0)]] [[spv::format_r16f]] RWTexture2D<lpfloat> g_depth_mip2;
[[vk::binding(6, 0)]] [[spv::format_r16f]] RWTexture2D<lpfloat> g_depth_mip3;
[[vk::binding(7, 0)]] [[spv::format_r16f]] RWTexture2D<lpfloat> g_depth_mip4;

// Main pass: view depth and aokit's normals in, the AO term and the denoiser's edges out.
[[vk::binding(2, 0)]] Texture2D<lpfloat> g_view_depth;
[[vk::binding(3, 0)]] Texture2D<uint> g_normals;
[[vk::binding(4, 0)]] [[spv::format_r8ui]] RWTexture2D<uint> g_ao_term_out;
[[vk::binding(5, 0)]] [[spv::format_r8]] RWTexture2D<unorm float> g_edges_out;

// Denoiser: the AO term and edges in; a working term out, or the final term from the last pass.
// The final term is R32Uint: the last pass scales by XE_GTAO_OCCLUSION_TERM_SCALE and stores
// up to 1.5 * 255, which Direct3D clamps on the way into an 8-bit integer texel but Vulkan leaves
// undefined; the harness clamps when it reads the value back.
[[vk::binding(2, 0)]] Texture2D<uint> g_ao_term;
[[vk::binding(3, 0)]] Texture2D<lpfloat> g_edges;
[[vk::binding(4, 0)]] [[spv::format_r8ui]] RWTexture2D<uint> g_ao_term_pong;
[[vk::binding(4, 0)]] [[spv::format_r32ui]] RWTexture2D<uint> g_ao_final;

// aokit's G-buffer normal: octahedral, two 16-bit unorms in one uint, x in the low half (Meyer
// et al. 2010, "On floating-point normal vectors"), in a right-handed view space looking down -z.
// XeGTAO's view space looks down +z with y up: z changes sign.
lpfloat3 LoadNormal(int2 pixel)
{
    uint bits = g_normals.Load(int3(pixel, 0)).x;
    float2 e = float2(bits & 0xffffu, bits >> 16) / 65535.0 * 2.0 - 1.0;
    float z = 1.0 - abs(e.x) - abs(e.y);
    float2 folded = (1.0 - abs(e.yx)) * (e >= 0.0 ? 1.0 : -1.0);
    float3 n = normalize(float3(z >= 0.0 ? e : folded, z));
    return lpfloat3(n.x, n.y, -n.z);
}

// XeGTAO's noise: the R2 sequence (Roberts 2018, "The unreasonable effectiveness of quasirandom
// sequences") indexed along a 64x64 Hilbert curve, offset by 288 per frame of a temporal
// accumulation; aokit passes frame 0, as an integration without TAA does.
lpfloat2 SpatioTemporalNoise(uint2 pixel, uint frame)
{
    uint index = HilbertIndex(pixel.x % 64u, pixel.y % 64u) + 288u * (frame % 64u);
    return lpfloat2(frac(0.5 + index * float2(0.75487766624669276005, 0.5698402909980532659114)));
}

// Each thread filters a 2x2 block: dispatch ceil(size / 16) groups.
[numthreads(8, 8, 1)]
void prefilter(uint2 id : SV_DispatchThreadID, uint2 local_id : SV_GroupThreadID)
{
    XeGTAO_PrefilterDepths16x16(id, local_id, g_consts, g_raw_depth, g_point_clamp, g_depth_mip0,
        g_depth_mip1, g_depth_mip2, g_depth_mip3, g_depth_mip4);
}

// Compiled once per quality level, with its slices and steps.
#ifdef AOKIT_SLICES
[numthreads(XE_GTAO_NUMTHREADS_X, XE_GTAO_NUMTHREADS_Y, 1)]
void main_pass(uint2 pixel : SV_DispatchThreadID)
{
    XeGTAO_MainPass(pixel, AOKIT_SLICES, AOKIT_STEPS,
        SpatioTemporalNoise(pixel, g_consts.NoiseIndex), LoadNormal(pixel), g_consts, g_view_depth,
        g_point_clamp, g_ao_term_out, g_edges_out);
}
#endif

// Each thread filters two horizontal neighbours: dispatch ceil(width / 16) x ceil(height / 8).
[numthreads(XE_GTAO_NUMTHREADS_X, XE_GTAO_NUMTHREADS_Y, 1)]
void denoise(uint2 id : SV_DispatchThreadID)
{
    XeGTAO_Denoise(id * uint2(2, 1), g_consts, g_ao_term, g_edges, g_point_clamp, g_ao_term_pong,
        false);
}

[numthreads(XE_GTAO_NUMTHREADS_X, XE_GTAO_NUMTHREADS_Y, 1)]
void denoise_last(uint2 id : SV_DispatchThreadID)
{
    XeGTAO_Denoise(id * uint2(2, 1), g_consts, g_ao_term, g_edges, g_point_clamp, g_ao_final, true);
}
