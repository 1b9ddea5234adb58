//! Ambient occlusion at one surface point by Monte Carlo integration over the hemisphere.

use glam::Vec3;

use crate::offset::offset_origin;
use crate::options::{AoOptions, Falloff};
use crate::sampling::{PixelSampler, cosine_hemisphere, tangent_frame};
use crate::tracer::Tracer;

impl Tracer {
    /// Ambient occlusion at `point` on a surface with unit geometric normal `normal` (facing
    /// the viewer): 1 minus the mean occlusion of `options.spp` cosine-weighted rays, where a ray
    /// that meets geometry at `t < radius` occludes as `options.falloff` says and one that does
    /// not occludes nothing. With cosine-weighted directions the estimator needs no weights: the
    /// cosine of the AO integral is the sampling density. `sampler` decides the ray directions.
    ///
    /// ```
    /// use aokit_reference::{AoOptions, Falloff, PixelSampler, Tracer};
    /// use glam::Vec3;
    /// // A point on the floor under a wide ceiling half the radius up.
    /// let (w, h) = (20.0, 0.5);
    /// let ceiling = [Vec3::new(-w, h, -w), Vec3::new(w, h, -w),
    ///                Vec3::new(w, h, w), Vec3::new(-w, h, w)];
    /// let tracer = Tracer::new(&ceiling, &[0, 1, 2, 0, 2, 3])?;
    /// let sampler = PixelSampler::new(0, 0);
    /// let ao = |falloff| {
    ///     let options = AoOptions { radius: 1.0, spp: 1024, falloff, ..Default::default() };
    ///     tracer.ambient_occlusion(Vec3::ZERO, Vec3::Y, &options, &sampler)
    /// };
    /// // Rays escape when their cosine to the normal is below h / R, which the cosine
    /// // weighting makes a fraction (h / R)^2 of them.
    /// assert!((ao(Falloff::None) - 0.25).abs() < 0.02);
    /// // With a falloff, hits near the radius darken less.
    /// assert!(ao(Falloff::Linear) > ao(Falloff::None));
    /// # Ok::<(), aokit_reference::ReferenceError>(())
    /// ```
    pub fn ambient_occlusion(
        &self,
        point: Vec3,
        normal: Vec3,
        options: &AoOptions,
        sampler: &PixelSampler,
    ) -> f32 {
        let origin = offset_origin(point, normal);
        let (tangent, bitangent) = tangent_frame(normal);
        let mut occlusion = 0.0f64;
        for i in 0..options.spp {
            let local = cosine_hemisphere(sampler.square(i));
            let direction =
                (tangent * local.x + bitangent * local.y + normal * local.z).normalize();
            occlusion += f64::from(match options.falloff {
                Falloff::None => {
                    if self.occluded(origin, direction, options.radius) {
                        1.0
                    } else {
                        0.0
                    }
                }
                falloff => self
                    .hit_distance(origin, direction, options.radius)
                    .map_or(0.0, |t| falloff.occlusion(t / options.radius)),
            });
        }
        (1.0 - occlusion / f64::from(options.spp)) as f32
    }
}
