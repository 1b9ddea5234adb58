//! # aokit
//!
//! Screen-space ambient occlusion for wgpu renderers, written as WGSL compute passes.
//!
//! Hand [`AoPipeline::encode`] your depth buffer, your normals and the camera [`Projection`] each
//! frame; it records its passes into your command encoder and returns the AO texture
//! (1 = unoccluded) for your lighting pass to sample.
//!
//! Conventions: view space is right-handed with the camera looking down -Z; depth is wgpu NDC
//! depth in `[0, 1]`, standard or reverse-Z, finite or infinite far plane; the radius is in world
//! units. See `docs/` in the repository for the method notes.

#![warn(missing_docs)]

pub mod debug;
mod device_errors;
pub use device_errors::DeviceLoss;
pub mod error;
pub mod gpu;
mod input_texture;
pub mod inputs;
mod methods;
pub mod noise;
pub mod normals;
pub mod occlusion;
pub mod passes;
pub mod pipeline;
mod plan;
mod presets;
pub mod projection;
mod record;
pub mod settings;
pub mod shader;
mod spiral;
mod targets;
pub mod timing;
mod uniforms;

pub use debug::DebugView;
pub use error::AoError;
pub use gpu::{AdapterKind, GpuContext, GpuError};
pub use input_texture::AoTexture;
pub use inputs::{AoInputs, AoMask, InputError};
pub use pipeline::{AoOutputs, AoPipeline};
pub use projection::{Projection, ProjectionError, ProjectionKind};
pub use settings::{
    AoSettings, DepthMips, DepthWeight, Downsample, FilterResolution, GtaoSettings, HbaoSettings,
    HbaoVariant, MSVO_MAX_LEVELS, Method, MsvoSettings, NoiseKind, NoiseSettings, NormalEncoding,
    NormalSource, NormalSpace, NormalsSettings, Preset, Resolution, SEPARABLE_HBAO_MAX_RADIUS_PX,
    SampleDepth, SettingsError, SliceMarch, SpatialKind, SpatialSettings, SsaoSettings,
    TemporalOffset, TemporalSettings, Ue4SsaoSettings, Upsample, VbaoSettings,
};
pub use timing::{PassTime, PassTimer};
