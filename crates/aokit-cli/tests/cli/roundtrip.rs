//! `render --gbuffer` then `aokit ao` on what it wrote: the same AO, to the byte, with the
//! settings render recorded beside camera.json; single frames and sequences.

use std::path::Path;

use crate::common::{aokit, ok, text};

fn run(dir: &Path, args: &[&str]) -> String {
    ok(&aokit(dir, args))
}

fn bytes(path: &Path) -> Vec<u8> {
    std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn exr(path: &Path) -> Vec<f32> {
    aokit_eval::read_scalar_exr(path).unwrap().data
}

#[test]
fn ao_on_render_gbuffer_is_render_to_the_byte_with_the_recorded_settings() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // Neither the method, the preset, the radius nor the overrides are the defaults.
    let cases: [(&str, &[&str]); 2] = [
        (
            "stairs",
            &[
                "--method",
                "hbao",
                "--preset",
                "low",
                "--radius",
                "0.7",
                "--set",
                "hbao.direction_count=3",
            ],
        ),
        (
            "room",
            &[
                "--method",
                "vbao",
                "--preset",
                "high",
                "--radius",
                "0.35",
                "--set",
                "spatial.enabled=true",
            ],
        ),
    ];
    for (scene, settings) in cases {
        let (g, a) = (format!("{scene}-g"), format!("{scene}-a"));
        let mut render = vec!["render", "--scene", scene, "--size", "64x40", "--gbuffer"];
        render.extend(settings);
        render.extend(["--out", &g]);
        run(d, &render);
        let stdout = run(
            d,
            &[
                "ao",
                "--depth",
                &format!("{g}/depth.exr"),
                "--normals",
                &format!("{g}/normal.exr"),
                "--camera-json",
                &format!("{g}/camera.json"),
                "--out",
                &a,
            ],
        );
        assert!(stdout.contains("settings recorded in"), "{stdout}");
        for file in ["ao.exr", "ao.png"] {
            assert!(
                bytes(&d.join(&g).join(file)) == bytes(&d.join(&a).join(file)),
                "{scene}: {file} differs between render and ao"
            );
        }
    }
}

#[test]
fn flags_override_the_recorded_settings_in_the_documented_order() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    run(
        d,
        &[
            "render",
            "--scene",
            "stairs",
            "--size",
            "48x32",
            "--gbuffer",
            "--method",
            "hbao",
            "--preset",
            "low",
            "--radius",
            "0.7",
            "--out",
            "g",
        ],
    );
    let ao = |extra: &[&str]| -> String {
        let mut args = vec![
            "ao",
            "--depth",
            "g/depth.exr",
            "--camera-json",
            "g/camera.json",
            "--out",
            "a",
        ];
        args.extend(extra);
        run(d, &args)
    };
    assert!(ao(&[]).contains("with hbao (radius 0.7, settings recorded in g/ao-settings.json)"));
    // `--radius` and `--set` apply over the record, `--set` last.
    assert!(ao(&["--radius", "2"]).contains("with hbao (radius 2,"));
    assert!(ao(&["--radius", "2", "--set", "radius=3"]).contains("(radius 3,"));
    // Another method or preset starts from its preset, keeping the recorded radius.
    assert!(ao(&["--method", "gtao"]).contains("with gtao (radius 0.7,"));
    assert!(ao(&["--preset", "high"]).contains("with hbao (radius 0.7,"));
    std::fs::write(d.join("s.toml"), "radius = 1.5\n").unwrap();
    assert!(ao(&["--settings", "s.toml"]).contains("(radius 1.5,"));

    // A record that is not one is refused, naming the file and the key.
    std::fs::write(
        d.join("g/ao-settings.json"),
        r#"{"preset": "low", "settings": {"radius": 0.7, "gtao": {"slicecount": 2}}}"#,
    )
    .unwrap();
    let out = aokit(
        d,
        &[
            "ao",
            "--depth",
            "g/depth.exr",
            "--camera-json",
            "g/camera.json",
        ],
    );
    let stderr = text(&out.stderr);
    assert!(!out.status.success());
    assert!(
        stderr.contains("ao-settings.json") && stderr.contains("gtao.slicecount"),
        "{stderr}"
    );
    // Without a record, the defaults: radius 1.
    std::fs::remove_file(d.join("g/ao-settings.json")).unwrap();
    let stdout = ao(&[]);
    assert!(stdout.contains("(radius 1)"), "{stdout}");
}

#[test]
fn renamed_flags_still_work_and_warn() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    run(
        d,
        &[
            "render",
            "--scene",
            "stairs",
            "--size",
            "32x24",
            "--gbuffer",
            "--out",
            "g",
        ],
    );
    let out = aokit(
        d,
        &["ao", "--depth", "g/depth.exr", "--camera", "g/camera.json"],
    );
    ok(&out);
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("`aokit ao --camera` is now `--camera-json`"),
        "{stderr}"
    );
    let out = aokit(
        d,
        &[
            "reference",
            "--scene",
            "stairs",
            "--size",
            "16x12",
            "--spp",
            "4",
            "--falloff",
            "linear",
            "--out",
            "r",
        ],
    );
    ok(&out);
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("`aokit reference --falloff` is now `--falloff-curve`"),
        "{stderr}"
    );
}

#[test]
fn ao_on_a_rendered_sequence_is_render_frame_by_frame() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let sequence = |out: &str, settings: &[&str]| {
        let mut render = vec![
            "render",
            "--scene",
            "room",
            "--size",
            "64x40",
            "--frames",
            "3",
            "--path",
            "orbit",
            "--gbuffer",
            "--method",
            "gtao",
            "--radius",
            "0.8",
        ];
        render.extend(settings);
        render.extend(["--out", out]);
        run(d, &render);
        let ao_out = format!("{out}-ao");
        let stdout = run(
            d,
            &[
                "ao",
                "--sequence",
                &format!("{out}/frames"),
                "--out",
                &ao_out,
            ],
        );
        assert!(stdout.contains("AO of 3 frames"), "{stdout}");
        (d.join(out), d.join(ao_out))
    };
    // Each frame on its own (a sequence runs the temporal filter by default): the same bytes.
    let (rendered, recomputed) = sequence("still", &["--set", "temporal.enabled=false"]);
    for i in 0..3 {
        let name = format!("frames/ao-{i:03}.png");
        assert!(
            bytes(&rendered.join(&name)) == bytes(&recomputed.join(&name)),
            "{name} differs"
        );
    }
    assert!(bytes(&rendered.join("ao.exr")) == bytes(&recomputed.join("ao.exr")));

    // With the temporal filter, the first frame is the same; later ones reproject from the
    // cameras alone where render had the raster's half-float motion vectors, which differ in
    // the last bits, so the history lands a little apart.
    let (rendered, recomputed) = sequence("temporal", &[]);
    assert!(
        bytes(&rendered.join("frames/ao-000.png")) == bytes(&recomputed.join("frames/ao-000.png"))
    );
    let (a, b) = (
        exr(&rendered.join("ao.exr")),
        exr(&recomputed.join("ao.exr")),
    );
    let mean = a.iter().zip(&b).map(|(x, y)| (x - y).abs()).sum::<f32>() / a.len() as f32;
    let max = a
        .iter()
        .zip(&b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f32::max);
    eprintln!("temporal sequence, last frame: mean |difference| {mean}, max {max}");
    // Measured: mean 1.6e-5, max 0.0016 (room, 64x40, orbit).
    assert!(mean < 1e-3 && max < 0.02, "mean {mean}, max {max}");
    // One frame with the temporal filter recorded on: the filter has nothing to accumulate.
    let out = aokit(
        d,
        &[
            "ao",
            "--depth",
            "temporal/depth.exr",
            "--camera-json",
            "temporal/camera.json",
            "--out",
            "one",
        ],
    );
    ok(&out);
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("temporal filter accumulates over a sequence (--sequence DIR)"),
        "{stderr}"
    );
}

#[test]
fn a_guard_band_round_trips_through_camera_json_and_reaches_the_border() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // VBAO with back faces: the back-face depth is written with the band too.
    let settings = ["--method", "vbao", "--set", "vbao.back_faces=true"];
    let render = |band: &str, out: &str| {
        let mut args = vec!["render", "--scene", "room", "--size", "64x40", "--gbuffer"];
        args.extend(settings);
        args.extend(["--guard-band", band, "--out", out]);
        run(d, &args)
    };
    render("0", "plain");
    render("8", "g");
    let depth = aokit_eval::read_depth(&d.join("g/depth.exr")).unwrap();
    assert_eq!([depth.width, depth.height], [80, 56]);
    let back = aokit_eval::read_depth(&d.join("g/back_depth.exr")).unwrap();
    assert_eq!([back.width, back.height], [80, 56]);
    let camera = std::fs::read_to_string(d.join("g/camera.json")).unwrap();
    assert!(camera.contains("\"guard_band\": 8"), "{camera}");
    assert!(camera.contains("\"width\": 64"), "{camera}");
    let plain_camera = std::fs::read_to_string(d.join("plain/camera.json")).unwrap();
    assert!(!plain_camera.contains("guard_band"), "{plain_camera}");
    let files = [
        "ao",
        "--depth",
        "g/depth.exr",
        "--normals",
        "g/normal.exr",
        "--back-depth",
        "g/back_depth.exr",
        "--camera-json",
        "g/camera.json",
    ];
    let mut ao = files.to_vec();
    ao.extend(["--out", "a"]);
    run(d, &ao);
    for file in ["ao.exr", "ao.png"] {
        assert!(
            bytes(&d.join("g").join(file)) == bytes(&d.join("a").join(file)),
            "{file} differs between render and ao with a guard band"
        );
    }
    // The band reaches the border: the AO there differs from the AO without one.
    let (banded, plain) = (exr(&d.join("a/ao.exr")), exr(&d.join("plain/ao.exr")));
    assert_eq!(banded.len(), 64 * 40);
    let changed = banded.iter().zip(&plain).filter(|(a, b)| a != b).count();
    assert!(changed > 0, "a guard band changed no pixel");

    // A band the images do not have is refused, naming the sizes.
    let mut wrong = files.to_vec();
    wrong.extend(["--guard-band", "4", "--out", "w"]);
    let out = aokit(d, &wrong);
    assert!(!out.status.success());
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("80x56") && stderr.contains("72x48 with a guard band of 4 px"),
        "{stderr}"
    );
    // Half resolution needs an even band.
    let mut odd = vec!["render", "--scene", "room", "--size", "64x40"];
    odd.extend([
        "--set",
        "resolution=half",
        "--guard-band",
        "3",
        "--out",
        "o",
    ]);
    let out = aokit(d, &odd);
    assert!(!out.status.success());
    let stderr = text(&out.stderr);
    assert!(stderr.contains("multiple of the scale (2)"), "{stderr}");
}
