// requires: common/view.wgsl, filter/guided_filter.wgsl
// Second pass of the guided filter (guided_filter.wgsl): each pixel averages the lines of the
// windows that hold it, evaluated at its own log depth, into the filtered AO.

@group(0) @binding(2) var coefficients_in: texture_2d<f32>;
@group(0) @binding(4) var ao_out: texture_storage_2d<r32float, write>;

// The line of the window centred here: its slope a_k and its value c_k at the centre.
fn load_values(pixel: vec2<i32>) -> vec2<f32> {
    return textureLoad(coefficients_in, pixel, 0).rg;
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
        textureStore(ao_out, id.xy, vec4<f32>(1.0, 0.0, 0.0, 0.0));
        return;
    }
    // The windows holding this pixel are those centred within `radius` of it.
    var count = 0.0;
    var sum = 0.0;
    for (var y = 0u; y <= 2u * radius; y++) {
        for (var x = 0u; x <= 2u * radius; x++) {
            let window = tile[tile_index(local.xy, vec2<u32>(x, y))];
            if window.x == 0.0 {
                continue;
            }
            count += 1.0;
            sum += window.z * (centre.y - window.y) + window.w;
        }
    }
    // A least-squares line through AO values in [0, 1] can leave that range at the ends of its
    // window's depth range (AO that levels off towards a crease, fitted by one slope).
    textureStore(ao_out, id.xy, vec4<f32>(clamp(sum / count, 0.0, 1.0), 0.0, 0.0, 0.0));
}
