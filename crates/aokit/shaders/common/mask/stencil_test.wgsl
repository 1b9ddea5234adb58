// requires: common/inputs/stencil.wgsl | common/inputs/stencil_multisampled.wgsl
// The stencil test of `apply_mask`: `STENCIL_REFERENCE` and `STENCIL_READ_MASK` are override
// constants, since a renderer's stencil values rarely change.
override STENCIL_REFERENCE: u32;
override STENCIL_READ_MASK: u32;
fn mask_weight(pixel: vec2<u32>) -> f32 {
    let bits = (load_stencil(pixel) ^ STENCIL_REFERENCE) & STENCIL_READ_MASK;
    return select(0.0, 1.0, bits == 0u);
}
