// requires: common/view.wgsl, filter/guided_filter.wgsl
// requires: common/formats/pair_rg32float.wgsl | common/formats/pair_rgba32float.wgsl
// First pass of the guided filter (guided_filter.wgsl): from the method's AO and the linear
// depth to each window's line, its slope a_k and its value c_k at the window's centre.

@group(0) @binding(2) var ao_in: texture_2d<f32>;
@group(0) @binding(4) var coefficients_out: pair_storage;

// The AO, staged beside the log depth.
fn load_values(pixel: vec2<i32>) -> vec2<f32> {
    return vec2<f32>(textureLoad(ao_in, pixel, 0).r, 0.0);
}

@compute @workgroup_size(GROUP, GROUP)
fn main(
    @builtin(global_invocation_id) id: vec3<u32>,
    @builtin(workgroup_id) group: vec3<u32>,
    @builtin(local_invocation_id) local: vec3<u32>,
    @builtin(local_invocation_index) index: u32,
) {
    stage_tile(group.xy, index);
    if any(id.xy >= vec2<u32>(view.size)) {
        return;
    }
    let radius = RADIUS;
    let centre = tile[tile_index(local.xy, vec2<u32>(radius))];
    if centre.x == 0.0 {
        // No window here: the output pass skips it.
        textureStore(coefficients_out, id.xy, vec4<f32>(0.0));
        return;
    }
    // Sums over the window's surface pixels of 1, g = ln(d / d_k), g^2, p and g p.
    var count = 0.0;
    var sum_g = 0.0;
    var sum_gg = 0.0;
    var sum_p = 0.0;
    var sum_gp = 0.0;
    for (var y = 0u; y <= 2u * radius; y++) {
        for (var x = 0u; x <= 2u * radius; x++) {
            let texel = tile[tile_index(local.xy, vec2<u32>(x, y))];
            if texel.x == 0.0 {
                continue;
            }
            let g = texel.y - centre.y;
            count += 1.0;
            sum_g += g;
            sum_gg += g * g;
            sum_p += texel.z;
            sum_gp += g * texel.z;
        }
    }
    let mean_g = sum_g / count;
    let mean_p = sum_p / count;
    // Rounding can take a variance of (nearly) 0 below 0, which epsilon might not outweigh.
    let variance = max(sum_gg / count - mean_g * mean_g, 0.0);
    let covariance = sum_gp / count - mean_g * mean_p;
    let a = covariance / (variance + guided.epsilon);
    // b_k = mean(p) - a mean(I) measured from the centre, where g = 0: the line's value there.
    let c = mean_p - a * mean_g;
    textureStore(coefficients_out, id.xy, vec4<f32>(a, c, 0.0, 0.0));
}
