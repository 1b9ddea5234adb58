// The bilateral weights' settings, shared by the spatial filter's bilateral kind
// (spatial_filter.wgsl) and its edges kind (edge_filter.wgsl): the settings buffer (mirrors
// `SpatialUniforms` in uniforms.rs) and the code paths fixed per pipeline.

struct SpatialUniforms {
    // 1 / sigma: pixel offsets times this are in units of the spatial standard deviation.
    spatial_scale: f32,
    // 1 / depth_sigma: relative depth differences times this are in units of depth_sigma.
    depth_scale: f32,
    // Exponent of the normal weight (> 0 where NORMAL_WEIGHT).
    normal_power: f32,
}

@group(0) @binding(1) var<uniform> spatial: SpatialUniforms;

// `DepthWeight as u32` in Rust (a test compares them).
const DEPTH_GAUSSIAN: u32 = 0u;
const DEPTH_THRESHOLD: u32 = 1u;

// The choices of code path, fixed per pipeline (why: resample.wgsl's header; lavapipe compiled
// the bilateral passes afresh every frame while they were uniforms).
// DEPTH_GAUSSIAN or DEPTH_THRESHOLD.
override DEPTH_WEIGHT: u32;
// Whether normals weigh in (normal_power > 0); without it no normal is loaded.
override NORMAL_WEIGHT: bool;

// log2(e): each factor of the weight is a power of e or of the facing cosine, so their base-2
// logarithms add up and one exp2 gives the weight.
const LOG2_E: f32 = 1.44269504;
