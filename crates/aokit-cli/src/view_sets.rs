//! The two sets of views quality is measured on: the tuning views, which `aokit tune` searches
//! the presets on, and the held-out views, of scenes the search never reads, which show whether
//! the presets' error holds on scenes they were not fitted to (docs/quality.md).

use std::path::Path;

use anyhow::{Result, bail};
use clap::ValueEnum;

/// The views `aokit tune` searches when none is named: the built-in room, stairs and thin, and
/// Sponza's four cameras.
pub const TUNING: [&str; 7] = [
    "room",
    "stairs",
    "thin",
    "scenes/sponza.obj@atrium",
    "scenes/sponza.obj@arcade",
    "scenes/sponza.obj@gallery",
    "scenes/sponza.obj@floor",
];

/// Views of three game levels that the presets never saw: giant furniture and railings
/// (`oa_minia`), a town of steps, arcades and balconies (`oa_rpg3dm2`), palms and a pavilion
/// (`islanddm`). `bash scripts/fetch-scenes.sh` makes the files (scenes/README.md).
pub const HELD_OUT: [&str; 10] = [
    "scenes/oa_minia.obj@chairs",
    "scenes/oa_minia.obj@table",
    "scenes/oa_minia.obj@stairs",
    "scenes/oa_rpg3dm2.obj@plaza",
    "scenes/oa_rpg3dm2.obj@steps",
    "scenes/oa_rpg3dm2.obj@hall",
    "scenes/oa_rpg3dm2.obj@court",
    "scenes/islanddm.obj@palms",
    "scenes/islanddm.obj@palm",
    "scenes/islanddm.obj@pavilion",
];

/// A named set of views, as `aokit compare --views` takes it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ViewSet {
    /// The views `aokit tune` fits the presets on.
    Tuning,
    /// The views of scenes `aokit tune` never reads.
    HeldOut,
}

impl ViewSet {
    /// The set's views, as SCENE@CAMERA.
    pub fn views(self) -> &'static [&'static str] {
        match self {
            Self::Tuning => &TUNING,
            Self::HeldOut => &HELD_OUT,
        }
    }

    /// The set's views, each checked to be here: a held-out scene missing is named with the
    /// script that makes it, rather than as a file not found.
    pub fn present_views(self) -> Result<Vec<String>> {
        for view in self.views() {
            let file = scene_file(view);
            if file.ends_with(".obj") && !Path::new(file).is_file() {
                bail!(
                    "{file} is not here: the held-out scenes are converted from Debian packages by \
                     `bash scripts/fetch-scenes.sh`, run in the repository root (scenes/README.md)"
                );
            }
        }
        Ok(self.views().iter().map(|v| v.to_string()).collect())
    }
}

/// The scene part of SCENE or SCENE@CAMERA.
fn scene_file(view: &str) -> &str {
    view.rsplit_once('@').map_or(view, |(scene, _)| scene)
}

/// The file name of each held-out scene: a scene is held out whole, from any of its cameras
/// and under whatever path names it.
fn held_out_scenes() -> Vec<&'static str> {
    let mut names: Vec<&str> = HELD_OUT
        .iter()
        .filter_map(|view| Path::new(scene_file(view)).file_name()?.to_str())
        .collect();
    names.dedup();
    names
}

/// An error when `view` shows a held-out scene: what `aokit tune` checks every view against,
/// so that no search ever reads one.
pub fn check_not_held_out(view: &str) -> Result<()> {
    let name = Path::new(scene_file(view)).file_name();
    if let Some(name) = name.and_then(|n| n.to_str())
        && held_out_scenes().contains(&name)
    {
        bail!(
            "{view} shows {name}, a held-out scene: `aokit tune` never reads it, so that its \
             error measures how the presets hold on scenes they were not fitted to \
             (docs/quality.md)"
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_held_out_scene_is_in_the_tuning_list() {
        for view in TUNING {
            assert!(!HELD_OUT.contains(&view), "{view} is in both lists");
            check_not_held_out(view).unwrap();
        }
    }

    #[test]
    fn every_held_out_view_is_refused_under_any_path_or_camera() {
        for view in HELD_OUT {
            assert!(check_not_held_out(view).is_err(), "{view}");
            let (scene, _) = view.rsplit_once('@').unwrap();
            let elsewhere = format!("/some/checkout/{scene}");
            assert!(check_not_held_out(&elsewhere).is_err(), "{elsewhere}");
            assert!(check_not_held_out(&format!("./{scene}@any")).is_err());
        }
        assert_eq!(
            held_out_scenes(),
            ["oa_minia.obj", "oa_rpg3dm2.obj", "islanddm.obj"]
        );
    }

    #[test]
    fn every_held_out_camera_is_in_its_scene_sidecar() {
        // The sidecars are in the repository, the meshes are fetched: check the names against
        // the sidecars so that a renamed camera fails here, not in a long bench run.
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        for view in HELD_OUT {
            let (scene, camera) = view.rsplit_once('@').unwrap();
            let sidecar = root.join(scene.replace(".obj", "-cameras.json"));
            let text = std::fs::read_to_string(&sidecar).unwrap();
            let json: serde_json::Value = serde_json::from_str(&text).unwrap();
            let names: Vec<&str> = json["cameras"]
                .as_array()
                .unwrap()
                .iter()
                .map(|c| c["name"].as_str().unwrap())
                .collect();
            assert!(names.contains(&camera), "{camera} not in {names:?}");
        }
    }
}
