// aokit's stand-in for XeGTAO.hlsli, for the peer harness's tests (see XeGTAO.h here). Each
// pass computes something the tests can check exactly:
// - the prefilter writes view depth, `mul / (add - depth)`, to MIP 0, and to MIP k the depth of
//   each block's top-left pixel;
// - the main pass writes how squarely the normal faces the camera, -z in a view space that
//   looks down +z, as the AO term (scaled by 1 / XE_GTAO_OCCLUSION_TERM_SCALE, 8 bits);
// - the denoiser averages each pixel's 3x3 neighbourhood when on (blur beta below 100), copies
//   when off, and the last pass scales by XE_GTAO_OCCLUSION_TERM_SCALE.

typedef float lpfloat;
typedef float2 lpfloat2;
typedef float3 lpfloat3;
typedef float4 lpfloat4;

float StandInViewDepth(float depth, const GTAOConstants consts)
{
    return clamp(consts.DepthUnpackConsts.x / (consts.DepthUnpackConsts.y - depth), 0.0, 65504.0);
}

void XeGTAO_PrefilterDepths16x16(uint2 dispatchThreadID, uint2 groupThreadID,
    const GTAOConstants consts, Texture2D<float> sourceNDCDepth, SamplerState depthSampler,
    RWTexture2D<lpfloat> outDepth0, RWTexture2D<lpfloat> outDepth1, RWTexture2D<lpfloat> outDepth2,
    RWTexture2D<lpfloat> outDepth3, RWTexture2D<lpfloat> outDepth4)
{
    uint2 base = dispatchThreadID * 2;
    for (uint i = 0; i < 4; i++)
    {
        uint2 p = base + uint2(i % 2, i / 2);
        outDepth0[p] = StandInViewDepth(sourceNDCDepth.Load(int3(p, 0)).x, consts);
    }
    float corner = StandInViewDepth(sourceNDCDepth.Load(int3(base, 0)).x, consts);
    outDepth1[dispatchThreadID] = corner;
    if (all(dispatchThreadID % 2 == 0)) outDepth2[dispatchThreadID / 2] = corner;
    if (all(dispatchThreadID % 4 == 0)) outDepth3[dispatchThreadID / 4] = corner;
    if (all(dispatchThreadID % 8 == 0)) outDepth4[dispatchThreadID / 8] = corner;
}

void XeGTAO_MainPass(const uint2 pixCoord, lpfloat sliceCount, lpfloat stepsPerSlice,
    const lpfloat2 localNoise, lpfloat3 viewspaceNormal, const GTAOConstants consts,
    Texture2D<lpfloat> sourceViewspaceDepth, SamplerState depthSampler,
    RWTexture2D<uint> outWorkingAOTerm, RWTexture2D<unorm float> outWorkingEdges)
{
    float visibility = saturate(-viewspaceNormal.z);
    float term = saturate(visibility / XE_GTAO_OCCLUSION_TERM_SCALE);
    outWorkingAOTerm[pixCoord] = uint(term * 255.0 + 0.5);
    outWorkingEdges[pixCoord] = 1.0;
}

void XeGTAO_Denoise(const uint2 pixCoordBase, const GTAOConstants consts,
    Texture2D<uint> sourceAOTerm, Texture2D<lpfloat> sourceEdges, SamplerState texSampler,
    RWTexture2D<uint> outputTexture, const uniform bool finalApply)
{
    int2 last = consts.ViewportSize - 1;
    for (int side = 0; side < 2; side++)
    {
        int2 pixel = int2(pixCoordBase) + int2(side, 0);
        float sum = 0.0;
        float count = 0.0;
        int reach = consts.DenoiseBlurBeta < 100.0 ? 1 : 0;
        for (int y = -reach; y <= reach; y++)
        {
            for (int x = -reach; x <= reach; x++)
            {
                sum += float(sourceAOTerm.Load(int3(clamp(pixel + int2(x, y), 0, last), 0)).x);
                count += 1.0;
            }
        }
        float scale = finalApply ? XE_GTAO_OCCLUSION_TERM_SCALE : 1.0;
        outputTexture[pixel] = uint(sum / count * scale + 0.5);
    }
}
