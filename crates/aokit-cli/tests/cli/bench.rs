//! `aokit bench`, at tiny sizes: the structure of its output, never the times' magnitudes.

use std::process::Output;

use serde_json::Value;

use crate::common::{aokit, command, output, text};

/// A tiny, quick run: every test starts from these.
const TINY: [&str; 8] = [
    "--size",
    "64x40",
    "--timing-frames",
    "3",
    "--warmup",
    "1",
    "--scene",
    "room",
];

fn bench(args: &[&str]) -> Output {
    let dir = tempfile::tempdir().unwrap();
    output(command(dir.path(), &["bench"]).args(args))
}

/// Runs a bench that must succeed; returns stdout and stderr.
fn bench_ok(args: &[&str]) -> (String, String) {
    let out = bench(&[&TINY[..], args].concat());
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "{args:?}: {stderr}");
    (text(&out.stdout), stderr)
}

/// A finite, non-negative number of milliseconds.
fn assert_ms(value: &Value, what: &str) {
    let ms = value
        .as_f64()
        .unwrap_or_else(|| panic!("{what} is not a number: {value}"));
    assert!(ms.is_finite() && ms >= 0.0, "{what} = {ms}");
}

/// `{"median", "p10", "p90"}`, each finite and >= 0.
fn assert_stats(value: &Value, what: &str) {
    for key in ["median", "p10", "p90"] {
        assert_ms(&value[key], &format!("{what}.{key}"));
    }
}

/// Checks one configuration's JSON object; returns its pass names (empty without timestamps).
fn check_object(object: &Value, stderr: &str) -> Vec<String> {
    assert!(object["adapter"].as_str().is_some_and(|a| !a.is_empty()));
    assert_eq!(object["size"], serde_json::json!([64, 40]));
    assert!(object["settings"]["method"].is_string(), "{object}");
    assert!(object["settings"]["radius"].is_number(), "{object}");
    assert_stats(&object["cpu_encode_ms"], "cpu_encode_ms");
    assert_stats(&object["wall_ms"], "wall_ms");
    if object["passes"].is_null() {
        assert!(object["total_gpu_ms"].is_null(), "{object}");
        assert!(stderr.contains("TIMESTAMP_QUERY"), "{stderr}");
        return Vec::new();
    }
    assert_stats(&object["total_gpu_ms"], "total_gpu_ms");
    let passes = object["passes"].as_array().expect("passes is an array");
    passes
        .iter()
        .map(|pass| {
            let name = pass["name"]
                .as_str()
                .expect("a pass has a name")
                .to_string();
            assert_stats(&pass["gpu_ms"], &name);
            name
        })
        .collect()
}

/// The numbers on a table row after its first column.
fn row_numbers(line: &str) -> Vec<f64> {
    line.split_whitespace()
        .skip(1)
        .map(|v| v.parse::<f64>().unwrap_or_else(|e| panic!("`{line}`: {e}")))
        .collect()
}

#[test]
fn text_has_a_header_a_row_per_pass_a_total_and_the_encode_time() {
    let (stdout, stderr) = bench_ok(&["--method", "gtao", "--preset", "low"]);
    let lines: Vec<&str> = stdout.lines().collect();
    let header = lines[0];
    for part in ["adapter:", "64x40", "method: gtao", "preset: low"] {
        assert!(header.contains(part), "{header}");
    }
    if stdout.contains("not measured") {
        assert!(stderr.contains("TIMESTAMP_QUERY"), "{stderr}");
    } else {
        for pass in ["linear_depth", "gtao", "total"] {
            let row = lines
                .iter()
                .find(|l| l.split_whitespace().next() == Some(pass))
                .unwrap_or_else(|| panic!("no row {pass}:\n{stdout}"));
            let numbers = row_numbers(row);
            assert_eq!(numbers.len(), 3, "{row}");
            assert!(numbers.iter().all(|v| v.is_finite() && *v >= 0.0), "{row}");
        }
    }
    let encode = lines
        .iter()
        .find(|l| l.starts_with("CPU encode"))
        .unwrap_or_else(|| panic!("no CPU encode line:\n{stdout}"));
    assert!(
        encode.contains("median") && encode.contains("p90"),
        "{encode}"
    );
    assert!(stdout.contains("wall time"), "{stdout}");
}

#[test]
fn json_is_one_object_with_every_field() {
    let (stdout, stderr) = bench_ok(&["--json", "--set", "spatial.enabled=true"]);
    let object: Value = serde_json::from_str(&stdout).expect("stdout is one JSON value");
    assert!(object.is_object(), "{object}");
    assert_eq!(object["settings"]["method"], "gtao");
    assert_eq!(object["settings"]["spatial"]["enabled"], true);
    let passes = check_object(&object, &stderr);
    if !passes.is_empty() {
        assert_eq!(passes, ["linear_depth", "gtao", "edge_filter"]);
    }
}

#[test]
fn compare_gives_one_entry_per_configuration_against_the_first() {
    let configurations = [
        "--compare",
        "--method gtao",
        "--method hbao --set resolution=half",
    ];
    let (stdout, stderr) = bench_ok(&[&["--json"][..], &configurations[..]].concat());
    let array: Value = serde_json::from_str(&stdout).expect("stdout is one JSON value");
    let entries = array.as_array().expect("an array");
    assert_eq!(entries.len(), 2, "{array}");
    assert_eq!(entries[0]["ratio_to_first"].as_f64(), Some(1.0));
    assert_ms(&entries[1]["ratio_to_first"], "ratio_to_first");
    assert_eq!(entries[0]["settings"]["method"], "gtao");
    assert_eq!(entries[1]["settings"]["method"], "hbao");
    assert_eq!(entries[1]["settings"]["resolution"], "half");
    let first = check_object(&entries[0], &stderr);
    let second = check_object(&entries[1], &stderr);
    if !first.is_empty() {
        assert_eq!(first, ["linear_depth", "gtao", "edge_filter"]);
        // Below full resolution the downsample and upsample read the depth themselves; the
        // presets' edge filter runs at the working resolution, before the upsample.
        assert_eq!(second, ["downsample", "hbao", "edge_filter", "upsample"]);
    }

    let (stdout, _) = bench_ok(&configurations);
    let rows: Vec<&str> = stdout
        .lines()
        .filter(|l| l.starts_with("1 ") || l.starts_with("2 "))
        .collect();
    assert_eq!(rows.len(), 2, "{stdout}");
    assert!(
        rows[0].contains("1.000") && rows[1].contains("--method hbao"),
        "{stdout}"
    );
}

#[test]
fn bad_input_is_refused_with_exit_code_2_naming_the_problem() {
    const QUICK: [&str; 4] = ["--warmup", "1", "--size", "64x40"];
    let cases: [(&[&str], &str); 9] = [
        (&["--timing-frames", "0"], "--timing-frames"),
        (&[&QUICK[..], &["--method", "nope"]].concat(), "nope"),
        (&[&QUICK[..], &["--preset", "nope"]].concat(), "nope"),
        (
            &[&QUICK[..], &["--set", "gtao.slices=2"]].concat(),
            "gtao.slices",
        ),
        (&["--size", "0x40"], "at least 1"),
        (&["--size", "20000x40"], "at most"),
        (
            &[
                &TINY[..],
                &["--compare", "--method gtao", "--timing-frames 0"],
            ]
            .concat(),
            "--timing-frames",
        ),
        (
            &[&TINY[..], &["--compare", "--method gtao", "--size 32x20"]].concat(),
            "G-buffer",
        ),
        (
            &[&TINY[..], &["--compare", "--method \"gtao"]].concat(),
            "quote",
        ),
    ];
    for (args, named) in cases {
        let out = bench(args);
        let stderr = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(named), "{args:?}: {stderr}");
        assert!(out.stdout.is_empty(), "{args:?}: {}", text(&out.stdout));
    }
}

#[test]
fn separable_hbao_is_timed_per_pass_and_refused_to_hbao_plus() {
    let separable = ["--method", "hbao", "--set", "hbao.variant=separable"];
    let (stdout, stderr) =
        bench_ok(&[&["--json", "--set", "resolution=half"][..], &separable].concat());
    let object: Value = serde_json::from_str(&stdout).expect("stdout is one JSON value");
    assert_eq!(object["settings"]["hbao"]["variant"], "separable");
    let passes = check_object(&object, &stderr);
    if !passes.is_empty() {
        assert_eq!(
            passes,
            [
                "downsample",
                "hbao_rows",
                "hbao_columns",
                "edge_filter",
                "upsample"
            ]
        );
    }
    let out = bench(
        &[
            &TINY[..],
            &["--method", "hbao-plus", "--set", "hbao.variant=separable"],
        ]
        .concat(),
    );
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("hbao.variant"), "{stderr}");
}

#[test]
fn msvo_is_timed_per_level_and_refuses_an_odd_sample_count() {
    let (stdout, stderr) = bench_ok(&["--json", "--method", "msvo"]);
    let object: Value = serde_json::from_str(&stdout).expect("stdout is one JSON value");
    assert_eq!(object["settings"]["msvo"]["levels"], 5);
    let passes = check_object(&object, &stderr);
    if !passes.is_empty() {
        // The chain (one pass for its four coarser levels), each level's obscurance, then the
        // merges coarsest first.
        let msvo: Vec<&str> = passes
            .iter()
            .map(String::as_str)
            .filter(|p| p.starts_with("depth_mips") || p.starts_with("msvo"))
            .collect();
        assert_eq!(
            msvo,
            [
                "depth_mips",
                "msvo_obscurance_0",
                "msvo_obscurance_1",
                "msvo_obscurance_2",
                "msvo_obscurance_3",
                "msvo_obscurance_4",
                "msvo_merge_3",
                "msvo_merge_2",
                "msvo_merge_1",
                "msvo_merge_0",
            ]
        );
    }
    let out = bench(
        &[
            &TINY[..],
            &["--method", "msvo", "--set", "msvo.sample_count=7"],
        ]
        .concat(),
    );
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("msvo.sample_count"), "{stderr}");
}

#[test]
fn the_old_frames_flag_still_times_and_says_its_new_name() {
    let dir = tempfile::tempdir().unwrap();
    let out = aokit(
        dir.path(),
        &[
            "bench", "--size", "32x20", "--frames", "2", "--warmup", "0", "--json",
        ],
    );
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.contains("`aokit bench --frames` is now `--timing-frames`"),
        "{stderr}"
    );
    let object: Value = serde_json::from_str(&text(&out.stdout)).unwrap();
    assert_eq!(object["frames"], 2);
}
