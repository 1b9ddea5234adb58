// aokit's stand-in for XeGTAO.h, for the peer harness's tests: the types, defines and function
// that aokit's wrapper (peers/xegtao.hlsl) uses, with the real header's constant buffer layout,
// and simple bodies of aokit's own whose results the tests check. Not XeGTAO.

#define XE_GTAO_NUMTHREADS_X 8
#define XE_GTAO_NUMTHREADS_Y 8
#define XE_GTAO_OCCLUSION_TERM_SCALE 1.5

struct GTAOConstants
{
    int2 ViewportSize;
    float2 ViewportPixelSize;
    float2 DepthUnpackConsts;
    float2 CameraTanHalfFOV;
    float2 NDCToViewMul;
    float2 NDCToViewAdd;
    float2 NDCToViewMul_x_PixelSize;
    float EffectRadius;
    float EffectFalloffRange;
    float RadiusMultiplier;
    float Padding0;
    float FinalValuePower;
    float DenoiseBlurBeta;
    float SampleDistributionPower;
    float ThinOccluderCompensation;
    float DepthMIPSamplingOffset;
    int NoiseIndex;
};

// Row-major order in a 64x64 tile: any index does for the tests.
uint HilbertIndex(uint x, uint y)
{
    return x + 64u * y;
}
