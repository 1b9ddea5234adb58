//! Error statistics of an AO image against the reference over a pixel mask.

use crate::ssim::masked_ssim;

/// How far an AO image is from the reference over the scored pixels. AO and reference are in
/// [0, 1] with 1 = unoccluded.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Metrics {
    /// Pixels scored (where the mask is set).
    pub pixels: usize,
    /// Mean absolute error.
    pub mae: f64,
    /// Root mean squared error.
    pub rmse: f64,
    /// Mean signed error `ao - reference`: positive means the method is too bright
    /// (under-occludes), negative too dark (over-occludes).
    pub bias: f64,
    /// Peak signal-to-noise ratio in dB with peak 1; infinite for an exact match.
    pub psnr: f64,
    /// Mean structural similarity (Wang et al. 2004) with mask-weighted windows; 1 is identical.
    pub ssim: f64,
}

impl Metrics {
    /// What an empty selection scores: no pixels, every statistic NaN.
    pub const EMPTY: Self = Self {
        pixels: 0,
        mae: f64::NAN,
        rmse: f64::NAN,
        bias: f64::NAN,
        psnr: f64::NAN,
        ssim: f64::NAN,
    };
}

/// How a method does over a sequence of frames (a camera path or moving objects), each scored
/// against its own reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SequenceMetrics {
    /// Frames in the sequence.
    pub frames: u32,
    /// Mean over the frames of each frame's RMSE against its reference.
    pub mean_rmse: f64,
    /// Mean absolute change of AO between consecutive frames over pixels that show a surface in
    /// both: with a still camera and scene, all of it is noise (flicker).
    pub flicker: f64,
    /// Scores over the pixels that each frame newly reveals (their surface was hidden or off
    /// screen in the frame before), all frames after the first together: where temporal
    /// filters have no history and trailing shows.
    pub disoccluded: Metrics,
}

/// Scores `ao` against `reference` over the pixels where `mask` is true.
///
/// All three slices hold `size[0] * size[1]` values, row-major from the top-left. With no masked
/// pixels, or slices of another length, the result is [`Metrics::EMPTY`].
pub fn compare(size: [u32; 2], ao: &[f32], reference: &[f32], mask: &[bool]) -> Metrics {
    let n = (size[0] as usize).checked_mul(size[1] as usize);
    if n.is_none()
        || [ao.len(), reference.len(), mask.len()]
            .iter()
            .any(|&len| Some(len) != n)
    {
        return Metrics::EMPTY;
    }
    let (mut count, mut abs, mut sq, mut signed) = (0usize, 0.0f64, 0.0f64, 0.0f64);
    for ((&a, &r), _) in ao.iter().zip(reference).zip(mask).filter(|(_, m)| **m) {
        let e = f64::from(a) - f64::from(r);
        count += 1;
        abs += e.abs();
        sq += e * e;
        signed += e;
    }
    if count == 0 {
        return Metrics::EMPTY;
    }
    let n = count as f64;
    let mse = sq / n;
    Metrics {
        pixels: count,
        mae: abs / n,
        rmse: mse.sqrt(),
        bias: signed / n,
        psnr: if mse == 0.0 {
            f64::INFINITY
        } else {
            10.0 * (1.0 / mse).log10()
        },
        ssim: masked_ssim(size, ao, reference, mask),
    }
}
