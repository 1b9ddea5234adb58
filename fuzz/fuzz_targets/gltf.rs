//! glTF and GLB bytes through the loader `aokit` uses for `--scene file.glb`: no panic, and an
//! accepted file gives a mesh the renderer and tracer can use.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    // Either extension: the loader tells GLB from JSON by the magic, not the name.
    if let Ok(scene) = aokit_scene::load::gltf::load_slice("fuzz.glb", data) {
        aokit_fuzz_check::scene(&scene);
    }
});

#[path = "check.rs"]
mod aokit_fuzz_check;
