// Camera and depth conventions shared by every pass (mirrors `ViewUniforms` in uniforms.rs).
// View space is right-handed with the camera looking down -Z; pixel y grows downwards, NDC y up.

struct ViewUniforms {
    // The pass's texel grid (the working resolution, or the input's), and its reciprocal: for
    // bounds and texture coordinates.
    size: vec2<f32>,
    inv_size: vec2<f32>,
    // linear = (c.x * ndc + c.y) / (c.z * ndc + c.w): one form for every projection.
    linearize: vec4<f32>,
    // NDC xy to view xy; perspective results are then scaled by linear depth.
    ndc_to_view: vec2<f32>,
    // Pixels per world unit at linear depth 1 (perspective) or anywhere (orthographic).
    pixels_per_unit: f32,
    // 1 for orthographic, 0 for perspective: used with mix() so one code path serves both.
    orthographic: f32,
    // Depth-buffer value of pixels nothing was drawn to.
    far_ndc_depth: f32,
    frame_index: u32,
    // Image uv per texel of the grid: inv_size, except below full resolution when a side of the
    // input is not a multiple of the scale and the grid's last texel reaches past the image.
    uv_per_pixel: vec2<f32>,
    // Where the view axis meets the image in NDC (Projection::ndc_offset): 0, or the frame's
    // jitter, or an off-centre frustum's shift.
    ndc_offset: vec2<f32>,
    // The guard band in texels of the grid (AoInputs::guard_band): the per-pixel kernel
    // dispatches over the inner frame and shades texel `id + kernel_offset`; 0 without a band.
    kernel_offset: vec2<u32>,
}

@group(0) @binding(0) var<uniform> view: ViewUniforms;

// Linear depth textures store this where there is no surface (sky, cleared depth).
const NO_SURFACE: f32 = 0.0;

// Largest finite f32: anything beyond came from an infinite or overflowing depth.
const MAX_DEPTH: f32 = 3.4e38;

fn linearize_depth(ndc_depth: f32) -> f32 {
    let c = view.linearize;
    return (c.x * ndc_depth + c.y) / (c.z * ndc_depth + c.w);
}

// View-space position of the point at `pixel` (in pixels, centres at +0.5) and linear depth.
fn view_position(pixel: vec2<f32>, linear_depth: f32) -> vec3<f32> {
    let uv = pixel * view.uv_per_pixel;
    let ndc = vec2<f32>(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0) - view.ndc_offset;
    let scale = mix(linear_depth, 1.0, view.orthographic);
    return vec3<f32>(ndc * view.ndc_to_view * scale, -linear_depth);
}

// Unit vector from a view-space point towards the eye.
fn view_direction(position: vec3<f32>) -> vec3<f32> {
    // Scaled to its largest component first: at tiny depths (1e-30) the squared length
    // underflows to 0 and normalize would return NaN, which GTAO's slices turn into AO 0.
    let toward_eye = mix(-position, vec3<f32>(0.0, 0.0, 1.0), view.orthographic);
    let largest = max(max(abs(toward_eye.x), abs(toward_eye.y)), abs(toward_eye.z));
    return normalize(toward_eye / select(1.0, largest, largest > 0.0));
}

// Screen-space length in pixels of `world_length` seen at `linear_depth`.
fn pixels_at_depth(world_length: f32, linear_depth: f32) -> f32 {
    return world_length * view.pixels_per_unit / mix(linear_depth, 1.0, view.orthographic);
}

// Pixel position (in pixels) where the view-space point `position` projects; the inverse of
// view_position. Perspective points must lie in front of the eye (position.z < 0).
fn pixel_of(position: vec3<f32>) -> vec2<f32> {
    let scale = mix(-position.z, 1.0, view.orthographic);
    let ndc = position.xy / (view.ndc_to_view * scale) + view.ndc_offset;
    return uv_to_pixel(vec2<f32>(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5));
}

// Grid position (in pixels) of image uv `uv`; the inverse of the uv view_position takes.
fn uv_to_pixel(uv: vec2<f32>) -> vec2<f32> {
    return uv / view.uv_per_pixel;
}
