//! The library's error type.

use crate::inputs::InputError;
use crate::projection::ProjectionError;
use crate::settings::SettingsError;

/// Everything [`AoPipeline`](crate::AoPipeline) can refuse.
///
/// The checks the pipeline runs can be run up front, before any device exists, and their
/// errors convert with `?`:
///
/// ```
/// use aokit::{AoError, AoSettings, Projection};
/// fn check(settings: &AoSettings, projection: &Projection) -> Result<(), AoError> {
///     settings.validate()?;
///     projection.validate()?;
///     Ok(())
/// }
/// let projection = Projection::perspective(1.0, 16.0 / 9.0, 0.1, None);
/// let settings = AoSettings { radius: -1.0, ..AoSettings::default() };
/// let err = check(&settings, &projection).unwrap_err();
/// assert!(matches!(err, AoError::Settings(ref e) if e.field == "radius"), "{err}");
/// ```
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum AoError {
    /// A setting is out of range.
    #[error(transparent)]
    Settings(#[from] SettingsError),
    /// The projection is unusable.
    #[error(transparent)]
    Projection(#[from] ProjectionError),
    /// A texture handed in is unusable.
    #[error(transparent)]
    Input(#[from] InputError),
    /// `depth_mips = fp16` on a device that cannot write R16Float storage textures: they need
    /// `Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES` and an adapter whose R16Float format
    /// features include storage. `fp32` works everywhere.
    #[error(
        "depth_mips = fp16 needs R16Float storage textures (Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES), which this device does not have; use depth_mips = fp32"
    )]
    Fp16DepthMipsUnsupported,
    /// The device cannot write storage textures of these formats, which aokit's passes write.
    /// WebGPU's core has them all, and so does wgpu's GL backend; it lacks `Rg32Float`, which
    /// aokit replaces with `Rgba32Float` there ([`PairFormat`](crate::gpu::PairFormat)).
    #[error(
        "this device cannot write {} storage textures, which aokit's passes write; use a \
         Vulkan, Metal or DX12 device",
        .0.iter().map(|f| format!("{f:?}")).collect::<Vec<_>>().join(", ")
    )]
    StorageFormats(Vec<wgpu::TextureFormat>),
    /// [`VbaoSettings::back_faces`](crate::VbaoSettings::back_faces) is on, but the inputs
    /// have no [`AoInputs::back_depth`](crate::AoInputs::back_depth).
    #[error(
        "vbao.back_faces = true measures occluders from the back faces' depth, but the inputs \
         have none (AoInputs::back_depth)"
    )]
    MissingBackDepth,
    /// The resolution exceeds the device's texture limit.
    #[error("resolution {}x{} exceeds this device's texture limit of {max}", size[0], size[1])]
    TooLarge {
        /// The resolution asked for.
        size: [u32; 2],
        /// The device's `max_texture_dimension_2d`.
        max: u32,
    },
    /// A debug view was asked of outputs that do not have what it shows.
    #[error("the `{view}` debug view needs the setting {needs}")]
    DebugViewUnavailable {
        /// The view's name.
        view: &'static str,
        /// The setting that makes the outputs have it.
        needs: &'static str,
    },
    /// The device was lost (destroyed, a driver reset, a removed GPU): nothing it runs any more
    /// produces a frame. Make a new device and a new pipeline. Reported by the pipeline's next
    /// call once the device's lost callback has run (wgpu runs it while polling the device),
    /// see [`AoPipeline::device_lost_callback`](crate::AoPipeline::device_lost_callback).
    #[error("the GPU device was lost ({reason}); make a new device and a new AoPipeline on it")]
    DeviceLost {
        /// wgpu's reason, and its message when it gave one.
        reason: String,
    },
    /// The device ran out of memory making the pipeline's buffers and noise textures
    /// ([`AoPipeline::new`](crate::AoPipeline::new)) or the intermediate textures that
    /// [`AoPipeline::encode`](crate::AoPipeline::encode) makes when the frame's size or layout
    /// changes: lower the resolution, or free GPU memory. The pipeline keeps nothing it made:
    /// the next `encode` tries again.
    #[error("out of GPU memory making {what}; try a lower resolution or free GPU memory")]
    OutOfMemory {
        /// What was being made.
        what: String,
    },
    /// A [`DebugStyle`](crate::debug::DebugStyle) value is out of range.
    #[error("debug style: {0}")]
    DebugStyle(String),
}
