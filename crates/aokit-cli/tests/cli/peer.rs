//! `--peer` in bench and compare, and `aokit peer compile`, with the stand-in XeGTAO of
//! tests/data/peer-stand-in (aokit's own HLSL, whose outputs src/peer/tests.rs checks). Tests
//! that compile need glslangValidator: they skip without it, or fail where
//! `AOKIT_REQUIRE_GLSLANG=1` says it must be there (CI).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use serde_json::Value;

use crate::common::{command, failure, ok, output};

fn stand_in() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/peer-stand-in")
}

fn peer_arg(dir: &Path) -> String {
    format!("xegtao={}", dir.display())
}

/// Runs aokit in `dir` with `env` added.
fn aokit(dir: &Path, args: &[&str], env: &[(&str, &str)]) -> Output {
    output(command(dir, args).envs(env.iter().copied()))
}

/// Whether glslangValidator runs here.
fn have_compiler() -> bool {
    let found = Command::new("glslangValidator")
        .arg("--version")
        .output()
        .is_ok();
    if !found {
        assert!(
            std::env::var("AOKIT_REQUIRE_GLSLANG").as_deref() != Ok("1"),
            "AOKIT_REQUIRE_GLSLANG=1 but glslangValidator (Debian package glslang-tools) \
             does not run"
        );
        eprintln!("skipping: no glslangValidator (Debian package glslang-tools)");
    }
    found
}

const TINY: [&str; 9] = [
    "bench",
    "--size",
    "64x40",
    "--timing-frames",
    "3",
    "--warmup",
    "1",
    "--scene",
    "room",
];

/// Pass names of one bench configuration's JSON object, checked to be timed per pass where
/// the adapter has timestamps.
fn pass_names(object: &Value) -> Option<Vec<String>> {
    let passes = object["passes"].as_array()?;
    Some(
        passes
            .iter()
            .map(|p| p["name"].as_str().unwrap().to_string())
            .collect(),
    )
}

#[test]
fn bench_times_the_peer_interleaved_with_aokit() {
    if !have_compiler() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let peer = format!("--peer {} --preset low", peer_arg(&stand_in()));
    let denoised = format!("{peer} --set peer.denoise_passes=2 --set peer.shader=naga");
    let args: Vec<&str> = TINY
        .iter()
        .copied()
        .chain(["--json", "--compare", "--method gtao", &peer, &denoised])
        .collect();
    let json: Value = serde_json::from_str(&ok(&aokit(dir.path(), &args, &[]))).unwrap();
    let runs = json.as_array().unwrap();
    // Through naga, and passed through where the adapter can.
    let peer_runs: Vec<&Value> = runs[1..runs.len() - 1].iter().collect();
    assert!(!peer_runs.is_empty() && peer_runs.len() <= 2, "{json}");
    assert_eq!(peer_runs[0]["settings"]["method"], "xegtao-naga");
    if let Some(passthrough) = peer_runs.get(1) {
        assert_eq!(passthrough["settings"]["method"], "xegtao-passthrough");
        assert!(
            passthrough["configuration"]
                .as_str()
                .unwrap()
                .ends_with("[passthrough]")
        );
    }
    assert_eq!(peer_runs[0]["settings"]["quality"], "low");
    assert_eq!(peer_runs[0]["settings"]["slices"], 1);
    let last = runs.last().unwrap();
    assert_eq!(last["settings"]["denoise_passes"], 2);
    for run in runs {
        assert!(run["wall_ms"]["median"].as_f64().unwrap() > 0.0, "{run}");
        assert!(run["ratio_to_first"].as_f64().unwrap() > 0.0, "{run}");
    }
    if let Some(names) = pass_names(peer_runs[0]) {
        assert_eq!(
            names,
            ["xegtao_prefilter", "xegtao_main", "xegtao_denoise_last"]
        );
        assert_eq!(
            pass_names(last).unwrap(),
            [
                "xegtao_prefilter",
                "xegtao_main",
                "xegtao_denoise",
                "xegtao_denoise_last"
            ]
        );
    }

    // The table names the peer and its passes.
    let plain = peer_arg(&stand_in());
    let args: Vec<&str> = TINY.iter().copied().chain(["--peer", &plain]).collect();
    let table = ok(&aokit(dir.path(), &args, &[]));
    assert!(table.contains("xegtao-naga"), "{table}");

    // XeGTAO's depth unpacking cannot express an orthographic projection.
    let args: Vec<&str> = args.into_iter().chain(["--ortho-height", "5"]).collect();
    let err = failure(&aokit(dir.path(), &args, &[]));
    assert!(err.contains("orthographic"), "{err}");
}

#[test]
fn compare_scores_the_peer_on_the_same_pixels() {
    if !have_compiler() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let peer = peer_arg(&stand_in());
    let args = [
        "compare",
        "--scene",
        "room",
        "--size",
        "48x32",
        "--spp",
        "16",
        "--method",
        "gtao",
        "--preset",
        "low,high",
        "--timing-frames",
        "1",
        "--cache",
        "cache",
        "--out",
        "cmp",
        "--peer",
        &peer,
        "--set",
        "peer.shader=naga",
    ];
    let table = ok(&aokit(dir.path(), &args, &[]));
    assert!(table.contains("| xegtao-naga | high | 18 |"), "{table}");
    let json: Value = serde_json::from_str(
        &std::fs::read_to_string(dir.path().join("cmp/metrics.json")).unwrap(),
    )
    .unwrap();
    let rows: Vec<&Value> = json["results"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|r| r["method"] == "xegtao-naga")
        .collect();
    assert_eq!(rows.len(), 2);
    for row in rows {
        let rmse = row["all"]["rmse"].as_f64().unwrap();
        assert!(rmse > 0.0 && rmse < 1.0, "{row}");
    }
    assert!(
        dir.path()
            .join("cmp/images/room-front-xegtao-naga-high.png")
            .is_file()
    );
}

#[test]
fn a_compiled_folder_runs_without_the_compiler() {
    if !have_compiler() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let peer = peer_arg(&stand_in());
    ok(&aokit(
        dir.path(),
        &["peer", "compile", &peer, "--out", "compiled"],
        &[],
    ));
    let compiled = dir.path().join("compiled");
    let manifest = compiled.join("aokit-peer.json");
    assert!(compiled.join("main-ultra.spv").is_file());
    let no_compiler = [("AOKIT_GLSLANG", "/nonexistent/glslangValidator")];
    let args: Vec<&str> = TINY
        .iter()
        .copied()
        .chain(["--peer", "xegtao=compiled", "--set", "peer.shader=naga"])
        .collect();
    assert!(ok(&aokit(dir.path(), &args, &no_compiler)).contains("xegtao-naga"));

    // Modules compiled from another wrapper need not fit this aokit's bindings.
    let text = std::fs::read_to_string(&manifest).unwrap();
    let mut json: Value = serde_json::from_str(&text).unwrap();
    json["wrapper"] = "0000000000000000".into();
    std::fs::write(&manifest, json.to_string()).unwrap();
    let err = failure(&aokit(dir.path(), &args, &no_compiler));
    assert!(
        err.contains("another version of aokit's XeGTAO wrapper"),
        "{err}"
    );
}

#[test]
fn a_peer_aokit_cannot_run_is_an_error_naming_what_is_missing() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let bench = |peer: &str, extra: &[&str], env: &[(&str, &str)]| {
        let args: Vec<&str> = TINY
            .iter()
            .copied()
            .chain(["--peer", peer])
            .chain(extra.iter().copied())
            .collect();
        failure(&aokit(d, &args, env))
    };
    let err = bench("xegtao=/nonexistent/XeGTAO", &[], &[]);
    assert!(err.contains("no such folder"), "{err}");
    std::fs::create_dir(d.join("empty")).unwrap();
    let err = bench("xegtao=empty", &[], &[]);
    assert!(
        err.contains("Source/Rendering/Shaders/XeGTAO.h") && err.contains("XeGTAO.hlsli"),
        "{err}"
    );
    std::fs::create_dir(d.join("half")).unwrap();
    std::fs::write(d.join("half/XeGTAO.h"), "").unwrap();
    let err = bench("xegtao=half", &[], &[]);
    assert!(
        err.contains("half/XeGTAO.hlsli") && !err.contains("XeGTAO.h "),
        "{err}"
    );
    let err = bench("hbao=somewhere", &[], &[]);
    assert!(err.contains("unknown peer"), "{err}");

    // No compiler, by name or on PATH: the tool and its package are named.
    let peer = peer_arg(&stand_in());
    for env in [
        &[("AOKIT_GLSLANG", "/nonexistent/glslangValidator")][..],
        &[("PATH", "")][..],
    ] {
        let err = bench(&peer, &[], env);
        assert!(
            err.contains("glslangValidator") && err.contains("glslang-tools"),
            "{err}"
        );
    }

    // Options without a counterpart in a peer.
    let err = bench(&peer, &["--method", "gtao"], &[]);
    assert!(err.contains("--method") && err.contains("--peer"), "{err}");
    let err = bench(&peer, &["--set", "gtao.slice_count=3"], &[]);
    assert!(err.contains("gtao.slice_count"), "{err}");
    let err = failure(&aokit(
        d,
        &["peer", "compile", "xegtao=empty", "--out", "x"],
        &[],
    ));
    assert!(err.contains("XeGTAO.hlsli"), "{err}");
}
