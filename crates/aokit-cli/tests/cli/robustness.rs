//! Issue 29's bad inputs, each answered with a clear error or the right result: never a panic,
//! never a silently wrong answer. docs/reliability.md lists them with their messages.

use std::path::Path;
use std::process::{Output, Stdio};

use crate::common::{self, text};

fn aokit(dir: &Path, args: &[&str]) -> Output {
    // A cache of the test's own, so a run never reuses another's references.
    common::output(common::command(dir, args).env("AOKIT_CACHE", dir.join("cache")))
}

/// The error text of a run that must fail with exit code 2 (not 101, a panic).
fn refused(dir: &Path, args: &[&str]) -> String {
    let out = aokit(dir, args);
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    stderr
}

fn ok(dir: &Path, args: &[&str]) -> String {
    let out = aokit(dir, args);
    assert!(out.status.success(), "{args:?}: {}", text(&out.stderr));
    text(&out.stdout)
}

/// A small G-buffer export of the stairs: g/depth.exr, g/normal.exr, g/camera.json.
fn gbuffer(dir: &Path) {
    ok(
        dir,
        &[
            "render",
            "--scene",
            "stairs",
            "--size",
            "40x24",
            "--preset",
            "low",
            "--gbuffer",
            "--out",
            "g",
        ],
    );
}

fn exr(path: &Path) -> Vec<f32> {
    aokit_eval::read_scalar_exr(path).unwrap().data
}

/// Runs `args` with stdout a pipe whose reader has already gone, as `aokit ... | head -c1`
/// does once it has its byte (here before the first).
fn with_closed_stdout(dir: &Path, args: &[&str]) -> Output {
    let mut child = common::command(dir, args)
        .env("AOKIT_CACHE", dir.join("cache"))
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    child.wait_with_output().unwrap()
}

#[test]
fn closing_stdout_early_neither_panics_nor_stops_the_files() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let cases: [(&[&str], &str); 4] = [
        (
            &["render", "--size", "24x16", "--preset", "low", "--out", "r"],
            "r/ao.png",
        ),
        (
            &["reference", "--size", "24x16", "--spp", "2", "--out", "ref"],
            "ref/reference.png",
        ),
        (
            &[
                "compare",
                "--inputs",
                "ref",
                "--method",
                "gtao",
                "--preset",
                "low",
                "--timing-frames",
                "1",
                "--out",
                "cmp",
            ],
            "cmp/report.html",
        ),
        (
            &[
                "bench",
                "--json",
                "--size",
                "24x16",
                "--timing-frames",
                "1",
                "--warmup",
                "0",
            ],
            "",
        ),
    ];
    for (args, file) in cases {
        let out = with_closed_stdout(d, args);
        let stderr = text(&out.stderr);
        assert!(out.status.success(), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert!(
            file.is_empty() || d.join(file).is_file(),
            "{args:?}: no {file}"
        );
    }
}

#[test]
fn unusable_normals_and_a_zero_view_from_world_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    gbuffer(d);
    let pixels = 40 * 24;
    let zeros = vec![0.0f32; pixels];
    let channels = [("R", zeros.clone()), ("G", zeros.clone()), ("B", zeros)];
    aokit_eval::write_exr(&d.join("zero.exr"), [40, 24], &channels).unwrap();
    let err = refused(
        d,
        &[
            "ao",
            "--depth",
            "g/depth.exr",
            "--normals",
            "zero.exr",
            "--camera-json",
            "g/camera.json",
            "--method",
            "sao",
        ],
    );
    assert!(
        err.contains("pixels showing a surface have a normal that is zero"),
        "{err}"
    );

    let mut camera: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("g/camera.json")).unwrap()).unwrap();
    camera["view_from_world"] = serde_json::json!([[0.0f32; 4]; 4].to_vec());
    std::fs::write(d.join("zero-view.json"), camera.to_string()).unwrap();
    let err = refused(
        d,
        &[
            "ao",
            "--depth",
            "g/depth.exr",
            "--normals",
            "g/normal.exr",
            "--camera-json",
            "zero-view.json",
            "--normal-space",
            "world",
        ],
    );
    assert!(
        err.contains("zero-view.json") && err.contains("view_from_world"),
        "{err}"
    );
}

#[test]
fn ndc_depth_outside_zero_to_one_is_refused_with_the_count() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    gbuffer(d);
    // depth.exr holds linear depth: most of it is past 1.
    let err = refused(
        d,
        &[
            "ao",
            "--depth",
            "g/depth.exr",
            "--camera-json",
            "g/camera.json",
            "--depth-kind",
            "ndc",
        ],
    );
    assert!(
        err.contains("depth.exr") && err.contains("pixels hold depth outside [0, 1]"),
        "{err}"
    );
    assert!(err.contains("of 960 pixels"), "{err}");
}

#[test]
fn set_normals_space_world_is_applied_over_the_normal_space_flag() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    gbuffer(d);
    // The same normals in world space: view = R world, so world = R^T view.
    let camera: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("g/camera.json")).unwrap()).unwrap();
    let r = |i: usize, j: usize| camera["view_from_world"][i][j].as_f64().unwrap() as f32;
    let normals = aokit_eval::read_normals(&d.join("g/normal.exr"))
        .unwrap()
        .data;
    let mut world = [vec![], vec![], vec![]];
    for n in normals.chunks_exact(3) {
        for (j, channel) in world.iter_mut().enumerate() {
            channel.push((0..3).map(|i| r(i, j) * n[i]).sum());
        }
    }
    let [x, y, z] = world;
    aokit_eval::write_exr(
        &d.join("world.exr"),
        [40, 24],
        &[("R", x), ("G", y), ("B", z)],
    )
    .unwrap();
    let run = |out: &str, normals: &str, extra: &[&str]| -> Vec<f32> {
        let mut args = vec![
            "ao",
            "--depth",
            "g/depth.exr",
            "--normals",
            normals,
            "--camera-json",
            "g/camera.json",
            "--preset",
            "low",
            "--out",
            out,
        ];
        args.extend_from_slice(extra);
        ok(d, &args);
        exr(&d.join(out).join("ao.exr"))
    };
    let view = run("view", "g/normal.exr", &[]);
    let worst = |a: &[f32]| {
        a.iter()
            .zip(&view)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0f32, f32::max)
    };
    let set = run("set", "world.exr", &["--set", "normals.space=world"]);
    assert!(
        worst(&set) < 0.01,
        "--set normals.space=world: {}",
        worst(&set)
    );
    let flag = run("flag", "world.exr", &["--normal-space", "world"]);
    assert!(
        worst(&flag) < 0.01,
        "--normal-space world: {}",
        worst(&flag)
    );
    // --set is applied last: it wins over the flag.
    let both = run(
        "both",
        "g/normal.exr",
        &["--normal-space", "world", "--set", "normals.space=view"],
    );
    assert!(worst(&both) < 0.01, "flag and --set: {}", worst(&both));
    // The check can tell: world normals read as view normals give other AO.
    let wrong = run("wrong", "world.exr", &[]);
    assert!(worst(&wrong) > 0.05, "{}", worst(&wrong));
}

#[test]
fn reference_refuses_bad_planes_before_tracing() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (args, named) in [
        (&["--near=-1"][..], "near plane -1 must be positive"),
        (&["--near", "-1"][..], "near plane -1 must be positive"),
        (
            &["--near", "5", "--far", "2"][..],
            "far plane 2 must be finite and greater than the near plane (5)",
        ),
    ] {
        let mut all = vec!["reference", "--size", "16x8", "--spp", "1", "--out", "r"];
        all.extend_from_slice(args);
        let err = refused(d, &all);
        assert!(err.contains(named), "{args:?}: {err}");
        assert!(!d.join("r/camera.json").exists(), "{args:?}");
    }
}

#[test]
fn sizes_past_the_pixel_budget_are_refused_up_front() {
    let dir = tempfile::tempdir().unwrap();
    for command in ["render", "reference", "bench"] {
        let err = refused(dir.path(), &[command, "--size", "16384x16384"]);
        assert!(
            err.contains("268435456 pixels") && err.contains("67108864"),
            "{command}: {err}"
        );
    }
}

#[test]
fn a_nan_in_the_reference_is_refused_naming_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    ok(
        d,
        &["reference", "--size", "24x16", "--spp", "2", "--out", "ref"],
    );
    let mut ao = exr(&d.join("ref/reference.exr"));
    ao[5] = f32::NAN;
    ao[6] = f32::INFINITY;
    aokit_eval::write_exr(&d.join("ref/reference.exr"), [24, 16], &[("Y", ao)]).unwrap();
    let err = refused(
        d,
        &[
            "compare", "--inputs", "ref", "--method", "gtao", "--preset", "low", "--out", "c",
        ],
    );
    assert!(
        err.contains("reference.exr: 2 of 384 pixels are not finite"),
        "{err}"
    );
}

#[test]
fn an_out_that_is_a_file_is_refused_before_the_work() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("taken"), "a file").unwrap();
    for args in [
        &["render", "--size", "16x8", "--out", "taken"][..],
        &[
            "reference",
            "--size",
            "16x8",
            "--spp",
            "1",
            "--out",
            "taken",
        ][..],
        &[
            "reference",
            "--size",
            "16x8",
            "--spp",
            "1",
            "--out",
            "taken/below",
        ][..],
    ] {
        let err = refused(d, args);
        assert!(
            err.contains("--out taken") && err.contains("is a file")
                || err.contains("a file of that name exists"),
            "{args:?}: {err}"
        );
        assert!(!err.contains("tracing"), "{args:?}: {err}");
    }
}

#[test]
fn negative_numbers_are_values_not_flags() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    ok(
        d,
        &[
            "render", "--size", "16x8", "--preset", "low", "--eye", "0,1,3", "--target", "-6,1,-2",
            "--up", "-0,1,0",
        ],
    );
    for (args, named) in [
        (
            &["reference", "--spp", "-1"][..],
            "rays per pixel must be at least 1, got -1",
        ),
        (
            &["render", "--size", "-64x48"][..],
            "width and height must be at least 1",
        ),
        (&["render", "--radius", "-1"][..], "radius"),
        (&["render", "--near", "-1"][..], "near plane -1"),
        (&["bench", "--timing-frames", "-1"][..], "-1"),
    ] {
        let err = refused(d, args);
        assert!(!err.contains("unexpected argument"), "{args:?}: {err}");
        assert!(err.contains(named), "{args:?}: {err}");
    }
}

#[test]
fn unclear_messages_now_name_the_problem() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let err = refused(d, &["render", "--eye", "0,1,1e20", "--target", "0,0,0"]);
    assert!(err.contains("too far apart"), "{err}");
    let err = refused(
        d,
        &[
            "render", "--eye", "0,1,3", "--target", "0,0,0", "--up", "0,0,0",
        ],
    );
    assert!(err.contains("up [0, 0, 0] has no direction"), "{err}");

    // A bad value in a settings file names the file.
    std::fs::write(d.join("bad.toml"), "radius = -1.0\n").unwrap();
    let err = refused(d, &["render", "--size", "16x8", "--settings", "bad.toml"]);
    assert!(err.contains("bad.toml") && err.contains("radius"), "{err}");

    // bench --compare blames the configuration that set its own size.
    let err = refused(
        d,
        &[
            "bench",
            "--timing-frames",
            "1",
            "--warmup",
            "0",
            "--compare=--size 16x8",
            "--compare=--method hbao",
        ],
    );
    assert!(err.contains("configuration 1 (`--size 16x8`)"), "{err}");

    // ndc_offset with three entries says so.
    gbuffer(d);
    let mut camera: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("g/camera.json")).unwrap()).unwrap();
    camera["ndc_offset"] = serde_json::json!([0.0, 0.0, 0.0]);
    std::fs::write(d.join("three.json"), camera.to_string()).unwrap();
    let err = refused(
        d,
        &[
            "ao",
            "--depth",
            "g/depth.exr",
            "--camera-json",
            "three.json",
        ],
    );
    assert!(
        err.contains("three.json") && err.contains("ndc_offset must have 2 entries (x, y), got 3"),
        "{err}"
    );
}
