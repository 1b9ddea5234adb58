//! `aokit reference` records what it traced, and `aokit compare --inputs` scores the passes
//! with the settings `render --gbuffer` recorded beside them, under the flags.

use std::path::Path;

use crate::common::{aokit, failure, ok, text};

fn bytes(path: &Path) -> Vec<u8> {
    std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_slice(&bytes(path)).unwrap()
}

/// The (method, preset) rows of a compare run's metrics.json.
fn rows(out: &Path) -> Vec<(String, String)> {
    let metrics = json(&out.join("metrics.json"));
    (metrics["results"].as_array().unwrap().iter())
        .map(|r| {
            let field = |k: &str| r[k].as_str().unwrap().to_string();
            (field("method"), field("preset"))
        })
        .collect()
}

#[test]
fn compare_on_inputs_runs_the_recorded_settings_and_the_flags_go_over_them() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let view = ["--scene", "stairs", "--size", "48x32"];
    let render = [
        "render",
        "--gbuffer",
        "--method",
        "hbao",
        "--preset",
        "low",
        "--radius",
        "0.7",
        "--set",
        "hbao.direction_count=3",
        "--out",
        "p",
    ];
    ok(&aokit(d, &[&render[..], &view[..]].concat()));
    // The reference traced into the same directory: its passes replace the raster's, and
    // render's ao-settings.json stays beside them.
    let reference = ["reference", "--radius", "0.7", "--spp", "8", "--out", "p"];
    ok(&aokit(d, &[&reference[..], &view[..]].concat()));
    let info = json(&d.join("p/reference.json"));
    assert_eq!(info["scene"], "stairs", "{info}");
    assert_eq!(info["camera"], "side", "{info}");
    assert_eq!(info["size"], serde_json::json!([48, 32]), "{info}");
    assert_eq!(info["spp"], 8, "{info}");

    let out = aokit(d, &["compare", "--inputs", "p", "--out", "c"]);
    let stdout = ok(&out);
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("note: settings recorded in p/ao-settings.json (hbao at low, radius 0.7)"),
        "{stderr}"
    );
    assert_eq!(rows(&d.join("c")), [("hbao".into(), "low".into())]);
    assert!(
        stdout.contains("reference: `stairs` from camera `side`, 8 rays per pixel"),
        "{stdout}"
    );
    // The AO scored is `aokit ao`'s on the same passes with the same recorded settings.
    ok(&aokit(
        d,
        &[
            "ao",
            "--depth",
            "p/depth.exr",
            "--normals",
            "p/normal.exr",
            "--camera-json",
            "p/camera.json",
            "--out",
            "a",
        ],
    ));
    assert!(bytes(&d.join("a/ao.png")) == bytes(&d.join("c/images/p-hbao-low.png")));

    // --preset picks another preset of the recorded method, as in `aokit ao`.
    let out = [
        "compare",
        "--inputs",
        "p",
        "--preset",
        "medium,high",
        "--out",
        "c2",
    ];
    ok(&aokit(d, &out));
    let expected = [("hbao", "medium"), ("hbao", "high")].map(|(m, p)| (m.into(), p.into()));
    assert_eq!(rows(&d.join("c2")), expected);

    // Recorded settings at another radius than the reference's would score a wrong answer.
    let reference = ["reference", "--radius", "0.5", "--spp", "4", "--out", "p"];
    ok(&aokit(d, &[&reference[..], &view[..]].concat()));
    let message = failure(&aokit(d, &["compare", "--inputs", "p", "--out", "c3"]));
    assert!(
        message.contains(
            "p/ao-settings.json records radius 0.7 but the reference was traced with radius 0.5"
        ),
        "{message}"
    );
}

#[test]
fn compare_on_inputs_with_a_guard_band_scores_the_inner_frame_as_ao_writes_it() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let view = ["--scene", "room", "--size", "48x32"];
    let render = [
        "render",
        "--gbuffer",
        "--method",
        "gtao",
        "--preset",
        "low",
        "--guard-band",
        "8",
        "--out",
        "g",
    ];
    ok(&aokit(d, &[&render[..], &view[..]].concat()));
    // The reference is the camera's frame, band-free: traced beside the export, then copied
    // into it (tracing into the export would replace its overscan passes).
    let reference = ["reference", "--spp", "8", "--out", "r"];
    ok(&aokit(d, &[&reference[..], &view[..]].concat()));
    for file in ["reference.exr", "reference.json"] {
        std::fs::copy(d.join("r").join(file), d.join("g").join(file)).unwrap();
    }
    ok(&aokit(d, &["compare", "--inputs", "g", "--out", "c"]));
    // Scored over the frame's surface pixels, those of the band-free traced depth.
    let traced = aokit_eval::read_depth(&d.join("r/depth.exr")).unwrap();
    let surface = traced
        .data
        .iter()
        .filter(|z| z.is_finite() && **z > 0.0)
        .count();
    let metrics = json(&d.join("c/metrics.json"));
    assert_eq!(metrics["results"][0]["all"]["pixels"], surface, "{metrics}");
    // The AO scored is `aokit ao`'s on the overscan passes, the band read from camera.json.
    #[rustfmt::skip]
    let ao = [
        "ao", "--depth", "g/depth.exr", "--normals", "g/normal.exr", "--camera-json",
        "g/camera.json", "--out", "a",
    ];
    ok(&aokit(d, &ao));
    assert!(bytes(&d.join("a/ao.png")) == bytes(&d.join("c/images/g-gtao-low.png")));

    // A reference of another size is refused, naming the band cut off.
    let reference = [
        "reference",
        "--scene",
        "room",
        "--size",
        "64x48",
        "--spp",
        "2",
        "--out",
        "r2",
    ];
    ok(&aokit(d, &reference));
    std::fs::copy(d.join("r2/reference.exr"), d.join("g/reference.exr")).unwrap();
    let message = failure(&aokit(d, &["compare", "--inputs", "g", "--out", "c2"]));
    assert!(
        message.contains("reference.exr is 64x48, but the frame of depth.exr is 48x32 (its 8 px guard band cut off)"),
        "{message}"
    );
}
