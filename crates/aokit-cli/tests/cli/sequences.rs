//! `aokit ao --sequence PATTERN`: frames named by a pattern of depth files, paired with their
//! cameras and normals as the directory form pairs them, and the errors of a broken sequence.

use std::path::Path;

use crate::common::{aokit, failure, ok};

fn bytes(path: &Path) -> Vec<u8> {
    std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn a_pattern_of_depth_files_runs_the_frames_in_the_order_of_their_numbers() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let render = [
        "render",
        "--scene",
        "room",
        "--size",
        "48x32",
        "--frames",
        "3",
        "--path",
        "orbit",
        "--gbuffer",
        "--set",
        "temporal.enabled=false",
        "--out",
        "r",
    ];
    ok(&aokit(d, &render));
    // Another renderer's names: `depth.8.exr`, numbered from 8, so that 10 sorts last only
    // by number.
    let shot = d.join("shot");
    std::fs::create_dir(&shot).unwrap();
    let frames = d.join("r/frames");
    for (i, number) in [8, 9, 10].iter().enumerate() {
        for (from, to) in [
            (format!("depth-{i:03}.exr"), format!("depth.{number}.exr")),
            (format!("normal-{i:03}.exr"), format!("normal.{number}.exr")),
            (
                format!("camera-{i:03}.json"),
                format!("camera.{number}.json"),
            ),
        ] {
            std::fs::copy(frames.join(from), shot.join(to)).unwrap();
        }
    }
    std::fs::copy(
        frames.join("ao-settings.json"),
        shot.join("ao-settings.json"),
    )
    .unwrap();
    let stdout = ok(&aokit(
        d,
        &["ao", "--sequence", "shot/depth.*.exr", "--out", "a"],
    ));
    assert!(
        stdout.contains("AO of 3 frames of shot/depth.*.exr"),
        "{stdout}"
    );
    assert!(stdout.contains("normals from file"), "{stdout}");
    // Frame by frame the AO is render's to the byte: each depth met its own camera and normals.
    for i in 0..3 {
        let name = format!("frames/ao-{i:03}.png");
        assert!(
            bytes(&d.join("r").join(&name)) == bytes(&d.join("a").join(&name)),
            "{name} differs"
        );
    }

    let error = |pattern: &str| failure(&aokit(d, &["ao", "--sequence", pattern, "--out", "x"]));
    let message = error("shot/depth.*.npy");
    assert!(
        message.contains("no file matches depth.*.npy in shot"),
        "{message}"
    );
    let message = error("shot/frame.*.exr");
    assert!(
        message.contains("neither a directory nor a pattern"),
        "{message}"
    );
    std::fs::remove_file(shot.join("camera.10.json")).unwrap();
    let message = error("shot/depth.*.exr");
    assert!(
        message.contains("depth.10.exr has no camera.10.json beside it"),
        "{message}"
    );
    std::fs::remove_file(shot.join("normal.9.exr")).unwrap();
    let message = error("shot/depth.*.exr");
    assert!(
        message.contains("2 of the 3 frames have a normal.*.exr; give one for every frame or none"),
        "{message}"
    );
}
