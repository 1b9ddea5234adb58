//! `aokit reference`, `aokit ao` and `aokit compare`, run in fresh temporary directories.

use std::path::Path;
use std::process::Output;

use crate::common::{command, output, text};

fn aokit(dir: &Path, args: &[&str]) -> Output {
    // A cache of the test's own, so a run never reuses another's references.
    output(command(dir, args).env("AOKIT_CACHE", dir.join("cache")))
}

fn ok(dir: &Path, args: &[&str]) -> String {
    let out = aokit(dir, args);
    assert!(
        out.status.success(),
        "aokit {args:?} failed: {}",
        text(&out.stderr)
    );
    text(&out.stdout)
}

fn exr(path: &Path) -> Vec<f32> {
    aokit_eval::read_scalar_exr(path).unwrap().data
}

/// Mean of `|a - b|` over every pixel.
fn mean_abs_difference(a: &[f32], b: &[f32]) -> f32 {
    a.iter().zip(b).map(|(x, y)| (x - y).abs()).sum::<f32>() / a.len() as f32
}

#[test]
fn reference_writes_the_ground_truth_and_the_gbuffer_deterministically() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let args = |out: &'static str, seed: &'static str| {
        [
            "reference",
            "--scene",
            "room",
            "--size",
            "48x32",
            "--spp",
            "32",
            "--seed",
            seed,
            "--out",
            out,
        ]
    };
    let stdout = ok(d, &args("a", "5"));
    assert!(stdout.contains("rays per pixel"), "{stdout}");
    for file in [
        "reference.exr",
        "reference.png",
        "depth.exr",
        "normal.exr",
        "camera.json",
        "back_depth.exr",
        "reference.json",
    ] {
        assert!(d.join("a").join(file).is_file(), "{file} missing");
    }
    let info: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("a/reference.json")).unwrap())
            .unwrap();
    assert_eq!(info["spp"], 32);
    assert_eq!(info["falloff"], "none");
    let a = exr(&d.join("a/reference.exr"));
    assert_eq!(a.len(), 48 * 32);
    assert!(a.iter().all(|v| (0.0..=1.0).contains(v)));
    assert!(a.iter().any(|&v| v < 0.5), "the room has dark corners");

    ok(d, &args("b", "5"));
    assert_eq!(a, exr(&d.join("b/reference.exr")), "same seed, same image");
    ok(d, &args("c", "6"));
    assert_ne!(
        a,
        exr(&d.join("c/reference.exr")),
        "another seed, other noise"
    );

    // The raster's G-buffer of the same view holds the same depth.
    ok(
        d,
        &[
            "render",
            "--scene",
            "room",
            "--size",
            "48x32",
            "--gbuffer",
            "--out",
            "r",
        ],
    );
    let raster = aokit_eval::read_depth(&d.join("r/depth.exr")).unwrap().data;
    let traced = aokit_eval::read_depth(&d.join("a/depth.exr")).unwrap().data;
    let agree = raster
        .iter()
        .zip(&traced)
        .filter(|(r, t)| (*r - *t).abs() <= 1e-4 * r.max(**t))
        .count();
    assert!(
        agree * 1000 >= raster.len() * 999,
        "{agree} of {} agree",
        raster.len()
    );
}

#[test]
fn ao_on_exported_passes_matches_render_itself() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    ok(
        d,
        &[
            "render",
            "--scene",
            "stairs",
            "--size",
            "80x48",
            "--radius",
            "0.5",
            "--gbuffer",
            "--out",
            "g",
        ],
    );
    let stdout = ok(
        d,
        &[
            "ao",
            "--depth",
            "g/depth.exr",
            "--normals",
            "g/normal.exr",
            "--camera-json",
            "g/camera.json",
            "--radius",
            "0.5",
            "--out",
            "a",
        ],
    );
    assert!(stdout.contains("normals from file"), "{stdout}");
    let rendered = exr(&d.join("g/ao.exr"));
    let recomputed = exr(&d.join("a/ao.exr"));
    // Exported depth is the pipeline's own linear depth, and oct32 normals survive the round
    // trip through float: the AO is the same to the bit.
    assert_eq!(rendered, recomputed);
    assert!(d.join("a/ao.png").is_file());

    // Without normals they are reconstructed from depth, and AO stays close.
    let stdout = ok(
        d,
        &[
            "ao",
            "--depth",
            "g/depth.exr",
            "--camera-json",
            "g/camera.json",
            "--radius",
            "0.5",
            "--out",
            "n",
        ],
    );
    assert!(stdout.contains("reconstructed from depth"), "{stdout}");
    let reconstructed = exr(&d.join("n/ao.exr"));
    let mean_difference = mean_abs_difference(&rendered, &reconstructed);
    assert!(mean_difference < 0.05, "mean difference {mean_difference}");
}

/// Writes `values` (H x W float32) as .npy version 1.0.
fn write_npy(path: &Path, shape: &[usize], values: &[f32]) {
    let dims = shape.iter().map(|d| format!("{d}, ")).collect::<String>();
    let mut header = format!("{{'descr': '<f4', 'fortran_order': False, 'shape': ({dims}), }}");
    while (10 + header.len() + 1) % 64 != 0 {
        header.push(' ');
    }
    header.push('\n');
    let mut bytes = b"\x93NUMPY\x01\x00".to_vec();
    bytes.extend((header.len() as u16).to_le_bytes());
    bytes.extend(header.as_bytes());
    for v in values {
        bytes.extend(v.to_le_bytes());
    }
    std::fs::write(path, bytes).unwrap();
}

#[test]
fn ao_reads_numpy_depth_with_infinite_background_and_ndc_depth() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    ok(
        d,
        &[
            "render",
            "--scene",
            "room",
            "--size",
            "64x40",
            "--gbuffer",
            "--out",
            "g",
        ],
    );
    let depth = aokit_eval::read_depth(&d.join("g/depth.exr")).unwrap().data;
    let infinite_sky: Vec<f32> = depth
        .iter()
        .map(|&z| if z > 0.0 { z } else { f32::INFINITY })
        .collect();
    write_npy(&d.join("depth.npy"), &[40, 64], &infinite_sky);
    ok(
        d,
        &[
            "ao",
            "--depth",
            "depth.npy",
            "--camera-json",
            "g/camera.json",
            "--out",
            "npy",
        ],
    );
    let ao = exr(&d.join("npy/ao.exr"));
    assert!(ao.iter().all(|v| v.is_finite() && (0.0..=1.0).contains(v)));

    // The same depth as depth-buffer values (reverse-Z, infinite far: ndc = near / depth).
    let camera: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("g/camera.json")).unwrap()).unwrap();
    let near = camera["near"].as_f64().unwrap() as f32;
    let ndc: Vec<f32> = depth
        .iter()
        .map(|&z| if z > 0.0 { near / z } else { 0.0 })
        .collect();
    write_npy(&d.join("ndc.npy"), &[40, 64, 1], &ndc);
    ok(
        d,
        &[
            "ao",
            "--depth",
            "ndc.npy",
            "--depth-kind",
            "ndc",
            "--camera-json",
            "g/camera.json",
            "--out",
            "ndc",
        ],
    );
    let from_ndc = exr(&d.join("ndc/ao.exr"));
    let worst = ao
        .iter()
        .zip(&from_ndc)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0f32, f32::max);
    assert!(worst < 0.05, "linear and NDC depth give AO {worst} apart");
}

#[test]
fn ao_refuses_bad_passes_with_the_reason() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    ok(
        d,
        &[
            "render",
            "--scene",
            "open",
            "--size",
            "32x24",
            "--gbuffer",
            "--out",
            "g",
        ],
    );
    std::fs::write(d.join("junk.exr"), b"not an exr").unwrap();
    std::fs::write(d.join("camera-bad.json"), b"{\"width\": 3}").unwrap();
    write_npy(&d.join("small.npy"), &[2, 2], &[1.0; 4]);
    let cases: &[(&[&str], &str)] = &[
        (
            &[
                "ao",
                "--depth",
                "missing.exr",
                "--camera-json",
                "g/camera.json",
            ],
            "missing.exr",
        ),
        (
            &[
                "ao",
                "--depth",
                "junk.exr",
                "--camera-json",
                "g/camera.json",
            ],
            "junk.exr",
        ),
        (
            &[
                "ao",
                "--depth",
                "g/depth.exr",
                "--camera-json",
                "camera-bad.json",
            ],
            "camera-bad.json",
        ),
        (
            &[
                "ao",
                "--depth",
                "small.npy",
                "--camera-json",
                "g/camera.json",
            ],
            "2x2",
        ),
        (
            &[
                "ao",
                "--depth",
                "g/depth.exr",
                "--normals",
                "small.npy",
                "--camera-json",
                "g/camera.json",
            ],
            "small.npy",
        ),
        (&["reference", "--spp", "0"], "rays per pixel"),
        (&["reference", "--falloff-curve", "cubic"], "cubic"),
        (
            &["compare", "--inputs", "g", "--method", "gtao"],
            "reference.exr",
        ),
    ];
    for (args, expected) in cases {
        let out = aokit(d, args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(
            stderr.contains(expected),
            "{args:?}: expected `{expected}` in: {stderr}"
        );
    }
}

#[test]
fn compare_scores_gtao_against_a_cached_reference_and_writes_the_report() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let args = [
        "compare",
        "--scene",
        "room",
        "--method",
        "gtao",
        "--size",
        "64x40",
        "--spp",
        "64",
        "--preset",
        "low,high",
        "--timing-frames",
        "2",
        "--out",
        "cmp",
    ];
    let first = aokit(d, &args);
    assert!(
        first.status.success(),
        "{}",
        String::from_utf8_lossy(&first.stderr)
    );
    assert!(String::from_utf8_lossy(&first.stderr).contains("traced"));
    for file in ["metrics.csv", "metrics.md", "metrics.json", "report.html"] {
        assert!(d.join("cmp").join(file).is_file(), "{file} missing");
    }
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("cmp/metrics.json")).unwrap())
            .unwrap();
    let results = json["results"].as_array().unwrap();
    assert_eq!(results.len(), 2);
    for r in results {
        assert_eq!(r["method"], "gtao");
        // Measured on lavapipe: MAE 0.050 at low and 0.026 at high (AO 1 everywhere scores
        // about 0.2): a ceiling 1.2 times each, and high below low.
        let mae = r["all"]["mae"].as_f64().unwrap();
        let ceiling = if r["preset"] == "low" { 0.060 } else { 0.032 };
        assert!(mae > 0.0 && mae < ceiling, "{}: MAE {mae}", r["preset"]);
        assert!(r["edges"]["pixels"].as_u64().unwrap() > 0);
    }
    let mae = |i: usize| results[i]["all"]["mae"].as_f64().unwrap();
    assert!(mae(1) < mae(0), "high is closer to the reference than low");
    let csv = std::fs::read_to_string(d.join("cmp/metrics.csv")).unwrap();
    assert_eq!(csv.lines().count(), 3, "{csv}");
    let html = std::fs::read_to_string(d.join("cmp/report.html")).unwrap();
    assert!(html.contains("data:image/png;base64,") && html.contains("<svg"));
    for image in [
        "room-front-reference.png",
        "room-front-gtao-low.png",
        "room-front-gtao-high-error.png",
    ] {
        assert!(
            d.join("cmp/images").join(image).is_file(),
            "{image} missing"
        );
    }

    // The second run finds the reference in the cache, and scores identically.
    let second = aokit(d, &[&args[..args.len() - 1], &["cmp2"]].concat());
    assert!(String::from_utf8_lossy(&second.stderr).contains("cached"));
    let again: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("cmp2/metrics.json")).unwrap())
            .unwrap();
    for (a, b) in results.iter().zip(again["results"].as_array().unwrap()) {
        assert_eq!(a["all"], b["all"]);
    }
}

#[test]
fn compare_on_exported_passes_scores_like_compare_on_the_scene() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // `aokit reference` writes passes and reference.exr side by side: the --inputs layout.
    ok(
        d,
        &[
            "reference",
            "--scene",
            "stairs",
            "--size",
            "64x40",
            "--spp",
            "64",
            "--out",
            "ref",
        ],
    );
    ok(
        d,
        &[
            "compare", "--inputs", "ref", "--preset", "medium", "--out", "in",
        ],
    );
    ok(
        d,
        &[
            "compare", "--scene", "stairs", "--size", "64x40", "--spp", "64", "--preset", "medium",
            "--out", "sc",
        ],
    );
    let maes = |path: &str| -> Vec<(String, f64)> {
        let json: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(d.join(path)).unwrap()).unwrap();
        json["results"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| {
                (
                    r["method"].as_str().unwrap().to_string(),
                    r["all"]["mae"].as_f64().unwrap(),
                )
            })
            .collect()
    };
    let (inputs, scene) = (maes("in/metrics.json"), maes("sc/metrics.json"));
    assert_eq!(inputs.len(), aokit::Method::ALL.len());
    // The passes differ only in their normals: geometric from the tracer, shading from the
    // raster; on the stairs' flat faces those are the same.
    for ((method, a), (_, b)) in inputs.iter().zip(&scene) {
        assert!(
            (a - b).abs() < 0.01,
            "{method}: --inputs MAE {a}, scene MAE {b}"
        );
    }

    // The traced back faces stand in for the rasterised ones: VBAO measuring its occluders
    // from them scores the same, and differently from its constant thickness.
    let back_faces = ["--method", "vbao", "--set", "vbao.back_faces=true"];
    let with = |source: &[&str], out: &str| {
        let mut args = vec!["compare", "--preset", "medium", "--out", out];
        args.extend(source);
        args.extend(back_faces);
        ok(d, &args);
        maes(&format!("{out}/metrics.json"))[0].1
    };
    let inputs = with(&["--inputs", "ref"], "in-back");
    let scene = with(
        &["--scene", "stairs", "--size", "64x40", "--spp", "64"],
        "sc-back",
    );
    assert!(
        (inputs - scene).abs() < 0.005,
        "vbao.back_faces: --inputs MAE {inputs}, scene MAE {scene}"
    );
    let constant = maes("in/metrics.json")
        .into_iter()
        .find(|(method, _)| method == "vbao")
        .unwrap()
        .1;
    assert!(
        (inputs - constant).abs() > 1e-4,
        "back faces changed nothing: {inputs} against {constant}"
    );
}

#[test]
fn compare_scores_sequences_along_camera_paths() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let args = |path: &'static str, out: &'static str| {
        [
            "compare",
            "--scene",
            "room",
            "--method",
            "gtao",
            "--preset",
            "medium",
            "--size",
            "48x32",
            "--spp",
            "32",
            "--frames",
            "4",
            "--path",
            path,
            "--set",
            "temporal.enabled=true",
            "--timing-frames",
            "0",
            "--out",
            out,
        ]
    };
    ok(d, &args("still", "still"));
    ok(d, &args("strafe", "strafe"));
    let sequence = |dir: &str| -> serde_json::Value {
        let json: serde_json::Value = serde_json::from_str(
            &std::fs::read_to_string(d.join(dir).join("metrics.json")).unwrap(),
        )
        .unwrap();
        json["results"][0]["sequence"].clone()
    };
    let (still, strafe) = (sequence("still"), sequence("strafe"));
    assert_eq!(still["frames"], 4);
    assert_eq!(
        still["disoccluded"]["pixels"], 0,
        "a still camera reveals nothing"
    );
    assert!(strafe["disoccluded"]["pixels"].as_u64().unwrap() > 0);
    assert!(still["flicker"].as_f64().unwrap() < strafe["flicker"].as_f64().unwrap());
    let md = std::fs::read_to_string(d.join("still/metrics.md")).unwrap();
    assert!(
        md.contains("Flicker") && md.contains("4 frames, still"),
        "{md}"
    );
    let refused = aokit(d, &["compare", "--inputs", "still", "--frames", "3"]);
    assert_eq!(refused.status.code(), Some(2));
}

#[test]
fn ao_measures_vbao_occluders_from_a_back_face_depth_file() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let stdout = ok(
        d,
        &[
            "render",
            "--scene",
            "room",
            "--size",
            "64x40",
            "--method",
            "vbao",
            "--set",
            "vbao.back_faces=true",
            "--gbuffer",
            "--out",
            "g",
        ],
    );
    assert!(stdout.contains("back_depth.exr"), "{stdout}");
    // The exported back faces lie behind the front ones, and give the AO render gave.
    let front = aokit_eval::read_depth(&d.join("g/depth.exr")).unwrap().data;
    let back = aokit_eval::read_depth(&d.join("g/back_depth.exr"))
        .unwrap()
        .data;
    for (i, (f, b)) in front.iter().zip(&back).enumerate() {
        assert!(
            *b == 0.0 || *b >= f * 0.999,
            "pixel {i}: back {b}, front {f}"
        );
    }
    assert!(back.iter().filter(|&&b| b > 0.0).count() > back.len() / 10);
    ok(
        d,
        &[
            "ao",
            "--depth",
            "g/depth.exr",
            "--normals",
            "g/normal.exr",
            "--back-depth",
            "g/back_depth.exr",
            "--camera-json",
            "g/camera.json",
            "--method",
            "vbao",
            "--set",
            "vbao.back_faces=true",
            "--out",
            "again",
        ],
    );
    let (rendered, again) = (exr(&d.join("g/ao.exr")), exr(&d.join("again/ao.exr")));
    let difference = mean_abs_difference(&rendered, &again);
    assert!(difference < 0.002, "mean difference {difference}");
    // Every surface 5 units deep: solid, as the room's sphere and boxes are.
    let depth = aokit_eval::read_depth(&d.join("g/depth.exr")).unwrap().data;
    let deep: Vec<f32> = depth
        .iter()
        .map(|&z| if z > 0.0 { z + 5.0 } else { 0.0 })
        .collect();
    write_npy(&d.join("back.npy"), &[40, 64], &deep);
    let ao = |extra: &[&str], out: &str| {
        let mut args = vec![
            "ao",
            "--depth",
            "g/depth.exr",
            "--camera-json",
            "g/camera.json",
            "--method",
            "vbao",
            "--out",
            out,
        ];
        args.extend_from_slice(extra);
        aokit(d, &args)
    };
    let measured = ["--set", "vbao.back_faces=true"];
    let refused = ao(&measured, "refused");
    assert_eq!(refused.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert!(
        stderr.contains("vbao.back_faces") && stderr.contains("back_depth"),
        "{stderr}"
    );
    assert!(ao(&[], "assumed").status.success());
    let with_file = [&measured[..], &["--back-depth", "back.npy"]].concat();
    assert!(ao(&with_file, "measured").status.success());
    let mean = |out: &str| {
        let ao = exr(&d.join(out).join("ao.exr"));
        ao.iter().sum::<f32>() / ao.len() as f32
    };
    let (assumed, measured) = (mean("assumed"), mean("measured"));
    assert!(
        measured < assumed - 0.005,
        "mean AO {measured} with deep back faces, {assumed} with the assumed thickness"
    );
}

#[test]
fn compare_with_a_guard_band_scores_the_frame_closer_to_the_reference() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let rmse = |band: &str| -> f64 {
        let out = format!("band-{band}");
        #[rustfmt::skip]
        ok(d, &[
            "compare", "--scene", "room", "--size", "96x54", "--spp", "32", "--method", "gtao",
            "--preset", "high", "--timing-frames", "0", "--cache", "cache", "--guard-band", band,
            "--out", &out,
        ]);
        let json: serde_json::Value = serde_json::from_str(
            &std::fs::read_to_string(d.join(out).join("metrics.json")).unwrap(),
        )
        .unwrap();
        json["results"][0]["all"]["rmse"].as_f64().unwrap()
    };
    // Room's walls run out of the frame: a 16 px band shows the kernel what lies beyond.
    let (without, with) = (rmse("0"), rmse("16"));
    assert!(
        with < 0.95 * without,
        "RMSE {with} with a 16 px band, {without} without"
    );
    // The passes of --inputs carry their own band.
    let out = aokit(d, &["compare", "--inputs", "p", "--guard-band", "8"]);
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("'--inputs <DIR>' cannot be used with '--guard-band <PX>'"),
        "{stderr}"
    );
}
