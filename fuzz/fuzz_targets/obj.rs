//! OBJ bytes and the `<stem>-cameras.json` sidecar (after the first NUL byte, when there is
//! one) through the loader `aokit` uses for `--scene file.obj`.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let (obj, sidecar) = match data.iter().position(|&b| b == 0) {
        Some(nul) => (&data[..nul], Some(&data[nul + 1..])),
        None => (data, None),
    };
    if let Ok(scene) = aokit_scene::load::obj::load_slice("fuzz.obj", obj, sidecar) {
        aokit_fuzz_check::scene(&scene);
        for camera in &scene.cameras {
            // The sidecar's cameras are validated when loaded.
            camera.validate().expect("a sidecar camera validates");
        }
    }
});

#[path = "check.rs"]
mod aokit_fuzz_check;
