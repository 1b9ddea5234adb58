//! PFM and NPY passes, hand-written byte by byte.

use std::path::PathBuf;

use aokit_eval::{read_depth, read_normals};

fn pfm(
    kind: &str,
    width: u32,
    height: u32,
    little_endian: bool,
    rows_bottom_first: &[f32],
) -> Vec<u8> {
    let scale = if little_endian { "-1.0" } else { "1.0" };
    let mut bytes = format!("{kind}\n{width} {height}\n{scale}\n").into_bytes();
    for v in rows_bottom_first {
        bytes.extend(if little_endian {
            v.to_le_bytes()
        } else {
            v.to_be_bytes()
        });
    }
    bytes
}

/// A version 1.0 `.npy` with the header padded to 64 bytes as numpy does.
fn npy(descr: &str, shape: &str, data: &[u8]) -> Vec<u8> {
    let mut header = format!("{{'descr': '{descr}', 'fortran_order': False, 'shape': {shape}, }}");
    while (10 + header.len() + 1) % 64 != 0 {
        header.push(' ');
    }
    header.push('\n');
    let mut bytes = b"\x93NUMPY\x01\x00".to_vec();
    bytes.extend((header.len() as u16).to_le_bytes());
    bytes.extend(header.as_bytes());
    bytes.extend(data);
    bytes
}

fn le_f32(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}

fn write(dir: &tempfile::TempDir, name: &str, bytes: &[u8]) -> PathBuf {
    let path = dir.path().join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

#[test]
fn pfm_grey_both_byte_orders_flip_rows() {
    let dir = tempfile::tempdir().unwrap();
    // Stored bottom row first: the image's top row is [4, 5, 6].
    let stored = [1.0, 2.0, 3.0, 4.0, 5.0, f32::INFINITY];
    for little in [true, false] {
        let path = write(&dir, "depth.pfm", &pfm("Pf", 3, 2, little, &stored));
        let depth = read_depth(&path).unwrap();
        assert_eq!((depth.width, depth.height, depth.channels), (3, 2, 1));
        assert_eq!(
            depth.data,
            [4.0, 5.0, f32::INFINITY, 1.0, 2.0, 3.0],
            "little endian: {little}"
        );
    }
}

#[test]
fn pfm_rgb_normals() {
    let dir = tempfile::tempdir().unwrap();
    let bottom = [0.0, 0.0, 1.0, 1.0, 0.0, 0.0];
    let top = [0.0, 1.0, 0.0, 0.5, 0.5, 0.5];
    let stored: Vec<f32> = bottom.iter().chain(&top).copied().collect();
    for little in [true, false] {
        let path = write(&dir, "normal.PFM", &pfm("PF", 2, 2, little, &stored));
        let normals = read_normals(&path).unwrap();
        assert_eq!((normals.width, normals.height, normals.channels), (2, 2, 3));
        assert_eq!(&normals.data[..6], &top);
        assert_eq!(&normals.data[6..], &bottom);
    }
}

#[test]
fn malformed_pfm_is_an_error_naming_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let good = pfm("Pf", 2, 2, true, &[1.0; 4]);
    let cases: Vec<(&str, Vec<u8>)> = vec![
        ("empty", vec![]),
        ("wrong magic", b"P6\n2 2\n255\n".to_vec()),
        ("header only", b"Pf\n2".to_vec()),
        ("bad width", b"Pf\nx 2\n-1\n".to_vec()),
        (
            "zero scale",
            pfm("Pf", 2, 2, true, &[1.0; 4])
                .into_iter()
                .map(|b| if b == b'1' { b'0' } else { b })
                .collect(),
        ),
        ("zero size", pfm("Pf", 0, 2, true, &[])),
        ("truncated", good[..good.len() - 3].to_vec()),
        ("extra data", [good.clone(), vec![0; 4]].concat()),
        ("huge", b"Pf\n4294967295 4294967295\n-1\n\0\0\0\0".to_vec()),
        ("rgb as depth", pfm("PF", 1, 1, true, &[1.0; 3])),
    ];
    for (case, bytes) in cases {
        let path = write(&dir, "broken.pfm", &bytes);
        let error = read_depth(&path).unwrap_err().to_string();
        assert!(error.contains("broken.pfm"), "{case}: {error}");
    }
    let path = write(&dir, "grey.pfm", &good);
    assert!(
        read_normals(&path)
            .unwrap_err()
            .to_string()
            .contains("grey.pfm")
    );
}

#[test]
fn npy_depth_and_normals() {
    let dir = tempfile::tempdir().unwrap();
    let values: Vec<f32> = (0..6).map(|i| i as f32 + 0.5).collect();
    let path = write(&dir, "depth.npy", &npy("<f4", "(2, 3)", &le_f32(&values)));
    let depth = read_depth(&path).unwrap();
    assert_eq!((depth.width, depth.height, depth.channels), (3, 2, 1));
    assert_eq!(depth.data, values);

    let path = write(
        &dir,
        "depth1.NPY",
        &npy("<f4", "(2, 3, 1)", &le_f32(&values)),
    );
    assert_eq!(read_depth(&path).unwrap().data, values);

    let big_endian: Vec<u8> = values.iter().flat_map(|v| v.to_be_bytes()).collect();
    let path = write(&dir, "be.npy", &npy(">f4", "(2, 3)", &big_endian));
    assert_eq!(read_depth(&path).unwrap().data, values);

    let doubles: Vec<u8> = values
        .iter()
        .flat_map(|&v| f64::from(v).to_le_bytes())
        .collect();
    let path = write(&dir, "f8.npy", &npy("<f8", "(2, 3)", &doubles));
    assert_eq!(read_depth(&path).unwrap().data, values);

    let normals: Vec<f32> = (0..18).map(|i| i as f32 * 0.1).collect();
    let path = write(
        &dir,
        "normal.npy",
        &npy("<f4", "(2, 3, 3)", &le_f32(&normals)),
    );
    let image = read_normals(&path).unwrap();
    assert_eq!((image.width, image.height, image.channels), (3, 2, 3));
    assert_eq!(image.data, normals);
}

#[test]
fn npy_version_2_header() {
    let dir = tempfile::tempdir().unwrap();
    let header = "{'descr': '<f4', 'fortran_order': False, 'shape': (1, 2), }\n";
    let mut bytes = b"\x93NUMPY\x02\x00".to_vec();
    bytes.extend((header.len() as u32).to_le_bytes());
    bytes.extend(header.as_bytes());
    bytes.extend(le_f32(&[3.0, 4.0]));
    let path = write(&dir, "v2.npy", &bytes);
    assert_eq!(read_depth(&path).unwrap().data, [3.0, 4.0]);
}

#[test]
fn malformed_npy_is_an_error_naming_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let six = le_f32(&[1.0; 6]);
    let fortran = {
        let good = npy("<f4", "(2, 3)", &six);
        String::from_utf8_lossy(&good)
            .replace("False", "True ")
            .into_bytes()
    };
    let cases: Vec<(&str, Vec<u8>)> = vec![
        ("empty", vec![]),
        ("no magic", b"NUMPY".to_vec()),
        ("version 9", b"\x93NUMPY\x09\x00\x00\x00".to_vec()),
        ("header cut", npy("<f4", "(2, 3)", &six)[..20].to_vec()),
        ("int dtype", npy("<i4", "(2, 3)", &six)),
        ("fortran order", fortran),
        ("3 channels as depth", npy("<f4", "(2, 1, 3)", &six)),
        ("1-D", npy("<f4", "(6,)", &six)),
        ("zero size", npy("<f4", "(0, 3)", &[])),
        ("truncated data", npy("<f4", "(2, 3)", &six[..20])),
        ("bad shape", npy("<f4", "(2, x)", &six)),
        ("huge", npy("<f4", "(99999999999, 99999999999)", &six)),
        ("not a dict", {
            let mut b = npy("<f4", "(2, 3)", &six);
            b[10] = b'[';
            b
        }),
    ];
    for (case, bytes) in cases {
        let path = write(&dir, "broken.npy", &bytes);
        let error = read_depth(&path).unwrap_err().to_string();
        assert!(error.contains("broken.npy"), "{case}: {error}");
    }
    let path = write(&dir, "grey.npy", &npy("<f4", "(2, 3)", &six));
    assert!(
        read_normals(&path)
            .unwrap_err()
            .to_string()
            .contains("grey.npy")
    );
}

#[test]
fn unknown_extensions_and_missing_files() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(&dir, "depth.tiff", b"II*\0");
    let error = read_depth(&path).unwrap_err().to_string();
    assert!(
        error.contains("depth.tiff") && error.contains(".exr"),
        "{error}"
    );
    let missing = dir.path().join("nothing.pfm");
    assert!(
        read_depth(&missing)
            .unwrap_err()
            .to_string()
            .contains("nothing.pfm")
    );
}
