//! `aokit tune`: it runs, never makes a preset worse, and the presets the library ships are
//! the table it wrote (bench/data/tuning.json).

use std::path::Path;

use aokit::{AoSettings, Method, Preset};
use serde_json::Value;

use crate::common::{aokit, command, failure, ok, output};

/// Runs `aokit tune` on the built-in room, one round at the `low` preset, with `args` added,
/// in a fresh directory; returns the directory and its tune.json.
fn tune_room(args: &[&str]) -> (tempfile::TempDir, Value) {
    let dir = tempfile::tempdir().unwrap();
    let tune = [
        "tune", "--view", "room", "--preset", "low", "--rounds", "1", "--out", "t", "--cache",
        "cache",
    ];
    ok(&output(command(dir.path(), &tune).args(args)));
    let json = std::fs::read_to_string(dir.path().join("t/tune.json")).unwrap();
    let json = serde_json::from_str(&json).unwrap();
    (dir, json)
}

#[test]
fn tune_writes_its_table_and_never_ends_worse_than_it_started() {
    let (dir, json) = tune_room(&[
        "--size",
        "64x36",
        "--spp",
        "16",
        "--method",
        // In an order that names each method before the one it depends on, which tune puts
        // right: hbao-plus takes hbao's split, vbao is held to GTAO's error.
        "vbao,hbao-plus,hbao,gtao",
    ]);
    let t = dir.path().join("t");
    let results = json["results"].as_array().unwrap();
    let find = |method: &str, back_faces: bool| {
        results
            .iter()
            .find(|r| r["method"] == method && r["back_faces"] == back_faces)
            .unwrap_or_else(|| panic!("no {method} back faces {back_faces} in {results:?}"))
    };
    // vbao is tuned twice: assuming its occluders' thickness, and measuring it from the back
    // faces.
    assert_eq!(results.len(), 5);
    let gtao = find("gtao", false);
    for r in results {
        let value = |key: &str| r[key].as_f64().unwrap();
        let (start, tuned) = (value("start_rmse"), value("tuned_rmse"));
        let (start_excess, tuned_excess) = (value("start_excess"), value("tuned_excess"));
        // A search held to a bound never ends further outside it, and from within it never
        // ends with a higher error.
        assert!(tuned_excess <= start_excess, "{r}");
        assert!(tuned > 0.0, "{r}");
        if start_excess == 0.0 {
            assert!(tuned <= start, "{r}");
        }
    }
    // vbao, both ways, is held to GTAO's error on each view, as this run tuned it.
    assert!(gtao["bound"].is_null());
    for r in [find("vbao", false), find("vbao", true)] {
        assert_eq!(r["bound"], gtao["views_rmse"], "{r}");
        if r["tuned_excess"].as_f64().unwrap() == 0.0 {
            let rmse = r["views_rmse"].as_array().unwrap();
            let bound = r["bound"].as_array().unwrap();
            assert!(
                rmse.iter()
                    .zip(bound)
                    .all(|(r, b)| r.as_f64().unwrap() <= b.as_f64().unwrap()),
                "{r}"
            );
        }
    }
    // hbao-plus runs on hbao's directions and steps.
    assert_eq!(
        find("hbao-plus", false)["tuned"]["split"],
        find("hbao", false)["tuned"]["split"]
    );
    assert_eq!(json["power_sweep"].as_array().unwrap().len(), 4);
    let csv = std::fs::read_to_string(t.join("evaluations.csv")).unwrap();
    assert!(csv.lines().count() > 20, "{csv}");
    let md = std::fs::read_to_string(t.join("tune.md")).unwrap();
    assert!(md.contains("| `gtao` | low |"), "{md}");
    assert!(md.contains("| `vbao` + back faces | low |"), "{md}");
}

#[test]
fn unbounded_tunes_vbao_for_its_mean_error_alone() {
    let (dir, json) = tune_room(&[
        "--size",
        "48x27",
        "--spp",
        "8",
        "--method",
        "vbao",
        "--unbounded",
    ]);
    let results = json["results"].as_array().unwrap();
    assert_eq!(results.len(), 2);
    for r in results {
        assert!(r["bound"].is_null(), "{r}");
        assert_eq!(r["tuned_excess"], 0.0, "{r}");
    }
    let md = std::fs::read_to_string(dir.path().join("t/tune.md")).unwrap();
    assert!(md.contains("| over GTAO's |"), "{md}");
}

/// `bench/data/NAME`, parsed.
fn bench_data(name: &str) -> Value {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../bench/data")
        .join(name);
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The results of `bash bench/tuning.sh METHOD PRESET`'s runs since the full one
/// (bench/data/tuning-retuned/, which a full run removes).
fn retuned() -> Vec<Value> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../bench/data/tuning-retuned");
    let Ok(entries) = std::fs::read_dir(&dir) else {
        return Vec::new();
    };
    let mut results = Vec::new();
    for entry in entries {
        let name = entry.unwrap().file_name().into_string().unwrap();
        let json = bench_data(&format!("tuning-retuned/{name}"));
        results.extend(json["results"].as_array().unwrap().iter().cloned());
    }
    results
}

#[test]
fn the_presets_are_the_tuning_table() {
    let json = bench_data("tuning.json");
    // Rows searched again since the full run stand in for its rows.
    let retuned = retuned();
    let key = |r: &Value| {
        (
            r["method"].clone(),
            r["back_faces"].clone(),
            r["preset"].clone(),
        )
    };
    let results: Vec<&Value> = json["results"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| retuned.iter().find(|f| key(f) == key(r)).unwrap_or(r))
        .collect();
    for r in &retuned {
        let stands_in = results.iter().filter(|x| key(x) == key(r)).count();
        assert_eq!(stands_in, 1, "{r}: not one of the full run's rows");
    }
    // Every method but ssao-crytek, sao, ue4-ssao and msvo, whose presets keep their published
    // forms, and vbao once more measuring its occluders from the back faces.
    assert_eq!(results.len(), (Method::ALL.len() - 3) * Preset::ALL.len());
    for preset in Preset::ALL {
        let crytek = AoSettings::preset(Method::SsaoCrytek, preset);
        assert_eq!(
            (crytek.power, crytek.falloff, crytek.radius_multiplier),
            (1.0, 0.0, 1.0)
        );
        // The SAO paper's: a bias of 0.01 m at its 1 m radius, no further shaping.
        let sao = AoSettings::preset(Method::Sao, preset);
        assert_eq!(
            (sao.power, sao.falloff, sao.radius_multiplier, sao.bias),
            (1.0, 0.0, 1.0, 0.01)
        );
        // Unreal Engine 4's SSAO (PostProcessAmbientOcclusion.usf, Epic Games): its weight's
        // linear fade over the radius, its flat-surface bias of 5 units at Unreal's default
        // 200-unit radius, half the samples in pairs.
        let ue4 = AoSettings::preset(Method::Ue4Ssao, preset);
        assert_eq!(
            (ue4.power, ue4.falloff, ue4.radius_multiplier, ue4.bias),
            (1.0, 1.0, 1.0, 0.025)
        );
        let gtao = AoSettings::preset(Method::Gtao, preset);
        assert_eq!(ue4.samples_per_pixel(), gtao.samples_per_pixel());
        // Unity's MSVO defaults (Post-processing Stack v2): thickness modifier 1, every level,
        // no shaping.
        let msvo = AoSettings::preset(Method::Msvo, preset);
        assert_eq!(
            (msvo.power, msvo.falloff, msvo.radius_multiplier),
            (1.0, 0.0, 1.0)
        );
        assert_eq!((msvo.msvo.thickness, msvo.msvo.levels), (1.0, 5));
        assert_eq!(msvo.samples_per_pixel(), gtao.samples_per_pixel());
    }
    assert!(
        results
            .iter()
            .all(|r| !["ssao-crytek", "sao", "ue4-ssao", "msvo"]
                .contains(&r["method"].as_str().unwrap())),
        "the published forms are not tuned"
    );
    for r in results {
        let method: Method = r["method"].as_str().unwrap().parse().unwrap();
        let preset: Preset = r["preset"].as_str().unwrap().parse().unwrap();
        let back_faces = r["back_faces"].as_bool().unwrap();
        let s = if back_faces {
            AoSettings::preset_with_back_faces(method, preset)
        } else {
            AoSettings::preset(method, preset)
        };
        assert_eq!(s.vbao.back_faces, back_faces);
        let tuned = &r["tuned"];
        let value = |key: &str| tuned[key].as_f64().unwrap() as f32;
        let what = format!(
            "{} {} back faces {back_faces}",
            method.name(),
            preset.name()
        );
        // The shipped vbao presets hold issue 4's target on the views they were tuned on:
        // within GTAO's error on every one.
        if method == Method::Vbao {
            assert!(r["bound"].is_array(), "{what}: not held to GTAO's error");
            let excess = r["tuned_excess"].as_f64().unwrap();
            assert_eq!(excess, 0.0, "{what}: {excess} above GTAO's error");
        }
        assert_eq!(s.power, value("power"), "{what}: power");
        assert_eq!(s.falloff, value("falloff"), "{what}: falloff");
        assert_eq!(s.step_power, value("step_power"), "{what}: step_power");
        assert_eq!(
            s.radius_multiplier,
            value("radius_multiplier"),
            "{what}: radius multiplier"
        );
        let (knob, split) = match method {
            Method::SsaoCrytek => (s.bias, [s.ssao_crytek.sample_count, 1]),
            Method::Ssao => (s.bias, [s.ssao.sample_count, 1]),
            Method::Sao => (s.bias, [s.sao.sample_count, 1]),
            Method::Ue4Ssao => (s.bias, [s.ue4_ssao.sample_count, 1]),
            Method::Msvo => (s.msvo.thickness, [s.msvo.sample_count, 1]),
            Method::Hbao | Method::HbaoPlus => {
                (s.angle_bias, [s.hbao.direction_count, s.hbao.step_count])
            }
            Method::Gtao => (
                s.gtao.thickness,
                [s.gtao.slice_count, s.gtao.steps_per_side],
            ),
            Method::Vbao => (
                s.vbao.thickness,
                [s.vbao.slice_count, s.vbao.steps_per_side],
            ),
        };
        assert_eq!(knob, value("knob"), "{what}: {}", r["knob"]);
        let tuned_split: Vec<u32> = tuned["split"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_u64().unwrap() as u32)
            .collect();
        assert_eq!(split.to_vec(), tuned_split, "{what}: split");
    }
}

#[test]
fn the_settings_tune_writes_are_what_it_found_and_render_reads_them() {
    let (dir, json) = tune_room(&[
        "--size",
        "64x36",
        "--spp",
        "16",
        "--method",
        "gtao",
        "--write-settings",
        "tuned.toml",
    ]);
    let found = &json["results"][0]["tuned"];
    let text = std::fs::read_to_string(dir.path().join("tuned.toml")).unwrap();
    assert!(
        text.starts_with("# `aokit tune` found these for gtao at `low`"),
        "{text}"
    );
    let table: toml::Table = text.parse().unwrap();
    assert!(
        table.get("radius").is_none(),
        "the radius is the scene's: {text}"
    );
    let number = |v: &toml::Value| v.as_float().or(v.as_integer().map(|i| i as f64)).unwrap();
    assert_eq!(table["method"].as_str(), Some("gtao"));
    for (key, tuned) in [
        ("power", &found["power"]),
        ("radius_multiplier", &found["radius_multiplier"]),
        ("falloff", &found["falloff"]),
        ("step_power", &found["step_power"]),
    ] {
        assert!(
            (number(&table[key]) - tuned.as_f64().unwrap()).abs() < 1e-6,
            "{key}: {text}"
        );
    }
    // Every other setting is there, the spatial filter's radius among them.
    assert!(
        table["spatial"].as_table().unwrap().contains_key("radius"),
        "{text}"
    );
    assert!(
        text.contains("bias = 0.005\n"),
        "f32 values as they are: {text}"
    );
    let gtao = table["gtao"].as_table().unwrap();
    assert_eq!(
        number(&gtao["slice_count"]),
        found["split"][0].as_f64().unwrap()
    );
    // The settings flag reads the file as it is.
    let out = output(&mut command(
        dir.path(),
        &[
            "render",
            "--size",
            "32x18",
            "--settings",
            "tuned.toml",
            "--out",
            "r",
        ],
    ));
    ok(&out);
    // One method and one preset only: anything else is refused before the search.
    let refused = output(&mut command(
        dir.path(),
        &[
            "tune",
            "--method",
            "gtao,hbao",
            "--write-settings",
            "x.toml",
        ],
    ));
    assert!(!refused.status.success());
    assert!(
        String::from_utf8_lossy(&refused.stderr).contains("one method at one preset"),
        "{}",
        String::from_utf8_lossy(&refused.stderr)
    );
}

#[test]
fn tune_refuses_a_held_out_view_and_compare_names_the_script_that_makes_them() {
    let dir = tempfile::tempdir().unwrap();
    let tune = [
        "tune",
        "--view",
        "room",
        "--view",
        "./scenes/islanddm.obj@palms",
    ];
    let error = failure(&aokit(dir.path(), &tune));
    assert!(error.contains("islanddm.obj, a held-out scene"), "{error}");
    // Without the fetched meshes, the held-out set says how to make them.
    let compare = [
        "compare", "--views", "held-out", "--method", "gtao", "--preset", "low",
    ];
    let error = failure(&aokit(dir.path(), &compare));
    assert!(error.contains("scripts/fetch-scenes.sh"), "{error}");
}
