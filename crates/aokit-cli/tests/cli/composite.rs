//! `aokit render`'s composite flags, run in fresh temporary directories.

use std::path::Path;

use crate::common::{aokit, text};

/// Renders the room at a small size into `dir/out` with `extra` flags; returns (ao.png, lit.png)
/// pixels.
fn render(dir: &Path, out: &str, extra: &[&str]) -> (Vec<u8>, Vec<u8>) {
    let mut args = vec!["render", "--size", "96x64", "--preset", "low", "--out", out];
    args.extend_from_slice(extra);
    let result = aokit(dir, &args);
    assert!(
        result.status.success(),
        "{extra:?}: {}",
        text(&result.stderr)
    );
    let read = |file: &str| image::open(dir.join(out).join(file)).unwrap().into_bytes();
    (read("ao.png"), read("lit.png"))
}

#[test]
fn composite_flags_change_the_lit_image_but_not_the_ao() {
    let dir = tempfile::tempdir().unwrap();
    let (ao, lit) = render(dir.path(), "default", &[]);
    let variants: &[&[&str]] = &[
        &["--no-multi-bounce"],
        &["--multi-bounce", "none"],
        &["--multi-bounce", "closed-form"],
        &["--specular-occlusion", "none"],
        &["--specular-occlusion", "gtso"],
        &["--roughness", "0.05"],
    ];
    for (k, flags) in variants.iter().enumerate() {
        let (other_ao, other_lit) = render(dir.path(), &format!("v{k}"), flags);
        assert_eq!(other_ao, ao, "{flags:?} changed ao.png");
        assert_ne!(other_lit, lit, "{flags:?} left lit.png as it was");
    }
    // The defaults spelled out (a bare --multi-bounce is gtao), and the last of two opposite
    // flags winning, change nothing.
    for flags in [
        &[
            "--multi-bounce",
            "gtao",
            "--specular-occlusion",
            "frostbite",
            "--roughness",
            "0.5",
        ][..],
        &["--multi-bounce", "--roughness", "0.5"][..],
        &["--no-multi-bounce", "--multi-bounce"][..],
        &[
            "--multi-bounce",
            "closed-form",
            "--no-multi-bounce",
            "--multi-bounce=gtao",
        ][..],
    ] {
        assert_eq!(render(dir.path(), "same", flags).1, lit, "{flags:?}");
    }
    // --no-multi-bounce is --multi-bounce none, and wins when it comes last.
    let none = render(dir.path(), "none", &["--multi-bounce", "none"]).1;
    for flags in [
        &["--no-multi-bounce"][..],
        &["--multi-bounce", "closed-form", "--no-multi-bounce"][..],
    ] {
        assert_eq!(render(dir.path(), "same", flags).1, none, "{flags:?}");
    }
}

#[test]
fn gtso_with_a_method_without_bent_normals_falls_back_and_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let out = aokit(
        dir.path(),
        &[
            "render",
            "--size",
            "48x32",
            "--method",
            "ssao",
            "--specular-occlusion",
            "gtso",
        ],
    );
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.contains("ssao has no bent normals"), "{stderr}");
}

#[test]
fn bad_composite_values_exit_2_and_name_the_flag() {
    let dir = tempfile::tempdir().unwrap();
    let cases: &[(&[&str], &str)] = &[
        (&["--roughness", "1.5"], "outside [0, 1]"),
        (&["--roughness", "-0.1"], "outside [0, 1]"),
        (&["--roughness", "nan"], "outside [0, 1]"),
        (&["--roughness", "rough"], "not a number"),
        (&["--specular-occlusion", "ssr"], "none, gtso, frostbite"),
        (&["--multi-bounce", "on"], "none, gtao, closed-form"),
    ];
    for (flags, expected) in cases {
        let mut args = vec!["render", "--size", "8x8"];
        args.extend_from_slice(flags);
        let out = aokit(dir.path(), &args);
        let stderr = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{flags:?}: {stderr}");
        assert!(
            stderr.contains(flags[0]) && stderr.contains(expected),
            "{flags:?}: expected `{}` and `{expected}` in: {stderr}",
            flags[0]
        );
        assert!(
            !dir.path().join("aokit-out").exists(),
            "{flags:?} wrote output"
        );
    }
}
