//! `aokit view`, the interactive viewer, in its screenshot mode under Xvfb: `xvfb-run -a aokit
//! view --frames 5 --screenshot FILE` opens the window, renders five frames and writes a PNG of
//! the window. Skipped (with a notice) where `xvfb-run` is not installed (Debian package
//! `xvfb`), unless `AOKIT_REQUIRE_XVFB=1` says it must be there (CI). The panel's generation
//! from the settings' declarations is tested without a window in src/view/panel.rs.

use std::path::Path;
use std::process::{Command, Output};

use crate::common::{command, failure, ok, output, text};

/// Whether `xvfb-run` is here; panics where `AOKIT_REQUIRE_XVFB=1` but it is not.
fn have_xvfb() -> bool {
    let found = Command::new("xvfb-run").arg("--help").output().is_ok();
    if !found {
        assert!(
            std::env::var("AOKIT_REQUIRE_XVFB").as_deref() != Ok("1"),
            "AOKIT_REQUIRE_XVFB=1 but xvfb-run (Debian package xvfb) does not run"
        );
        eprintln!("skipping: no xvfb-run (Debian package xvfb): `aokit view` needs a display");
    }
    found
}

/// Whether `xdotool` is here; panics where `AOKIT_REQUIRE_XVFB=1` but it is not.
fn have_xdotool() -> bool {
    let found = Command::new("xdotool").arg("version").output().is_ok();
    if !found {
        assert!(
            std::env::var("AOKIT_REQUIRE_XVFB").as_deref() != Ok("1"),
            "AOKIT_REQUIRE_XVFB=1 but xdotool (Debian package xdotool) does not run"
        );
        eprintln!("skipping: no xdotool (Debian package xdotool)");
    }
    found
}

/// `script` run by `sh` under a fresh Xvfb display in `dir`, with the aokit binary as `$1`.
fn script_in_xvfb(dir: &Path, script: &str) -> Output {
    output(
        Command::new("xvfb-run")
            .args([
                "-a",
                "-s",
                "-screen 0 1024x768x24",
                "sh",
                "-c",
                script,
                "sh",
            ])
            .arg(env!("CARGO_BIN_EXE_aokit"))
            .current_dir(dir),
    )
}

/// `aokit args` run in `dir` under a fresh Xvfb display.
fn aokit_in_xvfb(dir: &Path, args: &[&str]) -> Output {
    let aokit = command(dir, args);
    let mut xvfb = Command::new("xvfb-run");
    // A 24-bit screen: the default 8-bit one has no visual a Vulkan swapchain presents to.
    xvfb.args(["-a", "-s", "-screen 0 1024x768x24"])
        .arg(aokit.get_program())
        .args(aokit.get_args())
        .current_dir(dir);
    output(&mut xvfb)
}

/// The mean of the RGB channels over a box of `r` (a fraction of the width) about the point
/// (`x`, `y`), given as fractions of the image's size.
fn mean_grey(image: &image::RgbaImage, x: f32, y: f32, r: f32) -> f32 {
    let (w, h) = image.dimensions();
    let (cx, cy, half) = (
        (x * w as f32) as i64,
        (y * h as f32) as i64,
        (r * w as f32) as i64,
    );
    let mut sum = 0.0;
    let mut count = 0.0;
    for py in (cy - half)..=(cy + half) {
        for px in (cx - half)..=(cx + half) {
            let p = image.get_pixel(px as u32, py as u32);
            sum += (f32::from(p[0]) + f32::from(p[1]) + f32::from(p[2])) / 3.0;
            count += 1.0;
        }
    }
    sum / count
}

#[test]
fn screenshot_of_the_room_shows_the_window_with_a_dark_corner() {
    if !have_xvfb() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let out = aokit_in_xvfb(
        dir.path(),
        &[
            "view",
            "--scene",
            "room",
            "--mode",
            "ao",
            "--no-panel",
            "--window-size",
            "320x180",
            "--frames",
            "5",
            "--screenshot",
            "shot.png",
        ],
    );
    let stdout = ok(&out);
    assert!(stdout.contains("wrote shot.png (320x180"), "{stdout}");
    let shot = image::open(dir.path().join("shot.png")).unwrap().to_rgba8();
    assert_eq!(shot.dimensions(), (320, 180));
    // The `front` camera looks at the back wall: its left end meets the left wall and the
    // floor in a concave corner; the floor in front of the camera is open. (The bottom edge
    // holds the software-adapter note on lavapipe: the floor is sampled above it.)
    let corner = mean_grey(&shot, 0.31, 0.5, 0.02);
    let floor = mean_grey(&shot, 0.5, 0.72, 0.02);
    assert!(floor > 240.0, "open floor should be unoccluded: {floor}");
    assert!(
        corner < floor - 30.0,
        "the corner ({corner}) should be darker than the open floor ({floor})"
    );
}

#[test]
fn screenshot_with_the_panel_is_the_window_size_and_draws_the_panel() {
    if !have_xvfb() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let out = aokit_in_xvfb(
        dir.path(),
        &[
            "view",
            "--window-size",
            "640x360",
            "--frames",
            "3",
            "--screenshot",
            "panel.png",
        ],
    );
    let stdout = ok(&out);
    assert!(stdout.contains("wrote panel.png (640x360"), "{stdout}");
    let shot = image::open(dir.path().join("panel.png"))
        .unwrap()
        .to_rgba8();
    assert_eq!(shot.dimensions(), (640, 360));
    // egui's dark panel on the left, the lit room (bright walls and floor) on the right.
    let panel = mean_grey(&shot, 0.1, 0.5, 0.03);
    let scene = mean_grey(&shot, 0.8, 0.8, 0.03);
    assert!(panel < 80.0, "panel: {panel}");
    assert!(scene > panel + 60.0, "scene {scene} vs panel {panel}");
}

#[test]
fn bad_flags_are_refused_before_any_window_opens() {
    let dir = tempfile::tempdir().unwrap();
    let err = failure(&crate::common::aokit(
        dir.path(),
        &["view", "--screenshot", "shot.jpg", "--frames", "1"],
    ));
    assert!(err.contains("must name a .png file"), "{err}");
    let err = failure(&crate::common::aokit(
        dir.path(),
        &["view", "--mode", "sideways"],
    ));
    assert!(err.contains("unknown display mode"), "{err}");
    let err = failure(&crate::common::aokit(dir.path(), &["view", "--scale", "7"]));
    assert!(err.contains("outside"), "{err}");
    let err = failure(&crate::common::aokit(
        dir.path(),
        &["view", "--b-method", "hbao"],
    ));
    assert!(err.contains("--split"), "{err}");
    let err = failure(&crate::common::aokit(
        dir.path(),
        &["view", "--split", "--divider", "1.5"],
    ));
    assert!(err.contains("outside"), "{err}");
    let err = failure(&crate::common::aokit(
        dir.path(),
        &["view", "--split", "--b-set", "gtao.slice_count=0"],
    ));
    assert!(err.contains("B's settings"), "{err}");
    let err = failure(&crate::common::aokit(
        dir.path(),
        &["view", "--split", "--b-set", "normals.encoding=rgba16f"],
    ));
    assert!(err.contains("differs from A's `oct32`"), "{err}");
    let err = failure(&crate::common::aokit(
        dir.path(),
        &["view", "--animate", "--reference"],
    ));
    assert!(err.contains("add --paused"), "{err}");
    let err = failure(&crate::common::aokit(
        dir.path(),
        &["view", "--loop-frames", "1"],
    ));
    assert!(err.contains("--loop-frames"), "{err}");
    // Without a display, the error says how to get one.
    let out = output(
        command(dir.path(), &["view", "--frames", "1"])
            .env_remove("DISPLAY")
            .env_remove("WAYLAND_DISPLAY"),
    );
    assert!(!out.status.success());
    assert!(
        text(&out.stderr).contains("xvfb-run"),
        "{}",
        text(&out.stderr)
    );
}

/// The panel's widgets as `--panel-layout` prints them: every declared setting gets one, in its
/// key's group, of its kind, within its declared bounds. No window opens.
#[test]
fn the_panel_has_a_widget_within_its_bounds_for_every_declared_setting() {
    use aokit::settings::{SETTINGS, SettingKind};
    use aokit::{AoSettings, Method, Preset};

    let dir = tempfile::tempdir().unwrap();
    for (method, preset) in [(Method::Gtao, Preset::High), (Method::Vbao, Preset::Low)] {
        let layout = ok(&crate::common::aokit(
            dir.path(),
            &[
                "view",
                "--scene",
                "room",
                "--method",
                method.name(),
                "--preset",
                preset.name(),
                "--panel-layout",
            ],
        ));
        let lines: Vec<Vec<&str>> = layout
            .lines()
            .map(|line| line.split('\t').collect())
            .collect();
        assert_eq!(lines.len(), SETTINGS.len(), "{layout}");
        // The settings the flags give: the preset with the room's radius.
        let mut settings = AoSettings::preset(method, preset);
        settings.radius = 1.0;
        for spec in SETTINGS {
            let line = lines
                .iter()
                .find(|fields| fields[1] == spec.name)
                .unwrap_or_else(|| panic!("no widget for {}", spec.name));
            let group = spec.name.split_once('.').map_or("general", |(g, _)| g);
            assert_eq!(line[0], group, "{}", spec.name);
            let widget: Vec<&str> = line[2].split(' ').collect();
            let number = |text: &str| -> f32 { text.parse().unwrap() };
            match spec.kind {
                SettingKind::Bool => assert_eq!(widget, ["check"]),
                SettingKind::Integer(range) => assert_eq!(
                    line[2],
                    format!(
                        "int-slider {}..={} step {}",
                        range.min, range.max, range.step
                    )
                ),
                SettingKind::Choice(names) => {
                    assert_eq!(widget, ["combo", &names.join("|")], "{}", spec.name)
                }
                SettingKind::Float(range) => match widget[..] {
                    ["float-slider", bounds] => {
                        let (min, max) = bounds.split_once("..=").unwrap();
                        let (min, max) = (number(min), number(max));
                        assert!(min <= max, "{}: {bounds}", spec.name);
                        assert!(range.contains(min, &settings), "{}: {min}", spec.name);
                        assert!(range.contains(max, &settings), "{}: {max}", spec.name);
                    }
                    ["float-drag", bounds] => {
                        let min = number(bounds.strip_suffix("..").unwrap());
                        assert!(range.contains(min, &settings), "{}: {min}", spec.name);
                        assert_eq!(range.max_value(&settings), None, "{}", spec.name);
                    }
                    _ => panic!("{}: a float got {}", spec.name, line[2]),
                },
            }
        }
    }
}

/// Drives the window with xdotool under Xvfb: `P` prints the pose, holding `W` flies forward, a
/// right-button drag to the right turns the view right, `Escape` quits. Needs xdotool as well
/// (skipped without it unless `AOKIT_REQUIRE_XVFB=1`).
#[test]
fn keys_and_mouse_move_the_camera_and_p_prints_the_pose() {
    if !have_xvfb() || !have_xdotool() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    // The window opens, `P`, `W` held for a second and a half, `P`, a drag, `P`, `Escape`.
    let script = r#"
        "$1" view --scene room --window-size 320x180 --no-panel > out.txt 2> err.txt &
        app=$!
        window=$(xdotool search --sync --name "aokit view" | head -n 1)
        sleep 1
        # No window manager: focus the window and put the pointer over it.
        xdotool windowfocus --sync "$window"
        xdotool mousemove --window "$window" 160 90
        xdotool key p; sleep 0.5
        xdotool keydown w; sleep 1.5; xdotool keyup w; sleep 0.5
        xdotool key p; sleep 0.5
        xdotool mousemove --window "$window" 160 90 mousedown 3
        for i in 1 2 3 4 5 6 7 8 9 10; do xdotool mousemove_relative 10 0; sleep 0.1; done
        xdotool mouseup 3; sleep 0.5
        xdotool key p; sleep 0.5
        xdotool key Escape
        wait $app
    "#;
    let out = script_in_xvfb(dir.path(), script);
    let printed = std::fs::read_to_string(dir.path().join("out.txt")).unwrap();
    let errors = std::fs::read_to_string(dir.path().join("err.txt")).unwrap();
    assert!(out.status.success(), "{}\n{errors}", text(&out.stderr));
    let mut poses: Vec<[f32; 6]> = printed
        .lines()
        .map(|line| {
            let words: Vec<&str> = line.split(' ').collect();
            assert_eq!(words[0], "--eye", "{line}");
            assert_eq!(words[2], "--target", "{line}");
            let mut values = words[1].split(',').chain(words[3].split(','));
            std::array::from_fn(|_| values.next().unwrap().parse().unwrap())
        })
        .collect();
    // Under load Xvfb has delivered one `P` twice (the same pose printed twice, once in a
    // full `cargo test`); the pose printed is what this test checks, not how often.
    poses.dedup();
    assert_eq!(poses.len(), 3, "{printed}\n{errors}");
    // The room's `front` camera, looking down -Z.
    assert_eq!(poses[0], [0.0, 2.4, 6.5, 0.0, 0.9, -1.2]);
    // W: forward, towards -Z; the view direction is kept.
    assert!(poses[1][2] < 6.0, "{printed}");
    assert!(
        poses[1][0].abs() < 1e-3 && poses[1][3].abs() < 1e-3,
        "{printed}"
    );
    // A drag to the right turns right: the target moves to +X, the eye stays.
    assert_eq!(poses[2][..3], poses[1][..3], "{printed}");
    assert!(poses[2][3] > 0.5, "{printed}");
}

/// The mean absolute difference of the RGB channels of `a` and `b` over the box with corners
/// (`x0`, `y0`) and (`x1`, `y1`), as fractions of the images' size.
fn mean_difference(a: &image::RgbaImage, b: &image::RgbaImage, [x0, y0, x1, y1]: [f32; 4]) -> f32 {
    let (w, h) = a.dimensions();
    assert_eq!(b.dimensions(), (w, h));
    let (mut sum, mut count) = (0.0, 0.0);
    for y in (y0 * h as f32) as u32..(y1 * h as f32) as u32 {
        for x in (x0 * w as f32) as u32..(x1 * w as f32) as u32 {
            let (p, q) = (a.get_pixel(x, y), b.get_pixel(x, y));
            for c in 0..3 {
                sum += (f32::from(p[c]) - f32::from(q[c])).abs();
                count += 1.0;
            }
        }
    }
    sum / count
}

/// `--split`: GTAO left of a divider at 30% of the view, HBAO right of it. Each half is that
/// method's image as the viewer shows it alone, the two methods differ there, and the divider's
/// line is where asked.
#[test]
fn the_split_shows_a_left_of_the_divider_and_b_right_of_it() {
    if !have_xvfb() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let view = [
        "view",
        "--mode",
        "ao",
        "--no-panel",
        "--window-size",
        "320x180",
    ];
    let shoot = |file: &str, args: &[&str]| {
        let mut all = view.to_vec();
        all.extend_from_slice(args);
        all.extend_from_slice(&["--screenshot", file]);
        ok(&aokit_in_xvfb(dir.path(), &all));
        image::open(dir.path().join(file)).unwrap().to_rgba8()
    };
    let split = shoot(
        "split.png",
        &[
            "--method",
            "gtao",
            "--split",
            "--b-method",
            "hbao",
            "--divider",
            "0.3",
        ],
    );
    let gtao = shoot("gtao.png", &["--method", "gtao"]);
    let hbao = shoot("hbao.png", &["--method", "hbao"]);
    // Below the labels, above the software-adapter note.
    let (left, right) = ([0.02, 0.25, 0.27, 0.8], [0.35, 0.25, 0.98, 0.8]);
    assert!(mean_difference(&split, &gtao, left) < 1.0);
    assert!(mean_difference(&split, &hbao, right) < 1.0);
    let methods_left = mean_difference(&gtao, &hbao, left);
    let methods_right = mean_difference(&gtao, &hbao, right);
    assert!(
        methods_left > 1.0 && methods_right > 1.0,
        "{methods_left} {methods_right}"
    );
    // The divider's yellow line, across the middle row.
    let row = split.height() / 2;
    let line: Vec<u32> = (0..split.width())
        .filter(|&x| {
            let p = split.get_pixel(x, row);
            p[0] > 200 && p[1] > 150 && p[2] < 80
        })
        .collect();
    assert!(!line.is_empty(), "no divider line");
    for x in line {
        assert!((94..=97).contains(&x), "divider at x = {x}, not 96");
    }
}

/// `--reference` in the split, in the `error` mode: the viewer traces the view's reference
/// (small, few rays), waits for it, and its error image and printed RMSE for each half are what
/// `aokit compare` draws and computes for the same view, methods and rays per pixel.
#[test]
fn the_reference_error_and_rmse_match_aokit_compare() {
    if !have_xvfb() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    #[rustfmt::skip]
    let out = aokit_in_xvfb(dir.path(), &[
        "view", "--scene", "room", "--mode", "error", "--no-panel", "--window-size", "320x180",
        "--scale", "0.5", "--method", "gtao", "--split", "--b-method", "hbao", "--reference",
        "--reference-spp", "16", "--screenshot", "error.png",
    ]);
    let stdout = ok(&out);
    let rmse = |side: &str| -> f64 {
        let line = stdout
            .lines()
            .find(|line| line.starts_with(&format!("rmse {side} ")))
            .unwrap_or_else(|| panic!("no RMSE of {side}: {stdout}"));
        assert!(line.ends_with("160x90, 16 rays per pixel)"), "{line}");
        line.split(' ').nth(2).unwrap().parse().unwrap()
    };
    #[rustfmt::skip]
    ok(&crate::common::aokit(dir.path(), &[
        "compare", "--scene", "room", "--size", "160x90", "--method", "gtao,hbao", "--preset",
        "high", "--spp", "16", "--timing-frames", "0", "--cache", "cache", "--out", "compare",
    ]));
    let metrics: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.path().join("compare/metrics.json")).unwrap(),
    )
    .unwrap();
    let shot = image::open(dir.path().join("error.png"))
        .unwrap()
        .to_rgba8();
    for (i, (side, method)) in [("A", "gtao"), ("B", "hbao")].into_iter().enumerate() {
        let result = &metrics["results"][i];
        assert_eq!(result["method"], method);
        let expected = result["all"]["rmse"].as_f64().unwrap();
        // The viewer's AO is of a later frame (frame index 5, not 0): close, not equal.
        let got = rmse(side);
        assert!((got - expected).abs() < 2e-3, "{side}: {got} vs {expected}");
        let map = image::open(
            dir.path()
                .join(format!("compare/images/room-front-{method}-high-error.png")),
        )
        .unwrap()
        .to_rgba8();
        // The screenshot shows the 160x90 map stretched to 320x180: its 2x2 means against the
        // map, in the half that shows this side, below the labels and above the note.
        let columns = if i == 0 { 4..76 } else { 84..156 };
        let (mut sum, mut count) = (0.0, 0.0);
        for y in 14..70 {
            for x in columns.clone() {
                for c in 0..3 {
                    let shown: f32 = [(0, 0), (1, 0), (0, 1), (1, 1)]
                        .iter()
                        .map(|(dx, dy)| f32::from(shot.get_pixel(2 * x + dx, 2 * y + dy)[c]))
                        .sum::<f32>()
                        / 4.0;
                    sum += (shown - f32::from(map.get_pixel(x, y)[c])).abs();
                    count += 1.0;
                }
            }
        }
        // Bilinear stretching blurs the noisy map: about 9 here; another image gives 50.
        let difference = sum / count;
        assert!(difference < 15.0, "{side}: {difference}");
    }
}

/// `--guard-band`: the viewer draws the overscan, and its AO is closer to the reference (as
/// `aokit render --guard-band`, docs/quality.md#guard-band): 0.048 to 0.042 here.
#[test]
fn a_guard_band_lowers_the_error_against_the_reference() {
    if !have_xvfb() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let rmse = |band: &str| -> f64 {
        let shot = format!("band-{band}.png");
        #[rustfmt::skip]
        let out = aokit_in_xvfb(dir.path(), &[
            "view", "--scene", "room", "--mode", "ao", "--no-panel", "--window-size", "320x180",
            "--scale", "0.5", "--reference", "--reference-spp", "16", "--guard-band", band,
            "--screenshot", &shot,
        ]);
        let stdout = ok(&out);
        let line = stdout
            .lines()
            .find(|line| line.starts_with("rmse A "))
            .unwrap_or_else(|| panic!("no RMSE: {stdout}"));
        line.split(' ').nth(2).unwrap().parse().unwrap()
    };
    let (without, with) = (rmse("0"), rmse("32"));
    assert!(
        with < 0.95 * without,
        "RMSE {with} with a 32 px band, {without} without"
    );
}

/// `--animate --path orbit`: the fourth frame of an eight-frame loop is the fourth frame of
/// `aokit render --frames 8 --path orbit --animate` (the sphere rolled, the camera turned), not
/// its neighbours.
#[test]
fn the_motion_plays_the_frames_aokit_render_renders() {
    if !have_xvfb() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    #[rustfmt::skip]
    let out = aokit_in_xvfb(dir.path(), &[
        "view", "--scene", "room", "--mode", "ao", "--no-panel", "--window-size", "192x108",
        "--scale", "1", "--animate", "--path", "orbit", "--loop-frames", "8", "--frames", "4",
        "--screenshot", "motion.png",
    ]);
    ok(&out);
    #[rustfmt::skip]
    ok(&crate::common::aokit(dir.path(), &[
        "render", "--scene", "room", "--size", "192x108", "--frames", "8", "--path", "orbit",
        "--animate", "--out", "render",
    ]));
    let shot = image::open(dir.path().join("motion.png"))
        .unwrap()
        .to_rgba8();
    let frame = |i: u32| {
        image::open(dir.path().join(format!("render/frames/ao-{i:03}.png")))
            .unwrap()
            .to_rgba8()
    };
    // Above the software-adapter note.
    let region = [0.0, 0.1, 1.0, 0.78];
    let same = mean_difference(&shot, &frame(3), region);
    assert!(same < 4.0, "frame 3: {same}");
    for other in [2, 4] {
        let differs = mean_difference(&shot, &frame(other), region);
        assert!(
            differs > 2.0 * same + 4.0,
            "frame {other}: {differs} vs {same}"
        );
    }
}

#[test]
fn resizing_to_one_pixel_hiding_and_restoring_the_window_keep_it_rendering() {
    if !have_xvfb() || !have_xdotool() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    // The motion plays, so every frame renders the scene: 1x1, 1x40, 240x160, unmapped
    // (minimised: there is no window manager to iconify it), mapped, 320x180.
    let script = r#"
        "$1" view --scene room --mode ao --animate --loop-frames 24 --window-size 320x180 \
            --no-panel --frames 1000 --screenshot shot.png > out.txt 2> err.txt &
        app=$!
        window=$(xdotool search --sync --name "aokit view" | head -n 1)
        sleep 1
        xdotool windowsize --sync "$window" 1 1; sleep 1
        xdotool windowsize --sync "$window" 1 40; sleep 0.5
        xdotool windowsize --sync "$window" 240 160; sleep 1
        xdotool windowunmap --sync "$window"; sleep 1
        xdotool windowmap --sync "$window"; sleep 0.5
        xdotool windowsize --sync "$window" 320 180
        # The process's memory a few hundred frames apart, the window at its last size.
        sleep 2; grep VmRSS /proc/$app/status > rss-before.txt
        sleep 6; grep VmRSS /proc/$app/status > rss-after.txt
        wait $app
    "#;
    let out = script_in_xvfb(dir.path(), script);
    let errors = std::fs::read_to_string(dir.path().join("err.txt")).unwrap();
    assert!(out.status.success(), "{}\n{errors}", text(&out.stderr));
    let printed = std::fs::read_to_string(dir.path().join("out.txt")).unwrap();
    // All the frames were drawn; had the window been too fast for the script, the size would
    // not be the last one asked for.
    assert!(printed.contains("frame 1000"), "{printed}\n{errors}");
    let shot = image::open(dir.path().join("shot.png")).unwrap().to_rgba8();
    assert_eq!(shot.dimensions(), (320, 180), "{printed}");
    let rss = |name: &str| -> u64 {
        let line = std::fs::read_to_string(dir.path().join(name)).unwrap();
        let kib = line.split_whitespace().nth(1);
        kib.and_then(|kib| kib.parse().ok())
            .unwrap_or_else(|| panic!("{name}: {line:?} (the viewer ended too early?)"))
    };
    let (before, after) = (rss("rss-before.txt"), rss("rss-after.txt"));
    // The composite's old growth was half a megabyte a frame: a leak of that kind shows here.
    assert!(
        after < before + 8 * 1024,
        "resident memory grew from {before} KiB to {after} KiB in six seconds of frames"
    );
    // The room's AO again, as the first test sees it: the corner darker than the open floor.
    let corner = mean_grey(&shot, 0.31, 0.5, 0.02);
    let floor = mean_grey(&shot, 0.5, 0.72, 0.02);
    assert!(
        corner < floor - 30.0,
        "the corner ({corner}) should be darker than the open floor ({floor})"
    );
}

#[test]
fn the_lighting_flags_reach_the_lit_image_as_in_render() {
    if !have_xvfb() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let corner_of = |form: &str| {
        let shot = format!("{form}.png");
        let out = aokit_in_xvfb(
            dir.path(),
            &[
                "view",
                "--scene",
                "room",
                "--no-panel",
                "--window-size",
                "320x180",
                "--frames",
                "3",
                "--multi-bounce",
                form,
                "--screenshot",
                &shot,
            ],
        );
        ok(&out);
        let shot = image::open(dir.path().join(shot)).unwrap().to_rgba8();
        mean_grey(&shot, 0.31, 0.5, 0.02)
    };
    // Multi-bounce gives back light the raw AO takes: the corner is brighter with the closed
    // form (the brightest of the forms) than with none.
    let (none, closed) = (corner_of("none"), corner_of("closed-form"));
    assert!(
        closed > none + 3.0,
        "corner: none {none}, closed-form {closed}"
    );
}

#[test]
fn every_built_in_scene_opens_and_draws() {
    if !have_xvfb() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    for scene in ["room", "stairs", "thin", "open"] {
        let shot = format!("{scene}.png");
        let out = aokit_in_xvfb(
            dir.path(),
            &[
                "view",
                "--scene",
                scene,
                "--no-panel",
                "--window-size",
                "160x90",
                "--frames",
                "2",
                "--screenshot",
                &shot,
            ],
        );
        let stdout = ok(&out);
        assert!(
            stdout.contains(&format!("wrote {shot} (160x90")),
            "{stdout}"
        );
        // Lit: the sky and the shaded surfaces differ, whatever the scene.
        let image = image::open(dir.path().join(&shot)).unwrap().to_rgba8();
        let first = *image.get_pixel(0, 0);
        assert!(
            image.pixels().any(|p| p != &first),
            "{scene}: a uniform image"
        );
    }
}
