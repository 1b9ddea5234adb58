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
    let Some(sums) = error_sums(size, ao, reference, mask) else {
        return Metrics::EMPTY;
    };
    let n = sums.count as f64;
    let mse = sums.squared / n;
    Metrics {
        pixels: sums.count,
        mae: sums.absolute / n,
        rmse: mse.sqrt(),
        bias: sums.signed / n,
        psnr: if mse == 0.0 {
            f64::INFINITY
        } else {
            10.0 * (1.0 / mse).log10()
        },
        ssim: masked_ssim(size, ao, reference, mask),
    }
}

/// [`compare`]'s RMSE alone, for a search that scores many candidates: the SSIM is most of
/// `compare`'s time. NaN where `compare` gives [`Metrics::EMPTY`].
///
/// ```
/// let ao = [0.5, 1.0, 0.0];
/// let reference = [0.25, 1.0, 1.0];
/// let rmse = aokit_eval::rmse([3, 1], &ao, &reference, &[true, true, false]);
/// assert_eq!(rmse, aokit_eval::compare([3, 1], &ao, &reference, &[true, true, false]).rmse);
/// assert!((rmse - (0.0625f64 / 2.0).sqrt()).abs() < 1e-12);
/// ```
pub fn rmse(size: [u32; 2], ao: &[f32], reference: &[f32], mask: &[bool]) -> f64 {
    error_sums(size, ao, reference, mask).map_or(f64::NAN, |s| (s.squared / s.count as f64).sqrt())
}

/// The sums the statistics are made of, over the masked pixels of `ao - reference`.
struct ErrorSums {
    count: usize,
    absolute: f64,
    squared: f64,
    signed: f64,
}

/// [`ErrorSums`] of the masked pixels; `None` with none masked or slices of another length
/// than `size` holds.
fn error_sums(size: [u32; 2], ao: &[f32], reference: &[f32], mask: &[bool]) -> Option<ErrorSums> {
    let n = (size[0] as usize).checked_mul(size[1] as usize)?;
    if [ao.len(), reference.len(), mask.len()]
        .iter()
        .any(|&len| len != n)
    {
        return None;
    }
    let mut sums = ErrorSums {
        count: 0,
        absolute: 0.0,
        squared: 0.0,
        signed: 0.0,
    };
    for ((&a, &r), _) in ao.iter().zip(reference).zip(mask).filter(|(_, m)| **m) {
        let e = f64::from(a) - f64::from(r);
        sums.count += 1;
        sums.absolute += e.abs();
        sums.squared += e * e;
        sums.signed += e;
    }
    (sums.count > 0).then_some(sums)
}
