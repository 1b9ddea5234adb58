//! The filter stage: one spatial filter kind, then the temporal filter.

pub(crate) mod edge_filter;
pub(crate) mod guided_filter;
pub(crate) mod spatial_filter;
pub(crate) mod temporal_filter;

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
