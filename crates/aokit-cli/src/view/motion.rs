//! The viewer's motion: the scene's moving parts and a camera path played over a loop of
//! frames, as `aokit render --frames N --path P --animate` renders them, with pause and step.
//! Time advances one step per rendered frame, not with the clock, so that a screenshot after N
//! frames is always the same image.

use aokit_scene::{Camera, CameraPath};

/// Where the loop stands and what moves.
#[derive(Clone, Debug, PartialEq)]
pub struct Motion {
    /// The scene's moving parts follow the loop's time (`--animate`).
    pub animate: bool,
    /// The camera's path over the loop, about the camera the user steers (`--path`).
    pub path: CameraPath,
    /// Frames in one loop (at least 2): the first at time 0, the last at 1.
    pub loop_frames: u32,
    /// The frame the next render shows, `0..loop_frames`.
    pub frame: u32,
    /// Whether each rendered frame steps to the next.
    pub playing: bool,
}

impl Motion {
    /// Whether anything moves.
    pub fn active(&self) -> bool {
        self.animate || self.path != CameraPath::Still
    }

    /// The loop's time at the current frame, 0 to 1, as `aokit render` gives frame `i` of
    /// `N`: `i / (N - 1)`.
    pub fn t(&self) -> f32 {
        self.frame as f32 / (self.loop_frames - 1) as f32
    }

    /// The camera the current frame sees: `camera` moved along the path.
    pub fn camera(&self, camera: &Camera) -> Camera {
        self.path.at(camera, self.t())
    }

    /// The moving parts' time of the current frame (0, at rest, unless animated).
    pub fn time(&self) -> f32 {
        if self.animate { self.t() } else { 0.0 }
    }

    /// Steps `by` frames, wrapping around the loop; `true` when it wrapped (a cut: the
    /// temporal history must start over).
    pub fn step(&mut self, by: i64) -> bool {
        let n = i64::from(self.loop_frames);
        let next = i64::from(self.frame) + by;
        self.frame = next.rem_euclid(n) as u32;
        !(0..n).contains(&next)
    }

    /// Before each rendered frame but the first: the next frame while playing and moving;
    /// `true` when it wrapped.
    pub fn advance(&mut self) -> bool {
        self.playing && self.active() && self.step(1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn motion() -> Motion {
        Motion {
            animate: true,
            path: CameraPath::Orbit,
            loop_frames: 5,
            frame: 0,
            playing: true,
        }
    }

    #[test]
    fn the_loop_runs_from_time_0_to_1_and_wraps() {
        let mut m = motion();
        assert_eq!(m.t(), 0.0);
        for _ in 0..4 {
            assert!(!m.advance());
        }
        assert_eq!((m.frame, m.t(), m.time()), (4, 1.0, 1.0));
        assert!(m.advance());
        assert_eq!(m.frame, 0);
        assert!(m.step(-1));
        assert_eq!(m.frame, 4);
    }

    #[test]
    fn paused_or_still_it_stays() {
        let mut m = Motion {
            playing: false,
            ..motion()
        };
        m.advance();
        assert_eq!(m.frame, 0);
        let mut still = Motion {
            animate: false,
            path: CameraPath::Still,
            ..motion()
        };
        still.advance();
        assert_eq!((still.frame, still.time()), (0, 0.0));
        still.frame = 3;
        assert_eq!(still.time(), 0.0);
    }
}
