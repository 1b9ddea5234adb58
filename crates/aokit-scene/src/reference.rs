//! The ray-traced reference of a scene: the same triangles and the same pixels as the raster.

use aokit::ProjectionKind;
use aokit_reference::{Lens as RayLens, PixelCamera, ReferenceError, Tracer};

use crate::camera::Camera;
use crate::scene::Scene;

/// A tracer over the scene's triangles.
pub fn tracer(scene: &Scene) -> Result<Tracer, ReferenceError> {
    Tracer::new(&scene.mesh.positions, &scene.mesh.indices)
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
