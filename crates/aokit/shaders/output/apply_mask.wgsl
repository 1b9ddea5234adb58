// requires: common/view.wgsl, common/mask/texture_weight.wgsl | common/mask/stencil_test.wgsl
// Exclusion mask: the pixels the caller marked receive no AO (AoInputs::mask). The program
// starts with the mask's binding and its `mask_weight` (1 = no AO, 0 = all of it), one per mask
// kind and sample count (shader.rs). Runs last, at the input's size, on the AO the filters and
// the upsample left, so no filter spreads a masked pixel's 1 onto its neighbours.

@group(0) @binding(2) var ao_in: texture_2d<f32>;
@group(0) @binding(3) var ao_out: texture_storage_2d<r32float, write>;

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= vec2<u32>(view.size)) {
        return;
    }
    let ao = textureLoad(ao_in, id.xy, 0).r;
    textureStore(ao_out, id.xy, vec4<f32>(mix(ao, 1.0, mask_weight(id.xy)), 0.0, 0.0, 0.0));
}
