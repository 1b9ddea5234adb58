//! EXR round trips and channel choice.

use std::path::Path;

use aokit_eval::{EvalError, read_depth, read_normals, read_scalar_exr, write_exr};
use exr::prelude::{
    AnyChannel, AnyChannels, Encoding, FlatSamples, Image, ImageAttributes, Layer, LayerAttributes,
    SmallVec, WritableImage, f16,
};

const SIZE: [u32; 2] = [3, 2];

fn ramp(offset: f32) -> Vec<f32> {
    (0..6).map(|i| offset + i as f32 * 0.25).collect()
}

/// A layer of the given channels, for writing files the crate's own writer would not produce.
fn layer(
    name: Option<&str>,
    channels: Vec<(&str, FlatSamples)>,
) -> Layer<AnyChannels<FlatSamples>> {
    let list: SmallVec<[AnyChannel<FlatSamples>; 4]> = channels
        .into_iter()
        .map(|(n, s)| AnyChannel::new(n, s))
        .collect();
    let attributes = name.map_or_else(LayerAttributes::default, LayerAttributes::named);
    Layer::new(
        (3, 2),
        attributes,
        Encoding::UNCOMPRESSED,
        AnyChannels::sort(list),
    )
}

fn message(e: EvalError) -> String {
    e.to_string()
}

#[test]
fn scalar_round_trip_keeps_every_value() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("ao.exr");
    let values = vec![0.0, 0.25, 1.0, f32::NAN, f32::INFINITY, 1e-30];
    write_exr(&path, SIZE, &[("Y", values.clone())]).unwrap();
    let image = read_scalar_exr(&path).unwrap();
    assert_eq!((image.width, image.height, image.channels), (3, 2, 1));
    for (a, b) in image.data.iter().zip(&values) {
        assert!(a.to_bits() == b.to_bits(), "{a} vs {b}");
    }
}

#[test]
fn depth_round_trip_with_z_and_qualified_names() {
    let dir = tempfile::tempdir().unwrap();
    for name in ["Z", "Depth.V", "ViewLayer.Depth.Z", "depth", "Y", "R"] {
        let path = dir.path().join("depth.exr");
        write_exr(&path, SIZE, &[(name, ramp(1.0))]).unwrap();
        let depth = read_depth(&path).unwrap();
        assert_eq!(
            (depth.width, depth.height, depth.channels),
            (3, 2, 1),
            "{name}"
        );
        assert_eq!(depth.data, ramp(1.0), "{name}");
    }
}

#[test]
fn depth_is_found_among_other_passes() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("passes.EXR");
    write_exr(
        &path,
        SIZE,
        &[
            ("ViewLayer.Combined.R", ramp(0.0)),
            ("ViewLayer.Combined.G", ramp(0.0)),
            ("ViewLayer.Depth.Z", ramp(5.0)),
            ("ViewLayer.Normal.X", ramp(0.1)),
            ("ViewLayer.Normal.Y", ramp(0.2)),
            ("ViewLayer.Normal.Z", ramp(0.3)),
        ],
    )
    .unwrap();
    assert_eq!(read_depth(&path).unwrap().data, ramp(5.0));
    let normals = read_normals(&path).unwrap();
    assert_eq!(normals.channels, 3);
    assert_eq!(&normals.data[0..3], &[0.1, 0.2, 0.3]);
}

#[test]
fn unrecognised_channels_are_listed() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("odd.exr");
    write_exr(&path, SIZE, &[("foo", ramp(0.0)), ("bar", ramp(0.0))]).unwrap();
    let text = message(read_depth(&path).unwrap_err());
    assert!(
        text.contains("odd.exr") && text.contains("foo") && text.contains("bar"),
        "{text}"
    );
    let text = message(read_normals(&path).unwrap_err());
    assert!(text.contains("odd.exr") && text.contains("foo"), "{text}");
    let text = message(read_scalar_exr(&path).unwrap_err());
    assert!(text.contains("odd.exr") && text.contains("bar"), "{text}");

    // A lone channel is used whatever its name.
    write_exr(&path, SIZE, &[("foo", ramp(2.0))]).unwrap();
    assert_eq!(read_depth(&path).unwrap().data, ramp(2.0));
    assert_eq!(read_scalar_exr(&path).unwrap().data, ramp(2.0));
}

#[test]
fn ambiguous_depth_is_an_error() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("normals-only.exr");
    write_exr(
        &path,
        SIZE,
        &[("N.X", ramp(0.0)), ("N.Y", ramp(0.0)), ("N.Z", ramp(0.0))],
    )
    .unwrap();
    let text = message(read_depth(&path).unwrap_err());
    assert!(
        text.contains("normals-only.exr") && text.contains("N.Y") && text.contains("N.Z"),
        "{text}"
    );
}

#[test]
fn normals_round_trip_rgb_and_xyz() {
    let dir = tempfile::tempdir().unwrap();
    for names in [
        ["R", "G", "B"],
        ["X", "Y", "Z"],
        ["Normal.X", "Normal.Y", "Normal.Z"],
    ] {
        let path = dir.path().join("normal.exr");
        write_exr(
            &path,
            SIZE,
            &[
                (names[0], ramp(0.0)),
                (names[1], ramp(10.0)),
                (names[2], ramp(20.0)),
            ],
        )
        .unwrap();
        let normals = read_normals(&path).unwrap();
        assert_eq!((normals.width, normals.height, normals.channels), (3, 2, 3));
        for i in 0..6 {
            let expected = [ramp(0.0)[i], ramp(10.0)[i], ramp(20.0)[i]];
            assert_eq!(
                &normals.data[i * 3..i * 3 + 3],
                &expected,
                "{names:?} pixel {i}"
            );
        }
    }
}

#[test]
fn half_float_files_are_converted() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("half.exr");
    let half = |v: Vec<f32>| FlatSamples::F16(v.into_iter().map(f16::from_f32).collect());
    let image = Image::from_layer(layer(
        None,
        vec![
            ("B", half(ramp(2.0))),
            ("G", half(ramp(1.0))),
            ("R", half(ramp(0.0))),
            ("Z", half(ramp(3.0))),
        ],
    ));
    image.write().to_file(&path).unwrap();
    // Quarter steps are exact in half precision.
    assert_eq!(read_depth(&path).unwrap().data, ramp(3.0));
    let normals = read_normals(&path).unwrap();
    assert_eq!(&normals.data[3..6], &[0.25, 1.25, 2.25]);
}

#[test]
fn multi_part_files_use_the_first_layer_with_a_match() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("parts.exr");
    let f32s = FlatSamples::F32;
    let layers = vec![
        layer(
            Some("beauty"),
            vec![("A", f32s(ramp(0.0))), ("G", f32s(ramp(0.0)))],
        ),
        layer(Some("depth"), vec![("Z", f32s(ramp(7.0)))]),
        layer(
            Some("normal"),
            vec![
                ("X", f32s(ramp(1.0))),
                ("Y", f32s(ramp(2.0))),
                ("Z", f32s(ramp(3.0))),
            ],
        ),
    ];
    Image::from_layers(ImageAttributes::with_size((3, 2)), layers)
        .write()
        .to_file(&path)
        .unwrap();
    assert_eq!(read_depth(&path).unwrap().data, ramp(7.0));
    assert_eq!(&read_normals(&path).unwrap().data[0..3], &[1.0, 2.0, 3.0]);
}

#[test]
fn writer_refuses_bad_data() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.exr");
    type Channels<'a> = Vec<(&'a str, Vec<f32>)>;
    let cases: Vec<(&str, [u32; 2], Channels)> = vec![
        ("empty size", [0, 2], vec![("Y", vec![])]),
        ("no channels", SIZE, vec![]),
        ("short channel", SIZE, vec![("Y", vec![0.0; 5])]),
        ("duplicate", SIZE, vec![("Y", ramp(0.0)), ("Y", ramp(0.0))]),
        ("empty name", SIZE, vec![("", ramp(0.0))]),
        ("non-Latin-1 name", SIZE, vec![("深さ", ramp(0.0))]),
    ];
    for (case, size, channels) in cases {
        let text = message(write_exr(&path, size, &channels).unwrap_err());
        assert!(text.contains("bad.exr"), "{case}: {text}");
    }
    assert!(!path.exists());
}

#[test]
fn unreadable_files_name_the_path() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("missing.exr");
    assert!(message(read_scalar_exr(&missing).unwrap_err()).contains("missing.exr"));
    let garbage = dir.path().join("garbage.exr");
    std::fs::write(&garbage, b"not an exr at all").unwrap();
    for result in [
        read_scalar_exr(&garbage),
        read_depth(&garbage),
        read_normals(&garbage),
    ] {
        assert!(message(result.unwrap_err()).contains("garbage.exr"));
    }
    // A real file cut short.
    let good = dir.path().join("good.exr");
    write_exr(&good, [64, 64], &[("Y", vec![0.5; 64 * 64])]).unwrap();
    let bytes = std::fs::read(&good).unwrap();
    for len in [0, 8, bytes.len() / 2, bytes.len() - 1] {
        let cut = dir.path().join("cut.exr");
        std::fs::write(&cut, &bytes[..len]).unwrap();
        let result = read_scalar_exr(&cut);
        assert!(
            result
                .as_ref()
                .is_err_and(|e| e.to_string().contains("cut.exr")),
            "{len}: {result:?}"
        );
    }
    let unwritable = Path::new("/nonexistent-dir/ao.exr");
    assert!(
        message(write_exr(unwritable, SIZE, &[("Y", ramp(0.0))]).unwrap_err())
            .contains("/nonexistent-dir/ao.exr")
    );
}

/// Found by the `exr` fuzz target (fuzz/): a 610-byte file whose header claims a large image
/// made the ZIP decoder allocate 2.4 GB before it found the data missing. The headers are
/// checked first: a claim past aokit's pixel budget, or of far more sample bytes than the file
/// holds, is refused without the allocation.
#[test]
fn an_exr_claiming_far_more_than_it_holds_is_refused_before_allocating() {
    let crash = include_bytes!("data/fuzz-claims-2.4-gb.exr");
    for result in [
        aokit_eval::parse_depth(Path::new("crash.exr"), crash),
        aokit_eval::parse_normals(Path::new("crash.exr"), crash),
    ] {
        let err = result.unwrap_err().to_string();
        assert!(
            err.starts_with("crash.exr: ")
                && (err.contains("times its 610 bytes") || err.contains("pixels (8192x8192)")),
            "{err}"
        );
    }
}
