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
