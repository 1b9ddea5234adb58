//! The diverging colour scale for signed AO error.

/// Where the method is too bright (`ao > reference`, under-occludes).
const RED: [f32; 3] = [200.0, 20.0, 30.0];
/// Where the method is too dark (`ao < reference`, over-occludes).
const BLUE: [f32; 3] = [25.0, 70.0, 200.0];
/// Pixels that are not scored: neutral, so they read as neither sign.
const MASKED: [u8; 3] = [128, 128, 128];

/// Colour of `t` in [-1, 1]: blue through white to red.
fn diverging(t: f32) -> [u8; 3] {
    let t = t.clamp(-1.0, 1.0);
    let end = if t >= 0.0 { RED } else { BLUE };
    let a = t.abs();
    end.map(|c| (255.0 + (c - 255.0) * a).round() as u8)
}

/// Colours the signed error `ao - reference` per pixel as interleaved RGB8: white at 0, red when
/// the method is too bright (under-occludes), blue when too dark (over-occludes), saturating at
/// `±range`. Pixels outside `mask`, with a NaN error, or beyond the end of a shorter
/// `reference` or `mask` are mid grey. The output has `ao.len()` pixels.
pub fn error_map_rgb(ao: &[f32], reference: &[f32], mask: &[bool], range: f32) -> Vec<u8> {
    // A non-positive range would divide by zero; the smallest range saturates every error instead.
    let range = if range > 0.0 {
        range
    } else {
        f32::MIN_POSITIVE
    };
    let mut rgb = Vec::with_capacity(ao.len() * 3);
    for (i, &a) in ao.iter().enumerate() {
        let colour = match (reference.get(i), mask.get(i)) {
            (Some(&r), Some(true)) if !(a - r).is_nan() => diverging((a - r) / range),
            _ => MASKED,
        };
        rgb.extend_from_slice(&colour);
    }
    rgb
}

/// A horizontal colour bar of the same scale as interleaved RGB8: the leftmost column is the
/// colour of `-range`, the middle 0 and the rightmost column `+range`, so the bar can be labelled
/// at its ends and centre whatever the range.
pub fn legend_rgb(width: u32, height: u32) -> Vec<u8> {
    let last = width.saturating_sub(1).max(1) as f32;
    let row: Vec<u8> = (0..width)
        .flat_map(|x| {
            if width == 1 {
                diverging(0.0)
            } else {
                diverging(-1.0 + 2.0 * x as f32 / last)
            }
        })
        .collect();
    row.repeat(height as usize)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn legend_runs_blue_to_red() {
        let bar = legend_rgb(101, 2);
        assert_eq!(bar.len(), 101 * 2 * 3);
        assert_eq!(&bar[0..3], &diverging(-1.0));
        assert_eq!(&bar[150..153], &[255, 255, 255]);
        assert_eq!(&bar[300..303], &diverging(1.0));
        assert_eq!(&bar[303..306], &bar[0..3]);
        assert_eq!(legend_rgb(1, 1), [255, 255, 255]);
    }

    #[test]
    fn zero_range_saturates() {
        assert_eq!(
            error_map_rgb(&[0.6, 0.5], &[0.5, 0.5], &[true, true], 0.0),
            [200, 20, 30, 255, 255, 255]
        );
    }
}
