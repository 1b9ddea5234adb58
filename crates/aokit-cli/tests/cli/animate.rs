//! `aokit render --animate`, run in fresh temporary directories.

use std::path::Path;

use crate::common::{command, output, text};

/// Runs `aokit render` with `args` in `dir`, returning its stderr; panics if it fails.
fn render(dir: &Path, args: &[&str]) -> String {
    let out = output(command(dir, &["render"]).args(args));
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "{args:?}: {stderr}");
    stderr
}

fn grey(path: &Path) -> Vec<u8> {
    image::open(path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .into_luma8()
        .into_raw()
}

#[test]
fn animate_moves_the_parts_over_the_frames() {
    let dir = tempfile::tempdir().unwrap();
    let sequence = ["--scene", "room", "--size", "64x40", "--frames", "3"];
    render(
        dir.path(),
        &[&sequence[..], &["--animate", "--out", "moving"]].concat(),
    );
    render(dir.path(), &[&sequence[..], &["--out", "still"]].concat());
    let (moving, still) = (dir.path().join("moving"), dir.path().join("still"));
    for file in [
        "frames/ao-000.png",
        "frames/ao-002.png",
        "frames/lit-002.png",
        "ao.gif",
    ] {
        assert!(moving.join(file).is_file(), "{file} missing");
    }
    // The first frame shows the parts at rest; by the last the sphere has rolled.
    let differing = |a: &[u8], b: &[u8]| a.iter().zip(b).filter(|(x, y)| x != y).count();
    let frame = |dir: &Path, i: u32| grey(&dir.join(format!("frames/lit-{i:03}.png")));
    assert_eq!(differing(&frame(&moving, 0), &frame(&still, 0)), 0);
    let moved = differing(&frame(&moving, 2), &frame(&still, 2));
    assert!(moved > 50, "{moved} pixels changed");

    let stderr = render(
        dir.path(),
        &[
            "--scene",
            "open",
            "--size",
            "32x20",
            "--frames",
            "2",
            "--animate",
            "--out",
            "open",
        ],
    );
    assert!(stderr.contains("no moving parts"), "{stderr}");
}
