//! The `aokit` binary, run in fresh temporary directories.

use std::path::Path;

use crate::common::{aokit, command, output, text};

fn read_exr_channel(path: &Path, name: &str) -> (Vec<f32>, [usize; 2]) {
    use exr::prelude::*;
    let image = read_all_flat_layers_from_file(path).unwrap();
    let layer = &image.layer_data[0];
    let channel = layer
        .channel_data
        .list
        .iter()
        .find(|c| c.name == *name)
        .unwrap_or_else(|| panic!("{} has no channel {name}", path.display()));
    let values = channel.sample_data.values_as_f32().collect();
    (values, [layer.size.0, layer.size.1])
}

#[test]
fn render_without_arguments_writes_the_default_scene_to_aokit_out() {
    let dir = tempfile::tempdir().unwrap();
    let out = aokit(dir.path(), &["render"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    assert!(
        stdout.contains("aokit-out") && stdout.contains("room"),
        "{stdout}"
    );
    for file in ["ao.png", "ao.exr", "lit.png"] {
        assert!(
            dir.path().join("aokit-out").join(file).is_file(),
            "{file} missing"
        );
    }
    let ao = image::open(dir.path().join("aokit-out/ao.png")).unwrap();
    assert_eq!((ao.width(), ao.height()), (1280, 720));
    assert_eq!(ao.color(), image::ColorType::L8);
}

#[test]
fn a_machine_without_xdg_runtime_dir_gets_no_wayland_warning() {
    let dir = tempfile::tempdir().unwrap();
    let mut run = command(dir.path(), &["render", "--size", "32x24"]);
    run.env_remove("XDG_RUNTIME_DIR");
    let out = output(&mut run);
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(!stderr.contains("XDG_RUNTIME_DIR"), "{stderr}");
}

#[test]
fn gbuffer_export_writes_depth_normals_and_camera() {
    let dir = tempfile::tempdir().unwrap();
    let out = aokit(
        dir.path(),
        &[
            "render",
            "--scene",
            "stairs",
            "--size",
            "96x64",
            "--gbuffer",
            "--out",
            "g",
            "--preset",
            "low",
        ],
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let g = dir.path().join("g");
    let camera: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(g.join("camera.json")).unwrap()).unwrap();
    assert_eq!(camera["width"], 96);
    assert_eq!(camera["height"], 64);
    assert_eq!(camera["projection"], "perspective");
    assert_eq!(camera["reverse_z"], true);
    assert!(camera["far"].is_null());
    assert_eq!(camera["view_from_world"].as_array().unwrap().len(), 4);

    let (depth, size) = read_exr_channel(&g.join("depth.exr"), "Z");
    assert_eq!(size, [96, 64]);
    assert!(depth.iter().all(|d| d.is_finite() && *d >= 0.0));
    assert!(depth.iter().filter(|&&d| d > 0.0).count() > 96 * 64 / 2);
    let (ao, _) = read_exr_channel(&g.join("ao.exr"), "Y");
    assert!(ao.iter().all(|a| (0.0..=1.0).contains(a)));
    let channels: Vec<Vec<f32>> = ["R", "G", "B"]
        .iter()
        .map(|c| read_exr_channel(&g.join("normal.exr"), c).0)
        .collect();
    let fov_y = (camera["fov_y_deg"].as_f64().unwrap() as f32).to_radians();
    let tan_half = (0.5 * fov_y).tan();
    for i in 0..depth.len() {
        let n = [channels[0][i], channels[1][i], channels[2][i]];
        let length = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        if depth[i] > 0.0 {
            assert!(
                (length - 1.0).abs() < 1e-3,
                "pixel {i}: normal length {length}"
            );
            // Visible surfaces face the eye: the view position, camera looking down -Z, is
            // (ndc.x * tan * aspect, ndc.y * tan, -1) * depth.
            let (x, y) = ((i % 96) as f32 + 0.5, (i / 96) as f32 + 0.5);
            let ndc = [x / 96.0 * 2.0 - 1.0, 1.0 - y / 64.0 * 2.0];
            let to_eye = [-ndc[0] * tan_half * 1.5, -ndc[1] * tan_half, 1.0];
            let facing = n[0] * to_eye[0] + n[1] * to_eye[1] + n[2] * to_eye[2];
            assert!(
                facing > 0.0,
                "pixel {i}: normal {n:?} faces away from the eye"
            );
        } else {
            assert_eq!(length, 0.0);
        }
    }
}

#[test]
fn settings_flags_reach_the_pipeline() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.toml"), "intensity = 0.0\n").unwrap();
    let out = aokit(
        dir.path(),
        &[
            "render",
            "--size",
            "64x48",
            "--settings",
            "s.toml",
            "--set",
            "gtao.slice_count=2",
            "--out",
            "o",
        ],
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let (ao, _) = read_exr_channel(&dir.path().join("o/ao.exr"), "Y");
    assert!(
        ao.iter().all(|&a| a == 1.0),
        "intensity 0 must remove all occlusion"
    );
}

#[test]
fn the_sample_depth_read_is_reachable_from_the_command_line() {
    let dir = tempfile::tempdir().unwrap();
    let render = |read: &str| {
        let setting = format!("sample_depth={read}");
        let out = aokit(
            dir.path(),
            &[
                "render", "--size", "64x48", "--set", &setting, "--out", read,
            ],
        );
        assert!(out.status.success(), "{}", text(&out.stderr));
        read_exr_channel(&dir.path().join(read).join("ao.exr"), "Y").0
    };
    assert_ne!(render("nearest"), render("interpolated"));
}

#[test]
fn bad_arguments_exit_2_and_name_the_problem() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("broken.obj"), "v 0 0 0\nf 1 2 3\n").unwrap();
    std::fs::write(dir.path().join("broken.gltf"), "{ not json").unwrap();
    std::fs::write(dir.path().join("bad.toml"), "radius = [").unwrap();
    let cases: &[(&[&str], &str)] = &[
        (&["render", "--size", "0x10"], "at least 1"),
        (&["render", "--size", "big"], "WIDTHxHEIGHT"),
        (&["render", "--scene", "nowhere"], "unknown scene"),
        (&["render", "--scene", "broken.obj"], "broken.obj"),
        (&["render", "--scene", "broken.gltf"], "broken.gltf"),
        (&["render", "--camera", "nosuch"], "no camera `nosuch`"),
        (&["render", "--method", "ssao9"], "ssao9"),
        (&["render", "--set", "gtao.slices=3"], "gtao.slice_count"),
        (&["render", "--set", "radius=0"], "radius"),
        (
            &["render", "--set", "spatial.kind=box"],
            "`bilateral`, `guided`, `edges`",
        ),
        (
            &["render", "--set", "spatial.guided_epsilon=0"],
            "spatial.guided_epsilon",
        ),
        (
            &["render", "--set", "sample_depth=exact"],
            "one of `nearest`, `interpolated`, not `exact`",
        ),
        (&["render", "--settings", "missing.toml"], "missing.toml"),
        (&["render", "--settings", "bad.toml"], "bad.toml"),
        (
            &["render", "--eye", "0,1,2", "--target", "0,1,2"],
            "same point",
        ),
        (&["render", "--eye", "1,2"], "X,Y,Z"),
        (&["render", "--size", "100000x10"], "100000x10"),
        (&["frobnicate"], "frobnicate"),
    ];
    for (args, expected) in cases {
        let out = aokit(dir.path(), args);
        let stderr = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(
            stderr.contains(expected),
            "{args:?}: expected `{expected}` in: {stderr}"
        );
    }
}

#[test]
fn an_adapter_name_that_matches_nothing_lists_the_adapters() {
    let dir = tempfile::tempdir().unwrap();
    let out = output(
        command(dir.path(), &["render", "--size", "8x8"])
            .env("WGPU_ADAPTER_NAME", "no-such-gpu-9000"),
    );
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("no-such-gpu-9000") && stderr.contains("found:"),
        "{stderr}"
    );
}

#[test]
fn a_machine_without_an_adapter_gets_an_install_hint() {
    let dir = tempfile::tempdir().unwrap();
    // Metal does not exist on Linux or Windows, so asking only for it finds no adapter.
    let out =
        output(command(dir.path(), &["render", "--size", "8x8"]).env("WGPU_BACKEND", "metal"));
    let stderr = text(&out.stderr);
    if cfg!(target_os = "macos") {
        return;
    }
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("no GPU adapter") && stderr.contains("mesa-vulkan-drivers"),
        "{stderr}"
    );
}

#[test]
fn a_camera_path_writes_frames_and_animated_previews() {
    let dir = tempfile::tempdir().unwrap();
    let out = aokit(
        dir.path(),
        &[
            "render", "--size", "48x32", "--frames", "4", "--path", "orbit", "--out", "seq",
        ],
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let seq = dir.path().join("seq");
    for file in [
        "frames/ao-000.png",
        "frames/lit-003.png",
        "ao.gif",
        "lit.gif",
        "ao.png",
        "ao.exr",
        "frames/rejected-003.png",
        "rejected.png",
    ] {
        assert!(seq.join(file).is_file(), "{file} missing");
    }
    // The debug view: the first frame has no history on any surface (the sky is 0); the
    // orbit's last frame keeps most of it and rejects what it newly sees.
    let rejected = |file: &str| {
        let mask = image::open(seq.join(file)).unwrap().into_luma8();
        mask.pixels().filter(|p| p.0[0] > 127).count() as f64 / mask.len() as f64
    };
    let (first, last) = (
        rejected("frames/rejected-000.png"),
        rejected("rejected.png"),
    );
    assert!(first > 0.5, "first frame rejected {first}");
    assert!(
        last > 0.0 && last < first / 2.0,
        "last frame rejected {last}"
    );
    let gif = std::fs::read(seq.join("ao.gif")).unwrap();
    assert!(gif.starts_with(b"GIF89a"));
    // Frames that follow each other get the temporal filter unless --set turns it off.
    let args = [
        "render",
        "--size",
        "48x32",
        "--frames",
        "2",
        "--set",
        "temporal.enabled=false",
        "--out",
        "raw",
    ];
    let out = aokit(dir.path(), &args);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(dir.path().join("raw/ao.png").is_file());
    assert!(!dir.path().join("raw/rejected.png").exists());
    for (args, expected) in [
        (&["render", "--frames", "0"][..], "--frames"),
        (&["render", "--frames", "3", "--path", "spin"][..], "spin"),
    ] {
        let out = aokit(dir.path(), args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(
            text(&out.stderr).contains(expected),
            "{args:?}: {}",
            text(&out.stderr)
        );
    }
}

#[test]
fn debug_views_are_written_as_pngs_and_unknown_ones_refused() {
    let dir = tempfile::tempdir().unwrap();
    let out = aokit(
        dir.path(),
        &[
            "render",
            "--size",
            "48x32",
            "--debug",
            "edges,normals",
            "--out",
            "dbg",
        ],
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    for file in ["debug-edges.png", "debug-normals.png"] {
        let image = image::open(dir.path().join("dbg").join(file)).unwrap();
        assert_eq!((image.width(), image.height()), (48, 32), "{file}");
    }
    let out = aokit(dir.path(), &["render", "--debug", "mips"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains("working-depth"),
        "{}",
        text(&out.stderr)
    );
    let out = aokit(
        dir.path(),
        &["render", "--size", "48x32", "--debug", "rejected"],
    );
    assert!(!out.status.success());
    assert!(
        text(&out.stderr).contains("temporal.enabled"),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn old_flag_names_still_parse_and_say_the_new_ones() {
    let dir = tempfile::tempdir().unwrap();
    // An unknown method stops the run before any tracing; the warning comes first.
    let out = aokit(
        dir.path(),
        &["compare", "--methods=nope", "--presets", "high"],
    );
    let stderr = text(&out.stderr);
    assert!(!out.status.success());
    assert!(
        stderr.contains("`aokit compare --methods` is now `--method`")
            && stderr.contains("`aokit compare --presets` is now `--preset`"),
        "{stderr}"
    );
    assert!(stderr.contains("nope"), "{stderr}");
    let out = aokit(dir.path(), &["tune", "--method", "nope"]);
    let stderr = text(&out.stderr);
    assert!(!stderr.contains("warning"), "{stderr}");
    assert!(stderr.contains("nope"), "{stderr}");
}

#[test]
fn sequence_options_on_one_frame_draw_a_note() {
    let dir = tempfile::tempdir().unwrap();
    let out = aokit(
        dir.path(),
        &[
            "render",
            "--size",
            "32x24",
            "--path",
            "orbit",
            "--set",
            "temporal.enabled=true",
        ],
    );
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.contains("note: --path orbit moves the camera"),
        "{stderr}"
    );
    assert!(
        stderr.contains("note: the temporal filter accumulates"),
        "{stderr}"
    );
    // Over a sequence both do what they say, without a note.
    let out = aokit(
        dir.path(),
        &[
            "render", "--size", "32x24", "--frames", "2", "--path", "orbit", "--out", "seq",
        ],
    );
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(!stderr.contains("moves the camera"), "{stderr}");
}
