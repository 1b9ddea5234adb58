// requires: common/view.wgsl, common/ao.wgsl, kernel/msvo/msvo.wgsl
// Multi-scale volumetric obscurance, one merge (passes/kernel/msvo.rs): a level's own obscurance
// (`finer`) times the merged obscurance of the level below it in resolution (`coarser`),
// brought up by a bilateral upsample that trusts coarse texels by how close their depth is to
// the texel's (the blend of levels of Microsoft's MiniEngine and Unity's Post-processing Stack v2).
// Written into `ao_out`, whose size names the level; at level 0 the product is shaped and is the
// method's AO.

@group(0) @binding(9) var finer: texture_2d<f32>;
@group(0) @binding(10) var coarser: texture_2d<f32>;

// Relative depth difference that halves a coarse texel's weight against one on the texel's
// own surface: about what a plane seen at 60 degrees from its normal changes across one texel.
const DEPTH_TOLERANCE: f32 = 0.01;
// Weight of "no coarser occlusion" (1) beside the coarse texels: matched texels weigh 25 to 100
// times more, so it decides only where no coarse texel shows the texel's surface (a thin
// object the coarse level lost), which then keeps its own level's obscurance alone.
const UNMATCHED_WEIGHT: f32 = 0.1;

// The coarser level's merged obscurance at texel `t` of `level`, whose depth is `depth`: its
// 2x2 bilinear footprint, each texel weighted by its depth's closeness.
fn coarser_at(t: vec2<u32>, level: u32, depth: f32) -> f32 {
    let dims = vec2<i32>(textureDimensions(coarser));
    let q = (vec2<f32>(t) + 0.5) * 0.5 - 0.5;
    let base = floor(q);
    let f = q - base;
    var sum = UNMATCHED_WEIGHT;
    var total = UNMATCHED_WEIGHT;
    for (var i = 0u; i < 4u; i++) {
        let corner = vec2<f32>(f32(i & 1u), f32(i >> 1u));
        let texel = clamp(vec2<i32>(base + corner), vec2<i32>(0), dims - 1);
        let bilinear = mix(1.0 - f.x, f.x, corner.x) * mix(1.0 - f.y, f.y, corner.y);
        // Levels as i32: naga's GLSL output checks a load against textureSize(image, level), which
        // takes no u32 (wgpu's GL backend).
        let z = textureLoad(linear_depth, texel, i32(level + 1u)).r;
        if z == NO_SURFACE {
            continue;
        }
        let w = bilinear / (abs(z - depth) / depth + DEPTH_TOLERANCE);
        sum += w * textureLoad(coarser, texel, 0).r;
        total += w;
    }
    return sum / total;
}

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= textureDimensions(ao_out)) {
        return;
    }
    let level = output_level();
    let depth = textureLoad(linear_depth, id.xy, i32(level)).r;
    var value = 1.0;
    if depth != NO_SURFACE {
        value = textureLoad(finer, id.xy, 0).r * coarser_at(id.xy, level, depth);
        if level == 0u {
            value = shape_ao(value, depth);
        }
    }
    textureStore(ao_out, id.xy, vec4<f32>(value, 0.0, 0.0, 0.0));
}
