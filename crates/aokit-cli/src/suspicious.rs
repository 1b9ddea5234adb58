//! Passes that read without error but look like something else was given: a colour or normal
//! image as depth, depth-buffer values as linear depth, world-space normals as view-space ones.
//! Each check returns the warning to print (one line, naming the file), or `None`.

use std::path::Path;

use aokit::projection::pixel_to_ndc;
use aokit::{NormalSpace, Projection};
use aokit_eval::read_normals;
use glam::{Vec2, Vec3};

/// Share of the pixels (or of those showing a surface) above which a sign counts: a few
/// pixels of anything happen in real passes.
const SOME: f32 = 0.01;

/// Share of surface pixels whose normal faces away from the camera above which the normals
/// are taken to be in the other space: `render --gbuffer`'s have none (0% on every built-in
/// scene and camera), other renderers' a few along silhouettes (interpolated and bumped
/// normals); the stairs' in world space, seen from a turned camera, 33%.
const FACING_AWAY: f32 = 0.15;

fn is_surface(depth: f32) -> bool {
    depth.is_finite() && depth > 0.0
}

/// `depth` (as read from `path`) is the first channel of a three-channel image whose channels
/// differ: a normal map or a colour image rather than depth.
pub fn depth_is_a_colour_image(path: &Path, depth: &[f32]) -> Option<String> {
    // The file read as normals picks R, G, B (or X, Y, Z); a depth image has no such group.
    let image = read_normals(path).ok()?;
    let rgb: Vec<&[f32]> = image.data.chunks_exact(3).collect();
    // Depth picked from another channel (a layered file with both passes) is not this.
    if rgb.len() != depth.len()
        || rgb
            .iter()
            .zip(depth)
            .any(|(c, d)| c[0].to_bits() != d.to_bits())
    {
        return None;
    }
    let differ = rgb.iter().filter(|c| c[0] != c[1] || c[0] != c[2]).count();
    (differ as f32 > SOME * rgb.len() as f32).then(|| {
        format!(
            "{}: the depth is the red channel of an RGB image whose channels differ at {} of {} \
             pixels: is it a normal map or a colour image?",
            path.display(),
            differ,
            rgb.len()
        )
    })
}

/// `depth`, read as linear view depth, holds depth-buffer values: every surface within
/// `[0, 1]` while the far plane lies beyond 1, with many pixels nearer than the near plane
/// (reverse-Z, `near / d`) or at exactly 1 (a cleared conventional depth buffer).
pub fn linear_depth_looks_like_ndc(
    path: &Path,
    depth: &[f32],
    projection: &Projection,
) -> Option<String> {
    let surfaces: Vec<f32> = depth.iter().copied().filter(|&d| is_surface(d)).collect();
    let far_beyond_one = projection.far.is_none_or(|far| far > 1.0);
    if surfaces.is_empty() || !far_beyond_one || surfaces.iter().any(|&d| d > 1.0) {
        return None;
    }
    let share = |count: usize| count as f32 / surfaces.len() as f32;
    let nearer = share(surfaces.iter().filter(|&&d| d < projection.near).count());
    let at_one = share(surfaces.iter().filter(|&&d| d == 1.0).count());
    let below_one = surfaces.iter().any(|&d| d < 1.0);
    let sign = if nearer > SOME {
        format!(
            "{:.0}% of them nearer than the near plane ({})",
            100.0 * nearer,
            projection.near
        )
    } else if at_one > SOME && below_one {
        format!(
            "{:.0}% of them exactly 1, a cleared depth buffer",
            100.0 * at_one
        )
    } else {
        return None;
    };
    Some(format!(
        "{}: every depth lies within [0, 1] while the far plane is beyond 1, {sign}: are these \
         depth-buffer values? give --depth-kind ndc",
        path.display()
    ))
}

/// Many `normals` (in view space as read with `space`) face away from the camera at the
/// surfaces `linear_depth` shows: normals of the other space.
pub fn normals_face_away(
    path: &Path,
    normals: &[Vec3],
    linear_depth: &[f32],
    projection: &Projection,
    size: [u32; 2],
    space: NormalSpace,
) -> Option<String> {
    let pixels = Vec2::new(size[0] as f32, size[1] as f32);
    let width = size[0].max(1) as usize;
    let (mut surfaces, mut away) = (0usize, 0usize);
    for (i, (n, &d)) in normals.iter().zip(linear_depth).enumerate() {
        if !is_surface(d) {
            continue;
        }
        surfaces += 1;
        let pixel = Vec2::new((i % width) as f32, (i / width) as f32);
        // Towards the eye: from the point back to the camera, along -Z for a parallel one.
        let point = projection.view_position_from_linear(pixel_to_ndc(pixel, pixels), d);
        let to_eye = if projection.is_orthographic() {
            Vec3::Z
        } else {
            -point
        };
        if n.dot(to_eye) < 0.0 {
            away += 1;
        }
    }
    let share = away as f32 / surfaces.max(1) as f32;
    (share > FACING_AWAY).then(|| {
        let (given, other) = match space {
            NormalSpace::View => ("view", "world"),
            NormalSpace::World => ("world", "view"),
        };
        format!(
            "{}: {:.0}% of the normals face away from the camera, read as {given}-space: are \
             they {other}-space? give --normal-space {other}",
            path.display(),
            100.0 * share
        )
    })
}
