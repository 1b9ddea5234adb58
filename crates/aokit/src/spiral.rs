//! SAO's spiral of taps (McGuire, Mara and Luebke 2012, section 2.3): tap `i` of `N` lies at
//! `alpha_i = (i + 0.5) / N` of the screen radius, at angle `alpha_i * turns * 2 pi` plus the
//! pixel's rotation. The paper lists a number of turns per tap count; here it is computed.

use std::f32::consts::TAU;

/// Position of tap `i` of `count` on a spiral of `turns` turns in the unit disk, unrotated.
pub(crate) fn tap(i: u32, count: u32, turns: u32) -> [f32; 2] {
    let alpha = (i as f32 + 0.5) / count as f32;
    let angle = alpha * turns as f32 * TAU;
    [alpha * angle.cos(), alpha * angle.sin()]
}

/// Smallest distance between two of the `count` taps of a spiral of `turns` turns, each moved
/// out to radius `sqrt(alpha_i)`: where `count` points spread evenly over the disk's area would
/// put the `i`-th. On the spiral itself the innermost taps are `1 / count` apart whatever the
/// turns, so spacing measured there would only favour turns that put them on opposite sides
/// (half the taps' count: two straight spokes).
fn equal_area_spacing(count: u32, turns: u32) -> f32 {
    let taps: Vec<[f32; 2]> = (0..count)
        .map(|i| {
            let [x, y] = tap(i, count, turns);
            let stretch = x.hypot(y).sqrt().recip();
            [x * stretch, y * stretch]
        })
        .collect();
    let mut closest = f32::INFINITY;
    for (k, a) in taps.iter().enumerate() {
        for b in &taps[k + 1..] {
            closest = closest.min((a[0] - b[0]).hypot(a[1] - b[1]));
        }
    }
    closest
}

/// The turns, in `1..count` (1 for fewer than 3 taps), whose taps, moved to equal-area radii,
/// lie farthest apart (the largest smallest distance, the fewest turns among equals): a disk
/// covered without clumps or spokes, which the paper's table of turns per tap count aims at.
/// Whole turns, as the paper's.
pub(crate) fn turns(count: u32) -> u32 {
    let mut best = (1, equal_area_spacing(count, 1));
    for turns in 2..count {
        let spacing = equal_area_spacing(count, turns);
        // Spacings equal but for rounding are a tie, which the fewer turns win.
        if spacing > best.1 + 1e-6 {
            best = (turns, spacing);
        }
    }
    best.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::MAX_SAMPLE_COUNT;

    #[test]
    fn the_turns_maximise_the_equal_area_spacing_of_every_count() {
        for count in 2..=MAX_SAMPLE_COUNT {
            let chosen = turns(count);
            assert!(
                (1..count.max(2)).contains(&chosen),
                "{count} taps: {chosen} turns"
            );
            let spacing = equal_area_spacing(count, chosen);
            for other in 1..count {
                assert!(
                    equal_area_spacing(count, other) <= spacing + 1e-6,
                    "{count} taps: {other} turns space them wider than {chosen}"
                );
            }
        }
        assert_eq!(turns(1), 1);
        // The presets' counts (low, medium, high, ultra), and 32 taps on 7 turns, the pairing
        // that ports of the paper's shader use.
        assert_eq!([4, 8, 18, 54, 32].map(turns), [1, 3, 5, 16, 7]);
    }

    #[test]
    fn the_chosen_spirals_avoid_spokes_and_keep_every_tap_at_its_distance() {
        for count in [8, 18, 54] {
            let chosen = turns(count);
            // Half as many turns as taps puts the taps on two spokes, and one turn bunches the
            // inner taps on one side: both leave far wider gaps on the disk than the choice.
            for degenerate in [1, count / 2] {
                assert!(
                    equal_area_spacing(count, chosen) > 1.3 * equal_area_spacing(count, degenerate),
                    "{count} taps: {chosen} turns against {degenerate}"
                );
            }
            for i in 0..count {
                let [x, y] = tap(i, count, chosen);
                assert!((x.hypot(y) - (i as f32 + 0.5) / count as f32).abs() < 1e-5);
            }
        }
    }
}
