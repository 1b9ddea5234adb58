//! Scores over a sequence of frames: mean error, flicker and the error in what each frame newly
//! reveals, for `aokit compare --frames`.

use aokit::Projection;
use aokit::projection::pixel_to_ndc;
use aokit_eval::{Metrics, SequenceMetrics, compare as score};
use aokit_reference::ReferenceImage;
use aokit_scene::CameraPath;
use glam::{Mat4, Vec2};

/// A note for each sequence option that changes nothing over `frames` frames: a camera path
/// other than `still`, or the temporal filter, on a single frame.
pub fn single_frame_notes(frames: u32, path: CameraPath, temporal: bool) -> Vec<String> {
    let mut notes = Vec::new();
    if frames > 1 {
        return notes;
    }
    if path != CameraPath::Still {
        notes.push(format!(
            "--path {} moves the camera over --frames N; one frame does not move",
            path.name()
        ));
    }
    if temporal {
        notes.push(temporal_single_frame_note("--frames N"));
    }
    notes
}

/// The temporal filter on a single frame, where `sequence` is the flag that gives a sequence.
pub fn temporal_single_frame_note(sequence: &str) -> String {
    format!(
        "the temporal filter accumulates over a sequence ({sequence}); one frame is its own \
         history and comes out as the kernel made it"
    )
}

/// Relative depth difference above which a pixel's surface was not what the previous frame
/// showed there: the same threshold the temporal filter rejects history with.
const SAME_SURFACE: f32 = 0.05;

/// One frame of a sequence: the camera that saw it and its reference.
pub struct SequenceFrame<'a> {
    pub view_from_world: Mat4,
    pub projection: Projection,
    pub reference: &'a ReferenceImage,
}

/// Pixels of `current` whose surface `previous` did not show: off its screen, or behind (or in
/// front of) what it showed there. Reprojected through the references' exact depths.
pub fn newly_revealed(previous: &SequenceFrame<'_>, current: &SequenceFrame<'_>) -> Vec<bool> {
    let [w, h] = current.reference.size;
    let size = Vec2::new(w as f32, h as f32);
    let to_previous = previous.view_from_world * current.view_from_world.inverse();
    let prev_clip = previous.projection.clip_from_view();
    (0..w * h)
        .map(|i| {
            let depth = current.reference.linear_depth[i as usize];
            if depth <= 0.0 {
                return false;
            }
            let pixel = Vec2::new((i % w) as f32, (i / w) as f32);
            let p = current
                .projection
                .view_position_from_linear(pixel_to_ndc(pixel, size), depth);
            let q = to_previous.transform_point3(p);
            let clip = prev_clip * q.extend(1.0);
            let ndc = Vec2::new(clip.x, clip.y) / clip.w;
            let at = Vec2::new((ndc.x + 1.0) * 0.5, (1.0 - ndc.y) * 0.5) * size;
            if clip.w <= 0.0 || !(at.cmpge(Vec2::ZERO).all() && at.cmplt(size).all()) {
                return true;
            }
            let seen = previous.reference.linear_depth[at.y as usize * w as usize + at.x as usize];
            let expected = -q.z;
            !(seen > 0.0 && (seen - expected).abs() <= SAME_SURFACE * seen.min(expected))
        })
        .collect()
}

/// Scores `ao` (one image per frame) against the frames' references.
pub fn score_sequence(frames: &[SequenceFrame<'_>], ao: &[Vec<f32>]) -> SequenceMetrics {
    let size = frames[0].reference.size;
    let surface =
        |r: &ReferenceImage| -> Vec<bool> { r.linear_depth.iter().map(|&d| d > 0.0).collect() };
    let rmse: Vec<f64> = frames
        .iter()
        .zip(ao)
        .map(|(f, a)| score(size, a, &f.reference.ao, &surface(f.reference)).rmse)
        .collect();
    let mut changes = Vec::new();
    let (mut revealed_ao, mut revealed_reference, mut revealed) =
        (Vec::new(), Vec::new(), Vec::new());
    for i in 1..frames.len() {
        let (before, now) = (&frames[i - 1], &frames[i]);
        for (k, (a, b)) in ao[i - 1].iter().zip(&ao[i]).enumerate() {
            if before.reference.linear_depth[k] > 0.0 && now.reference.linear_depth[k] > 0.0 {
                changes.push(f64::from((a - b).abs()));
            }
        }
        revealed.extend(newly_revealed(before, now));
        revealed_ao.extend_from_slice(&ao[i]);
        revealed_reference.extend_from_slice(&now.reference.ao);
    }
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let disoccluded = if revealed.is_empty() {
        Metrics::EMPTY
    } else {
        // The frames stacked into one tall image: the statistics are per pixel, SSIM's windows
        // only meet across the seams.
        let stacked = [size[0], size[1] * (frames.len() as u32 - 1)];
        score(stacked, &revealed_ao, &revealed_reference, &revealed)
    };
    SequenceMetrics {
        frames: frames.len() as u32,
        mean_rmse: mean(&rmse),
        flicker: if changes.is_empty() {
            f64::NAN
        } else {
            mean(&changes)
        },
        disoccluded,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    fn flat(size: [u32; 2], depth: f32, ao: f32) -> ReferenceImage {
        let n = (size[0] * size[1]) as usize;
        ReferenceImage {
            size,
            ao: vec![ao; n],
            linear_depth: vec![depth; n],
            normals: vec![Vec3::Z; n],
        }
    }

    #[test]
    fn a_still_camera_reveals_nothing_and_a_sidestep_reveals_one_edge() {
        let reference = flat([16, 8], 5.0, 0.8);
        let projection = Projection::perspective(1.0, 2.0, 0.1, None);
        let frame = |x: f32| SequenceFrame {
            view_from_world: Mat4::from_translation(Vec3::new(-x, 0.0, 0.0)),
            projection,
            reference: &reference,
        };
        assert!(newly_revealed(&frame(0.0), &frame(0.0)).iter().all(|&r| !r));
        // The camera moves right: the wall in front of it slides left on screen, and the
        // rightmost columns were off the previous frame's screen.
        let revealed = newly_revealed(&frame(0.0), &frame(1.0));
        assert!(revealed[15] && !revealed[0], "{revealed:?}");
        let scores = score_sequence(&[frame(0.0), frame(0.0)], &[vec![0.8; 128], vec![0.7; 128]]);
        assert!((scores.flicker - 0.1).abs() < 1e-6);
        assert!((scores.mean_rmse - 0.05).abs() < 1e-6);
        assert_eq!(scores.disoccluded.pixels, 0);
    }
}
