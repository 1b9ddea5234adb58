// Binding 1 of `apply_mask`: a stencil aspect.
@group(0) @binding(1) var mask: texture_2d<u32>;
fn load_stencil(pixel: vec2<u32>) -> u32 {
    return textureLoad(mask, pixel, 0).r;
}
