//! A whole reference image: primary hits, then AO at each, over all cores.

use std::sync::atomic::{AtomicUsize, Ordering};

use glam::{Mat4, Vec3};
use rayon::prelude::*;

use crate::ReferenceError;
use crate::camera::PixelCamera;
use crate::options::AoOptions;
use crate::sampling::PixelSampler;
use crate::tracer::Tracer;

/// A traced image, row by row from the top-left pixel. Pixels that show no surface have AO 1,
/// depth 0 and a zero normal, as the raster G-buffer leaves them.
///
/// ```
/// use aokit_reference::{AoOptions, Lens, PixelCamera, Tracer};
/// use glam::{Mat4, Vec3};
/// // A small square 5 units in front of the eye, on an empty background.
/// let square = [Vec3::new(-1.0, -1.0, -5.0), Vec3::new(1.0, -1.0, -5.0),
///               Vec3::new(1.0, 1.0, -5.0), Vec3::new(-1.0, 1.0, -5.0)];
/// let tracer = Tracer::new(&square, &[0, 1, 2, 0, 2, 3])?;
/// let camera = PixelCamera {
///     size: [9, 9],
///     lens: Lens::Perspective { fov_y: 1.2 },
///     view_from_world: Mat4::IDENTITY,
///     near: 0.1,
///     far: None,
/// };
/// let image = tracer.render(&camera, &AoOptions { spp: 4, ..Default::default() }, &|_| {})?;
/// let pixel = |x: usize, y: usize| y * image.size[0] as usize + x;
/// let centre = pixel(4, 4);
/// assert!((image.linear_depth[centre] - 5.0).abs() < 1e-4);
/// assert!((image.normals[centre] - Vec3::Z).length() < 1e-6);
/// let corner = pixel(0, 0);
/// assert_eq!((image.ao[corner], image.linear_depth[corner]), (1.0, 0.0));
/// # Ok::<(), aokit_reference::ReferenceError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct ReferenceImage {
    /// Width and height in pixels.
    pub size: [u32; 2],
    /// Ambient occlusion, 1 = unoccluded.
    pub ao: Vec<f32>,
    /// Linear view depth: distance along the view axis to the primary hit.
    pub linear_depth: Vec<f32>,
    /// View-space unit geometric normals, facing the camera.
    pub normals: Vec<Vec3>,
}

/// One pixel's primary hit and AO.
struct Pixel {
    ao: f32,
    depth: f32,
    normal: Vec3,
}

const BACKGROUND: Pixel = Pixel {
    ao: 1.0,
    depth: 0.0,
    normal: Vec3::ZERO,
};

impl Tracer {
    /// Traces `camera`'s pixels. `progress` is called with the number of finished rows as rows
    /// finish, from worker threads. The result depends only on the inputs and `options.seed`,
    /// not on the number of threads.
    ///
    /// ```
    /// use aokit_reference::{AoOptions, Lens, PixelCamera, Tracer};
    /// use glam::Vec3;
    /// use glam::camera::rh::view::look_at_mat4;
    /// let floor = [Vec3::new(-9.0, 0.0, -9.0), Vec3::new(9.0, 0.0, -9.0),
    ///              Vec3::new(9.0, 0.0, 9.0), Vec3::new(-9.0, 0.0, 9.0)];
    /// let tracer = Tracer::new(&floor, &[0, 2, 1, 0, 3, 2])?;
    /// let camera = PixelCamera {
    ///     size: [8, 8],
    ///     lens: Lens::Perspective { fov_y: 0.5 },
    ///     view_from_world: look_at_mat4(Vec3::new(0.0, 3.0, 0.1), Vec3::ZERO, Vec3::Y),
    ///     near: 0.01,
    ///     far: None,
    /// };
    /// let image = tracer.render(&camera, &AoOptions { spp: 16, ..Default::default() }, &|_| {})?;
    /// assert!(image.ao.iter().all(|&ao| ao == 1.0)); // nothing above a lone floor
    /// # Ok::<(), aokit_reference::ReferenceError>(())
    /// ```
    pub fn render(
        &self,
        camera: &PixelCamera,
        options: &AoOptions,
        progress: &(dyn Fn(usize) + Sync),
    ) -> Result<ReferenceImage, ReferenceError> {
        options.validate()?;
        let [width, height] = camera.size;
        if width == 0 || height == 0 {
            return Err(ReferenceError::Size(width, height));
        }
        // Before the image is allocated: a limit on each side alone let 16384x16384 through.
        if u64::from(width) * u64::from(height) > crate::MAX_PIXELS {
            return Err(ReferenceError::TooManyPixels(width, height));
        }
        let view_from_world: Mat4 = camera.view_from_world;
        let rows_done = AtomicUsize::new(0);
        let pixels: Vec<Pixel> = (0..height)
            .into_par_iter()
            .flat_map_iter(|y| {
                let row: Vec<Pixel> = (0..width)
                    .map(|x| {
                        let ray = camera.ray(x, y);
                        let Some(hit) =
                            self.closest_hit(ray.origin, ray.direction, ray.t_min, ray.t_max)
                        else {
                            return BACKGROUND;
                        };
                        let index = u64::from(y) * u64::from(width) + u64::from(x);
                        let sampler = PixelSampler::new(options.seed, index);
                        Pixel {
                            ao: self.ambient_occlusion(hit.point, hit.normal, options, &sampler),
                            depth: hit.t * ray.depth_per_t,
                            normal: view_from_world.transform_vector3(hit.normal).normalize(),
                        }
                    })
                    .collect();
                progress(rows_done.fetch_add(1, Ordering::Relaxed) + 1);
                row
            })
            .collect();
        Ok(ReferenceImage {
            size: camera.size,
            ao: pixels.iter().map(|p| p.ao).collect(),
            linear_depth: pixels.iter().map(|p| p.depth).collect(),
            normals: pixels.iter().map(|p| p.normal).collect(),
        })
    }

    /// Linear view depth of the closest back face through each of `camera`'s pixels
    /// ([`Tracer::closest_back_face`]), 0 where there is none: what a rasteriser culling front
    /// faces draws, the input `vbao.back_faces` reads. Row by row from the top-left pixel.
    ///
    /// ```
    /// use aokit_reference::{Lens, PixelCamera, Tracer};
    /// use glam::{Mat4, Vec3};
    /// // A square 5 units in front of the eye, facing it: no back face behind it.
    /// let square = [Vec3::new(-1.0, -1.0, -5.0), Vec3::new(1.0, -1.0, -5.0),
    ///               Vec3::new(1.0, 1.0, -5.0), Vec3::new(-1.0, 1.0, -5.0)];
    /// let camera = PixelCamera {
    ///     size: [3, 3],
    ///     lens: Lens::Perspective { fov_y: 0.5 },
    ///     view_from_world: Mat4::IDENTITY,
    ///     near: 0.1,
    ///     far: None,
    /// };
    /// let facing = Tracer::new(&square, &[0, 1, 2, 0, 2, 3])?;
    /// assert!(facing.back_depth(&camera)?.iter().all(|&d| d == 0.0));
    /// // Wound the other way it shows its back, at the depth of its plane.
    /// let away = Tracer::new(&square, &[0, 2, 1, 0, 3, 2])?;
    /// assert!(away.back_depth(&camera)?.iter().all(|&d| (d - 5.0).abs() < 1e-5));
    /// # Ok::<(), aokit_reference::ReferenceError>(())
    /// ```
    pub fn back_depth(&self, camera: &PixelCamera) -> Result<Vec<f32>, ReferenceError> {
        let [width, height] = camera.size;
        if width == 0 || height == 0 {
            return Err(ReferenceError::Size(width, height));
        }
        // Before the image is allocated: a limit on each side alone let 16384x16384 through.
        if u64::from(width) * u64::from(height) > crate::MAX_PIXELS {
            return Err(ReferenceError::TooManyPixels(width, height));
        }
        Ok((0..height)
            .into_par_iter()
            .flat_map_iter(|y| {
                (0..width).map(move |x| {
                    let ray = camera.ray(x, y);
                    self.closest_back_face(ray.origin, ray.direction, ray.t_min, ray.t_max)
                        .map_or(0.0, |t| t * ray.depth_per_t)
                })
            })
            .collect())
    }
}
