//! The ray-traced reference of a scene: the same triangles and the same pixels as the raster.

use aokit::{Projection, ProjectionKind};
use aokit_reference::{Lens as RayLens, PixelCamera, ReferenceError, Tracer};

use crate::camera::Camera;
use crate::scene::Scene;

/// A tracer over the scene's triangles, its moving parts at rest.
///
/// ```
/// use glam::Vec3;
/// let scene = aokit_scene::Scene::open("open")?;
/// let tracer = aokit_scene::reference::tracer(&scene)?;
/// // The scene is one floor at height 0.
/// let hit = tracer.closest_hit(Vec3::new(3.0, 10.0, -7.0), Vec3::NEG_Y, 0.0, f32::INFINITY);
/// assert!(hit.is_some_and(|h| (h.t - 10.0).abs() < 1e-5 && h.normal == Vec3::Y));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn tracer(scene: &Scene) -> Result<Tracer, ReferenceError> {
    tracer_at(scene, 0.0)
}

/// A tracer over the scene's triangles at `time` of a sequence
/// ([`Scene::mesh_at`]), as [`Renderer::render_at`](crate::Renderer::render_at) draws them.
/// It builds a BVH each call: for a per-frame reference of a moving scene.
///
/// ```
/// use aokit_scene::{Scene, reference::tracer_at};
/// let scene = Scene::open("room")?;
/// let frames = 3;
/// for frame in 0..frames {
///     let time = frame as f32 / (frames - 1) as f32;
///     // The triangles as the raster draws them in this frame.
///     let tracer = tracer_at(&scene, time)?;
///     // Every triangle the raster draws, but the degenerate ones, which cover no pixel.
///     let drawn = scene.mesh_at(time).triangle_count();
///     assert!(tracer.triangle_count() > drawn / 2 && tracer.triangle_count() <= drawn);
///     // ... trace this frame's reference ...
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn tracer_at(scene: &Scene, time: f32) -> Result<Tracer, ReferenceError> {
    let mesh = scene.mesh_at(time);
    Tracer::new(&mesh.positions, &mesh.indices)
}

/// The pixel grid `camera` gets at `size`, with exactly the projection and clipping planes the
/// raster uses ([`Renderer::projection`](crate::Renderer::projection)).
///
/// ```
/// use aokit_reference::AoOptions;
/// use aokit_scene::{Scene, reference};
/// let scene = Scene::open("room")?;
/// let camera = scene.camera(None)?;
/// // A thumbnail of the ground truth, to compare with the raster's AO pixel by pixel.
/// let pixels = reference::pixel_camera(&scene, &camera, [16, 9]);
/// let options = AoOptions { radius: scene.suggested_radius.unwrap_or(1.0), spp: 8,
///                           ..Default::default() };
/// let image = reference::tracer(&scene)?.render(&pixels, &options, &|_| {})?;
/// assert_eq!(image.ao.len(), 16 * 9);
/// assert!(image.ao.iter().any(|&ao| ao < 1.0));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn pixel_camera(scene: &Scene, camera: &Camera, size: [u32; 2]) -> PixelCamera {
    let projection = camera.projection(size[0] as f32 / size[1] as f32, &scene.bounds);
    pixel_camera_for(&projection, camera.view_from_world(), size)
}

/// The tracer's pixel grid for a rasteriser's `projection` and `view_from_world` at `size`: the
/// camera of a camera.json ([`crate::CameraFile::checked`]), for ground truth of exported
/// passes.
///
/// ```
/// use aokit::Projection;
/// use aokit_reference::Lens;
/// use aokit_scene::reference::pixel_camera_for;
/// use glam::Mat4;
/// let projection = Projection::orthographic(4.0, 2.0, 0.5, 20.0);
/// let camera = pixel_camera_for(&projection, Mat4::IDENTITY, [64, 32]);
/// assert_eq!(camera.lens, Lens::Orthographic { height: 4.0 });
/// assert_eq!((camera.near, camera.far), (0.5, Some(20.0)));
/// ```
pub fn pixel_camera_for(
    projection: &Projection,
    view_from_world: glam::Mat4,
    size: [u32; 2],
) -> PixelCamera {
    let lens = match projection.kind {
        ProjectionKind::Perspective { fov_y } => RayLens::Perspective { fov_y },
        ProjectionKind::Orthographic { height } => RayLens::Orthographic { height },
    };
    PixelCamera {
        size,
        lens,
        view_from_world,
        near: projection.near,
        far: projection.far,
    }
}
