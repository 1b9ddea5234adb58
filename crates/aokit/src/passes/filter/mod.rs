//! The filter stage: one spatial filter kind, then the temporal filter.

pub(crate) mod edge_filter;
pub(crate) mod guided_filter;
pub(crate) mod spatial_filter;
pub(crate) mod temporal_filter;

use crate::settings::{DepthWeight, SpatialSettings};

/// What filter/bilateral_weights.wgsl compiles in, shared by the bilateral and the edges kind:
/// the depth weight's kind, whether normals weigh in and the normal power's squarings.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
struct Weights {
    depth_weight: DepthWeight,
    normal_weight: bool,
    normal_squarings: i32,
}

impl Weights {
    fn of(settings: &SpatialSettings) -> Self {
        Self {
            depth_weight: settings.depth_weight,
            normal_weight: settings.normal_power > 0.0,
            normal_squarings: normal_squarings(settings.normal_power),
        }
    }

    /// The override constants of bilateral_weights.wgsl.
    fn constants(self) -> [(&'static str, f64); 3] {
        [
            ("DEPTH_WEIGHT", f64::from(self.depth_weight as u32)),
            ("NORMAL_WEIGHT", f64::from(u8::from(self.normal_weight))),
            ("NORMAL_SQUARINGS", f64::from(self.normal_squarings)),
        ]
    }
}

/// `NORMAL_SQUARINGS` of filter/bilateral_weights.wgsl for a normal power: k where the power is
/// 2^k for k in 0..=6 (squared k times), -1 for any other (a log2 and the exp2).
fn normal_squarings(power: f32) -> i32 {
    (0..=6).find(|&k| power == (1u32 << k) as f32).unwrap_or(-1)
}

#[cfg(test)]
mod tests {
    use super::normal_squarings;

    #[test]
    fn normal_powers_of_two_are_squarings() {
        assert_eq!(normal_squarings(1.0), 0);
        assert_eq!(normal_squarings(16.0), 4);
        assert_eq!(normal_squarings(64.0), 6);
        for other in [0.5, 3.0, 12.0, 128.0, 16.000001] {
            assert_eq!(normal_squarings(other), -1, "{other}");
        }
    }
}
