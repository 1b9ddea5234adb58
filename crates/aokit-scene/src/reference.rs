//! The ray-traced reference of a scene: the same triangles and the same pixels as the raster.

use aokit::ProjectionKind;
use aokit_reference::{Lens as RayLens, PixelCamera, ReferenceError, Tracer};

use crate::camera::Camera;
use crate::scene::Scene;

/// A tracer over the scene's triangles, its moving parts at rest.
pub fn tracer(scene: &Scene) -> Result<Tracer, ReferenceError> {
    tracer_at(scene, 0.0)
}

/// A tracer over the scene's triangles at `time` of a sequence
/// ([`Scene::mesh_at`]), as [`Renderer::render_at`](crate::Renderer::render_at) draws them.
/// It builds a BVH each call: for a per-frame reference of a moving scene.
pub fn tracer_at(scene: &Scene, time: f32) -> Result<Tracer, ReferenceError> {
    let mesh = scene.mesh_at(time);
    Tracer::new(&mesh.positions, &mesh.indices)
}

/// The pixel grid `camera` gets at `size`, with exactly the projection and clipping planes the
/// raster uses ([`Renderer::projection`](crate::Renderer::projection)).
pub fn pixel_camera(scene: &Scene, camera: &Camera, size: [u32; 2]) -> PixelCamera {
    let projection = camera.projection(size[0] as f32 / size[1] as f32, &scene.bounds);
    let lens = match projection.kind {
        ProjectionKind::Perspective { fov_y } => RayLens::Perspective { fov_y },
        ProjectionKind::Orthographic { height } => RayLens::Orthographic { height },
    };
    PixelCamera {
        size,
        lens,
        view_from_world: camera.view_from_world(),
        near: projection.near,
        far: projection.far,
    }
}
