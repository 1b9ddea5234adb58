// requires: common/view.wgsl, common/noise.wgsl, common/ao.wgsl, common/ao_and_depth.wgsl
// The per-pixel AO kernels' entry point (after common/ao.wgsl): one thread per pixel, the
// method's `estimate`, the shaped result stored. Kept apart from ao.wgsl so that kernels of
// another shape (separable HBAO's row and column passes) share the interface without it.

// What a method estimates for one pixel.
struct Estimate {
    // Cosine-weighted visibility of the hemisphere, 1 = unoccluded.
    visibility: f32,
    // Unnormalised mean unoccluded direction, view space (slice methods; others return n).
    bent: vec3<f32>,
}

// The noise kind and its offset over frames (`ao.noise_kind`, `ao.noise_temporal`), compiled
// in so that the kernel holds the code of one kind only: a switch on a uniform is code every
// pixel runs on a SIMD CPU adapter (lavapipe), whatever the value.
override NOISE_KIND: u32;
override NOISE_TEMPORAL: u32;

// With PACKED_AO_AND_DEPTH (`SpatialSettings::packed_input`, where the edges kind filters the
// kernel's output at its size), the stored AO and the pixel's linear depth in one texel as well
// (common/ao_and_depth.wgsl), for the filter to read; a 1x1 stand-in otherwise, never written.
override PACKED_AO_AND_DEPTH: bool = false;
@group(0) @binding(9) var ao_and_depth_out: texture_storage_2d<r32uint, write>;

fn store_ao_and_depth(s: Surface, value: f32) {
    if PACKED_AO_AND_DEPTH {
        textureStore(ao_and_depth_out, s.pixel, vec4<u32>(pack_ao_and_depth(value, s.depth)));
    }
}

// 16x16 rather than 8x8: a workgroup's slices then fetch from a larger shared neighbourhood, so
// more of their far samples hit the texture cache. Measured on an H100
// (docs/notes/performance-investigations.md): GTAO `high` 8 to 17% faster, HBAO 2 to 12%; the
// other passes gained nothing from it.
@compute @workgroup_size(16, 16)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    // With a guard band the dispatch covers the inner frame: the band is read, never shaded.
    if any(id.xy + 2u * view.kernel_offset >= vec2<u32>(view.size)) {
        return;
    }
    let surface = load_surface(id.xy + view.kernel_offset);
    if nothing_to_sample(surface) {
        store_unoccluded(surface);
        store_ao_and_depth(surface, 1.0);
        return;
    }
    let texel = textureLoad(noise_tile, id.xy % textureDimensions(noise_tile), 0).xy;
    let noise = pixel_noise(id.xy, view.frame_index, NOISE_KIND, NOISE_TEMPORAL, texel);
    let result = estimate(surface, noise);
    store_ao_and_depth(surface, store_ao(surface, result.visibility, result.bent));
}
