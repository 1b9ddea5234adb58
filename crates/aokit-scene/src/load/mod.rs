//! Scene file loaders.

pub mod gltf;
pub mod obj;

use glam::Vec3;

/// Albedo for surfaces whose file gives no colour: a mid grey, as in most AO showcases.
pub const DEFAULT_ALBEDO: Vec3 = Vec3::splat(0.7);
