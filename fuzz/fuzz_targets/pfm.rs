//! `.pfm` depth and normal passes as `aokit ao --depth/--normals` read them: no panic, and an
//! accepted file gives an image of the size it claims.
#![no_main]

use std::path::Path;

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(depth) = aokit_eval::parse_depth(Path::new("depth.pfm"), data) {
        aokit_fuzz_check::image(&depth, 1);
    }
    if let Ok(normals) = aokit_eval::parse_normals(Path::new("normals.pfm"), data) {
        aokit_fuzz_check::image(&normals, 3);
    }
});

#[path = "check.rs"]
mod aokit_fuzz_check;
