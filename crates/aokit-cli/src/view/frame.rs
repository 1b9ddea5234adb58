//! What the viewer shows of a rendered frame (lit, AO only, a debug view), the internal render
//! size, and the frame timings.

use std::collections::VecDeque;
use std::time::Duration;

use aokit::PassTime;
use aokit::debug::DebugView;
use aokit_reference::ReferenceImage;
use aokit_scene::Frame;

/// What the central area shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DisplayMode {
    /// The scene lit, with the AO in its ambient light.
    Lit,
    /// The AO alone, white unoccluded to black occluded.
    Ao,
    /// One of the pipeline's debug views.
    Debug(DebugView),
    /// The CPU reference of the view, in grey as the AO.
    Reference,
    /// The signed error AO - reference, blue too dark to red too bright, as `aokit compare`
    /// draws it.
    Error,
}

impl DisplayMode {
    /// Every mode, in the order the panel and the `M` key step through them. The debug view
    /// `ao` is the `ao` mode (the pipeline's AO in grey), listed once.
    pub fn all() -> Vec<DisplayMode> {
        let mut all = vec![
            DisplayMode::Lit,
            DisplayMode::Ao,
            DisplayMode::Reference,
            DisplayMode::Error,
        ];
        all.extend(
            DebugView::ALL
                .iter()
                .filter(|&&v| v != DebugView::Ao)
                .map(|&v| DisplayMode::Debug(v)),
        );
        all
    }

    /// The name `--mode` takes and the panel shows: `lit`, `ao`, or the debug view's
    /// (`normals`, `raw-ao`, ...).
    pub fn name(self) -> &'static str {
        match self {
            DisplayMode::Lit => "lit",
            DisplayMode::Ao => "ao",
            DisplayMode::Reference => "reference",
            DisplayMode::Error => "error",
            DisplayMode::Debug(view) => view.name(),
        }
    }

    /// The next mode after this one, wrapping around.
    pub fn next(self) -> DisplayMode {
        let all = DisplayMode::all();
        let i = all.iter().position(|&m| m == self).unwrap_or(0);
        all[(i + 1) % all.len()]
    }

    /// The debug view the renderer must draw for this mode.
    pub fn debug_view(self) -> Option<DebugView> {
        match self {
            DisplayMode::Debug(view) => Some(view),
            _ => None,
        }
    }

    /// Whether the mode shows the reference, which must be traced first.
    pub fn needs_reference(self) -> bool {
        matches!(self, DisplayMode::Reference | DisplayMode::Error)
    }
}

impl std::str::FromStr for DisplayMode {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        DisplayMode::all()
            .into_iter()
            .find(|m| m.name() == s)
            .ok_or_else(|| {
                let names: Vec<&str> = DisplayMode::all().iter().map(|m| m.name()).collect();
                format!("unknown display mode `{s}`; one of {}", names.join(", "))
            })
    }
}

/// The RGBA8 (sRGB) image `mode` shows of `frame` with the view's `reference`; `None` where the
/// frame lacks that debug view, or the mode needs a reference of the frame's size and there is
/// none.
pub fn image_of(
    frame: &Frame,
    mode: DisplayMode,
    reference: Option<&ReferenceImage>,
) -> Option<Vec<u8>> {
    let reference = reference.filter(|r| r.size == frame.size);
    match mode {
        DisplayMode::Lit => Some(frame.lit.clone()),
        DisplayMode::Ao => Some(aokit_eval::grey_to_rgba(&frame.ao)),
        DisplayMode::Reference => reference.map(|r| aokit_eval::grey_to_rgba(&r.ao)),
        DisplayMode::Error => reference.map(|r| {
            crate::compare::error_map(r, &frame.ao)
                .chunks_exact(3)
                .flat_map(|rgb| [rgb[0], rgb[1], rgb[2], 255])
                .collect()
        }),
        DisplayMode::Debug(view) => frame
            .debug
            .iter()
            .find(|(v, _)| *v == view)
            .map(|(_, image)| image.clone()),
    }
}

/// The size to render at for an area of `area` pixels at `scale`: each side scaled and rounded,
/// at least 8 pixels.
pub fn internal_size(area: [u32; 2], scale: f32) -> [u32; 2] {
    area.map(|side| ((side as f32 * scale).round() as u32).max(8))
}

/// Per-pass times, smoothed over frames so that the table can be read, and the last frames'
/// times unsmoothed for the graph.
#[derive(Default)]
pub struct Timings {
    /// Milliseconds of each AO pass, by name, in the order the frame ran them.
    pub passes: Vec<(&'static str, f64)>,
    /// Milliseconds the CPU spent on the last frames (render, read back, draw), smoothed.
    pub frame_ms: f64,
    /// The last [`HISTORY`] rendered frames, oldest first: the CPU time of each and, where
    /// the adapter has timestamps, the GPU time of its AO passes.
    pub history: VecDeque<(f64, Option<f64>)>,
}

/// Weight of the newest sample in the smoothed times.
const SMOOTHING: f64 = 0.2;

/// Frames the graph shows: a few seconds at interactive rates.
pub const HISTORY: usize = 240;

impl Timings {
    /// Adds one frame's CPU time and, where the adapter has timestamps, its pass times.
    pub fn add(&mut self, frame: Duration, passes: Option<&[PassTime]>) {
        let ms = frame.as_secs_f64() * 1e3;
        if self.history.len() == HISTORY {
            self.history.pop_front();
        }
        let gpu = passes.map(|passes| passes.iter().map(|p| p.ms).sum());
        self.history.push_back((ms, gpu));
        self.frame_ms = if self.frame_ms == 0.0 {
            ms
        } else {
            self.frame_ms + SMOOTHING * (ms - self.frame_ms)
        };
        let Some(passes) = passes else { return };
        let same = self.passes.len() == passes.len()
            && self
                .passes
                .iter()
                .zip(passes)
                .all(|((n, _), p)| *n == p.name);
        if same {
            for ((_, old), pass) in self.passes.iter_mut().zip(passes) {
                *old += SMOOTHING * (pass.ms - *old);
            }
        } else {
            self.passes = passes.iter().map(|p| (p.name, p.ms)).collect();
        }
    }

    /// Sum of the pass times.
    pub fn total_ms(&self) -> f64 {
        self.passes.iter().map(|(_, ms)| ms).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_history_keeps_the_newest_frames_unsmoothed() {
        let mut timings = Timings::default();
        for i in 0..HISTORY + 10 {
            let passes = [PassTime {
                name: "gtao",
                ms: i as f64,
            }];
            timings.add(Duration::from_millis(i as u64), Some(&passes));
        }
        assert_eq!(timings.history.len(), HISTORY);
        assert_eq!(timings.history.front(), Some(&(10.0, Some(10.0))));
        let last = (HISTORY + 9) as f64;
        assert_eq!(timings.history.back(), Some(&(last, Some(last))));
        // The table's time is smoothed: it lags the newest frame.
        assert!(timings.frame_ms < last);
        timings.add(Duration::from_millis(1), None);
        assert_eq!(timings.history.back(), Some(&(1.0, None)));
    }

    #[test]
    fn modes_parse_by_name_and_cycle_through_every_debug_view() {
        assert_eq!("lit".parse::<DisplayMode>(), Ok(DisplayMode::Lit));
        assert_eq!(
            "raw-ao".parse::<DisplayMode>(),
            Ok(DisplayMode::Debug(DebugView::RawAo))
        );
        assert!(
            "nope"
                .parse::<DisplayMode>()
                .unwrap_err()
                .contains("normals")
        );
        let mut mode = DisplayMode::Lit;
        for _ in 0..DisplayMode::all().len() {
            mode = mode.next();
        }
        assert_eq!(mode, DisplayMode::Lit);
        // `ao` once: the mode, not also the debug view of the same name.
        assert_eq!(DisplayMode::all().len(), 3 + DebugView::ALL.len());
        let names: Vec<&str> = DisplayMode::all().iter().map(|m| m.name()).collect();
        assert_eq!(names.iter().filter(|&&n| n == "ao").count(), 1);
    }

    #[test]
    fn internal_size_scales_and_keeps_a_minimum() {
        assert_eq!(internal_size([1280, 720], 0.5), [640, 360]);
        assert_eq!(internal_size([10, 3], 0.25), [8, 8]);
    }

    #[test]
    fn timings_smooth_and_restart_when_the_passes_change() {
        let mut timings = Timings::default();
        let pass = |name, ms| PassTime { name, ms };
        timings.add(Duration::from_millis(10), Some(&[pass("kernel", 2.0)]));
        timings.add(Duration::from_millis(20), Some(&[pass("kernel", 4.0)]));
        assert!((timings.frame_ms - 12.0).abs() < 1e-9);
        assert!((timings.passes[0].1 - 2.4).abs() < 1e-9);
        timings.add(
            Duration::from_millis(20),
            Some(&[pass("a", 1.0), pass("b", 1.0)]),
        );
        assert_eq!(timings.total_ms(), 2.0);
        timings.add(Duration::from_millis(20), None);
        assert_eq!(timings.passes.len(), 2);
    }
}
