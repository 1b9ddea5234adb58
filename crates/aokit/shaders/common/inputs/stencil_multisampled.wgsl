// Binding 1 of `apply_mask`: sample 0 of a multisampled stencil aspect.
@group(0) @binding(1) var mask: texture_multisampled_2d<u32>;
fn load_stencil(pixel: vec2<u32>) -> u32 {
    return textureLoad(mask, pixel, 0).r;
}
