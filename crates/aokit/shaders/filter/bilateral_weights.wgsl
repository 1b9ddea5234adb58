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

// With NORMAL_WEIGHT, log2(normal_power) where the power is 2^k for k in 0..=6 (the default 16
// among them), -1 for any other: the facing cosine is then squared k times instead of taking
// its log2 for the exp2. On lavapipe a log2 is a polynomial: GTAO `high`'s frame with the edges
// kind took 0.93 and 0.92 of its time with the squarings on `room` and the atrium at 640x360
// (0.94 and 0.92 with the bilateral kind); on a GPU a log2 is a special-function op, which
// bounds these passes.
override NORMAL_SQUARINGS: i32 = -1;

// The normal weight max(0, n . n0)^normal_power of a neighbour facing `facing` (> 0), as a base-2
// logarithm to add to the exponent and a factor to multiply by: one of them is 0 or 1.
struct NormalWeight {
    log2: f32,
    factor: f32,
}

fn normal_weight(facing: f32) -> NormalWeight {
    if NORMAL_SQUARINGS < 0 {
        return NormalWeight(spatial.normal_power * log2(facing), 1.0);
    }
    var factor = facing;
    for (var i = 0; i < NORMAL_SQUARINGS; i++) {
        factor *= factor;
    }
    return NormalWeight(0.0, factor);
}
