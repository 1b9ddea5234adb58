//! `aokit ao` warns about passes that read but look like something else: a normal map as depth,
//! depth-buffer values as linear depth, world-space normals as view-space ones; and says
//! nothing about what `render --gbuffer` writes.

use std::path::Path;

use aokit_eval::{read_depth, read_normals, write_exr};
use aokit_scene::CameraFile;
use glam::{Mat3, Vec3};

use crate::common::{aokit, ok, text};

fn render(dir: &Path, out: &str, view: &[&str]) {
    let mut args = vec!["render", "--size", "64x40", "--gbuffer", "--out", out];
    args.extend(view);
    ok(&aokit(dir, &args));
}

/// The warnings `aokit ao` printed with `args`, which must succeed.
fn warnings(dir: &Path, args: &[&str]) -> Vec<String> {
    let mut all = vec!["ao", "--out", "a"];
    all.extend(args);
    let out = aokit(dir, &all);
    ok(&out);
    text(&out.stderr)
        .lines()
        .filter(|line| line.starts_with("warning:"))
        .map(String::from)
        .collect()
}

fn camera(path: &Path) -> CameraFile {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn render_gbuffer_output_draws_no_warning() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (scene, camera) in [("stairs", "0"), ("room", "1"), ("thin", "0"), ("open", "1")] {
        render(d, scene, &["--scene", scene, "--camera", camera]);
        let files = [
            "--depth",
            &format!("{scene}/depth.exr"),
            "--normals",
            &format!("{scene}/normal.exr"),
            "--camera-json",
            &format!("{scene}/camera.json"),
        ];
        assert_eq!(warnings(d, &files), Vec::<String>::new(), "{scene}");
    }
}

#[test]
fn a_normal_map_given_as_depth_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    render(d, "g", &["--scene", "stairs"]);
    let found = warnings(
        d,
        &["--depth", "g/normal.exr", "--camera-json", "g/camera.json"],
    );
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(
        found[0].contains("g/normal.exr") && found[0].contains("normal map"),
        "{found:?}"
    );
}

#[test]
fn depth_buffer_values_given_as_linear_depth_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    render(d, "g", &["--scene", "room"]);
    let linear = read_depth(&d.join("g/depth.exr")).unwrap();
    let size = [linear.width, linear.height];
    let mut file = camera(&d.join("g/camera.json"));
    // The render's own reverse-Z buffer with an infinite far plane, then a conventional one
    // with a far plane at 50, whose cleared background reads as 1.
    for (name, reverse_z, far) in [("reverse", true, None), ("conventional", false, Some(50.0))] {
        file.reverse_z = reverse_z;
        file.far = far;
        let projection = file.projection().unwrap();
        let ndc: Vec<f32> = linear
            .data
            .iter()
            .map(|&z| {
                if z > 0.0 {
                    projection.ndc_depth(z)
                } else {
                    projection.far_ndc_depth()
                }
            })
            .collect();
        let (depth, json) = (format!("{name}.exr"), format!("{name}/camera.json"));
        write_exr(&d.join(&depth), size, &[("Z", ndc)]).unwrap();
        std::fs::create_dir_all(d.join(name)).unwrap();
        std::fs::write(d.join(&json), serde_json::to_string(&file).unwrap()).unwrap();
        let found = warnings(d, &["--depth", &depth, "--camera-json", &json]);
        assert_eq!(found.len(), 1, "{name}: {found:?}");
        assert!(
            found[0].contains(&depth) && found[0].contains("--depth-kind ndc"),
            "{name}: {found:?}"
        );
        let found = warnings(
            d,
            &[
                "--depth",
                &depth,
                "--camera-json",
                &json,
                "--depth-kind",
                "ndc",
            ],
        );
        assert_eq!(found, Vec::<String>::new(), "{name}");
    }
}

#[test]
fn world_space_normals_given_as_view_space_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // A camera turned well away from the world's axes, as most are.
    render(
        d,
        "g",
        &[
            "--scene", "stairs", "--eye", "3,2.5,-3", "--target", "0,0.5,0",
        ],
    );
    let view = read_normals(&d.join("g/normal.exr")).unwrap();
    let world_from_view =
        Mat3::from_mat4(camera(&d.join("g/camera.json")).view_from_world()).transpose();
    let world: Vec<Vec3> = view
        .data
        .chunks_exact(3)
        .map(|n| world_from_view * Vec3::new(n[0], n[1], n[2]))
        .collect();
    let channel = |i: usize| world.iter().map(|n| n[i]).collect::<Vec<f32>>();
    write_exr(
        &d.join("world.exr"),
        [view.width, view.height],
        &[("R", channel(0)), ("G", channel(1)), ("B", channel(2))],
    )
    .unwrap();
    let files = [
        "--depth",
        "g/depth.exr",
        "--normals",
        "world.exr",
        "--camera-json",
        "g/camera.json",
    ];
    let found = warnings(d, &files);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(
        found[0].contains("world.exr") && found[0].contains("--normal-space world"),
        "{found:?}"
    );
    let mut told = files.to_vec();
    told.extend(["--normal-space", "world"]);
    assert_eq!(warnings(d, &told), Vec::<String>::new());
    // The view-space file read as world space is the same mistake the other way round.
    let found = warnings(
        d,
        &[
            "--depth",
            "g/depth.exr",
            "--normals",
            "g/normal.exr",
            "--camera-json",
            "g/camera.json",
            "--normal-space",
            "world",
        ],
    );
    assert!(
        found.len() == 1 && found[0].contains("--normal-space view"),
        "{found:?}"
    );
}
