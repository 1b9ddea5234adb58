//! Which pixels to score: surfaces, the neighbourhoods of depth edges where screen-space AO
//! goes wrong first (halos, missing contact shadows), and surfaces seen nearly edge-on.

/// True where there is a surface: linear depth finite and positive.
pub fn surface_mask(linear_depth: &[f32]) -> Vec<bool> {
    linear_depth
        .iter()
        .map(|&d| d.is_finite() && d > 0.0)
        .collect()
}

/// Surface pixels seen nearly edge-on: where the unit `normals` and the unit directions towards
/// the eye `to_eye` have `|n . v| < max_cos`. Zero normals (no surface) are never in the mask,
/// and if the two slices differ in length the mask is all false.
///
/// ```
/// let normals = [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.0; 3]];
/// let to_eye = [[0.0, 0.0, 1.0]; 3];
/// assert_eq!(aokit_eval::grazing_mask(&normals, &to_eye, 0.3), [true, false, false]);
/// ```
pub fn grazing_mask(normals: &[[f32; 3]], to_eye: &[[f32; 3]], max_cos: f32) -> Vec<bool> {
    if normals.len() != to_eye.len() {
        return vec![false; normals.len()];
    }
    normals
        .iter()
        .zip(to_eye)
        .map(|(n, v)| {
            let facing = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
            n.iter().any(|&c| c != 0.0) && facing.abs() < max_cos
        })
        .collect()
}

/// Surface pixels within `radius` pixels (a square neighbourhood) of a depth edge.
///
/// A surface pixel is on an edge when a 4-neighbour is background, or when the two depths differ
/// by more than `relative_depth` times the smaller one (relative, so the same threshold works
/// near and far). If `linear_depth` does not hold `size[0] * size[1]` values the mask is all
/// false.
pub fn depth_edge_mask(
    size: [u32; 2],
    linear_depth: &[f32],
    relative_depth: f32,
    radius: u32,
) -> Vec<bool> {
    let (w, h) = (size[0] as usize, size[1] as usize);
    if w.checked_mul(h) != Some(linear_depth.len()) {
        return vec![false; linear_depth.len()];
    }
    let surface = surface_mask(linear_depth);
    let differs = |a: usize, b: usize| {
        if !surface[b] {
            return true;
        }
        let (da, db) = (linear_depth[a], linear_depth[b]);
        (da - db).abs() > relative_depth * da.min(db)
    };
    let mut edges = vec![false; w * h];
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            if !surface[i] {
                continue;
            }
            edges[i] = (x > 0 && differs(i, i - 1))
                || (x + 1 < w && differs(i, i + 1))
                || (y > 0 && differs(i, i - w))
                || (y + 1 < h && differs(i, i + w));
        }
    }
    let dilated = dilate(&edges, w, h, radius as usize);
    dilated
        .iter()
        .zip(&surface)
        .map(|(&e, &s)| e && s)
        .collect()
}

/// Square dilation as two 1-D passes; each pass keeps a running count of set pixels in the
/// window so the cost does not grow with the radius.
fn dilate(mask: &[bool], w: usize, h: usize, r: usize) -> Vec<bool> {
    if r == 0 {
        return mask.to_vec();
    }
    let pass = |src: &[bool], len: usize, lines: usize, at: &dyn Fn(usize, usize) -> usize| {
        let mut out = vec![false; src.len()];
        for line in 0..lines {
            let mut count = 0usize;
            // Prime the window with the first `r` samples.
            for k in 0..r.min(len) {
                count += usize::from(src[at(line, k)]);
            }
            for k in 0..len {
                if k + r < len {
                    count += usize::from(src[at(line, k + r)]);
                }
                if k > r {
                    count -= usize::from(src[at(line, k - r - 1)]);
                }
                out[at(line, k)] = count > 0;
            }
        }
        out
    };
    let rows = pass(mask, w, h, &|y, x| y * w + x);
    pass(&rows, h, w, &|x, y| y * w + x)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn brute_dilate(mask: &[bool], w: usize, h: usize, r: usize) -> Vec<bool> {
        (0..w * h)
            .map(|i| {
                let (x, y) = ((i % w) as isize, (i / w) as isize);
                let r = r as isize;
                (-r..=r).any(|dy| {
                    (-r..=r).any(|dx| {
                        let (nx, ny) = (x + dx, y + dy);
                        nx >= 0
                            && ny >= 0
                            && (nx as usize) < w
                            && (ny as usize) < h
                            && mask[ny as usize * w + nx as usize]
                    })
                })
            })
            .collect()
    }

    #[test]
    fn dilation_matches_brute_force() {
        let (w, h) = (13, 9);
        let mask: Vec<bool> = (0..w * h).map(|i| (i * 7919) % 23 == 0).collect();
        for r in 0..5 {
            assert_eq!(
                dilate(&mask, w, h, r),
                brute_dilate(&mask, w, h, r),
                "radius {r}"
            );
        }
    }

    #[test]
    fn surface_mask_rejects_background() {
        assert_eq!(
            surface_mask(&[1.0, 0.0, -1.0, f32::INFINITY, f32::NAN, 0.5]),
            [true, false, false, false, false, true]
        );
    }

    #[test]
    fn wrong_length_gives_empty_mask() {
        assert_eq!(depth_edge_mask([2, 2], &[1.0; 3], 0.1, 1), [false; 3]);
    }
}
