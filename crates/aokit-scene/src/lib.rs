//! # aokit-scene
//!
//! The headless scene renderer behind the `aokit` CLI: built-in procedural scenes (some with
//! moving parts), glTF and OBJ loading, cameras and camera paths, a G-buffer raster pass with
//! motion vectors and a lit composite around [`aokit::AoPipeline`].
//!
//! ```no_run
//! use aokit_scene::{Renderer, Scene};
//! let gpu = aokit::GpuContext::headless()?;
//! let scene = Scene::open("room")?;
//! let camera = scene.camera(None)?;
//! let mut settings = aokit::AoSettings::default();
//! settings.radius = scene.suggested_radius.unwrap_or(1.0);
//! let mut renderer = Renderer::new(&gpu, &scene, &settings)?;
//! let frame = renderer.render(&gpu, &camera, [640, 360], 0)?;
//! println!("mean AO {}", frame.ao.iter().sum::<f32>() / frame.ao.len() as f32);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![warn(missing_docs)]

pub mod animation;
pub mod builtin;
pub mod camera;
pub mod composite;
pub mod external;
pub mod gbuffer;
pub mod load;
pub mod mesh;
pub mod path;
pub mod reference;
pub mod renderer;
pub mod scene;
pub mod shaders;
pub mod shadow;
pub mod shapes;
mod uniform_block;

pub use animation::{Motion, MovingPart};
pub use builtin::Builtin;
pub use camera::{Camera, CameraFile, Lens};
pub use path::CameraPath;
pub use renderer::{Frame, RenderError, Renderer};
pub use scene::{Scene, SceneError};
