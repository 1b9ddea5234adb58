//! A headless wgpu device for tools and tests, and texture read-back.
//!
//! Engines bring their own device; this module is for the CLI, the scene renderer and tests,
//! which need one without a window.

use std::fmt;

use crate::passes::{ComputeKernel, bind};

/// How an adapter was found, for the one-line notice tools print.
///
/// ```no_run
/// use aokit::{AdapterKind, GpuContext};
/// let gpu = GpuContext::headless()?;
/// if gpu.adapter_kind() == AdapterKind::Software {
///     eprintln!("note: no GPU found, running on {} (slow, but the results are the same)",
///               gpu.describe());
/// }
/// # Ok::<(), aokit::GpuError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AdapterKind {
    /// A GPU (discrete, integrated or virtual).
    Hardware,
    /// A CPU rasteriser such as lavapipe or llvmpipe.
    Software,
}

/// Why no device could be created.
///
/// ```no_run
/// use aokit::{GpuContext, GpuError};
/// match GpuContext::headless() {
///     Ok(gpu) => println!("{}", gpu.describe()),
///     // The message says what to install; a test suite may prefer to skip.
///     Err(GpuError::NoAdapter { .. }) => eprintln!("skipping: no GPU adapter"),
///     Err(e) => panic!("{e}"),
/// }
/// ```
#[derive(Debug, thiserror::Error)]
pub enum GpuError {
    /// No adapter exists on any enabled backend.
    #[error(
        "no GPU adapter found (backends: {backends}). Install a Vulkan driver, e.g. \
         `apt-get install mesa-vulkan-drivers` for the lavapipe software rasteriser, \
         or set WGPU_BACKEND to a backend this machine has"
    )]
    NoAdapter {
        /// The backends that were searched.
        backends: String,
    },
    /// Adapters exist, but none can run aokit's passes.
    #[error(
        "no adapter found can run aokit: {found}. Install a Vulkan driver, e.g. \
         `apt-get install mesa-vulkan-drivers` for the lavapipe software rasteriser"
    )]
    NoUsableAdapter {
        /// Each adapter found, with what it lacks.
        found: String,
    },
    /// `WGPU_ADAPTER_NAME` matched none of the adapters.
    #[error("WGPU_ADAPTER_NAME=`{wanted}` matches no adapter; found: {found}")]
    NoAdapterNamed {
        /// The requested name.
        wanted: String,
        /// Names of the adapters that exist.
        found: String,
    },
    /// The adapter refused to open a device.
    #[error("could not open a device on adapter `{adapter}`: {source}")]
    RequestDevice {
        /// The adapter's name.
        adapter: String,
        /// wgpu's reason.
        source: wgpu::RequestDeviceError,
    },
    /// A texture read-back failed.
    #[error("reading a texture back from the GPU failed: {0}")]
    Readback(String),
    /// Data handed in does not fit the texture.
    #[error("cannot upload texture data: {0}")]
    Upload(String),
}

/// A device and queue with the adapter they came from.
///
/// ```no_run
/// use aokit::{AoPipeline, AoSettings, GpuContext};
/// let gpu = GpuContext::headless()?;
/// let pipeline = AoPipeline::new(&gpu.device, &gpu.queue, &AoSettings::default())?;
/// println!("{} on {:?}", gpu.adapter_info.name, gpu.adapter_info.backend);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub struct GpuContext {
    /// The logical device.
    pub device: wgpu::Device,
    /// Its queue.
    pub queue: wgpu::Queue,
    /// Adapter name, backend, driver.
    pub adapter_info: wgpu::AdapterInfo,
}

impl fmt::Debug for GpuContext {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("GpuContext")
            .field("adapter", &self.adapter_info.name)
            .field("backend", &self.adapter_info.backend)
            .finish()
    }
}

impl GpuContext {
    /// Opens a device on the best adapter: a hardware GPU when there is one, otherwise a
    /// software rasteriser. `WGPU_BACKEND` (e.g. `vulkan`, `gl`) limits the backends searched
    /// and `WGPU_ADAPTER_NAME` picks an adapter by a case-insensitive part of its name.
    ///
    /// ```no_run
    /// let gpu = aokit::GpuContext::headless()?;
    /// println!("running on {}", gpu.describe());
    /// # Ok::<(), aokit::GpuError>(())
    /// ```
    pub fn headless() -> Result<Self, GpuError> {
        pollster::block_on(Self::headless_async())
    }

    /// The async form of [`GpuContext::headless`].
    ///
    /// ```no_run
    /// async fn start() -> Result<aokit::GpuContext, aokit::GpuError> {
    ///     // Inside an async runtime, where blocking on the adapter would stall other tasks.
    ///     aokit::GpuContext::headless_async().await
    /// }
    /// let gpu = pollster::block_on(start())?;
    /// # Ok::<(), aokit::GpuError>(())
    /// ```
    pub async fn headless_async() -> Result<Self, GpuError> {
        Self::headless_with_features_async(wgpu::Features::empty()).await
    }

    /// [`GpuContext::headless`], also asking for those of `wanted` the adapter has (aokit
    /// itself needs none of them): a tool that runs other shaders beside aokit's, e.g.
    /// SPIR-V with `PASSTHROUGH_SHADERS`, checks `device.features()` for what it got.
    ///
    /// ```no_run
    /// let gpu = aokit::GpuContext::headless_with_features(wgpu::Features::PASSTHROUGH_SHADERS)?;
    /// let passthrough = gpu.device.features().contains(wgpu::Features::PASSTHROUGH_SHADERS);
    /// # Ok::<(), aokit::GpuError>(())
    /// ```
    pub fn headless_with_features(wanted: wgpu::Features) -> Result<Self, GpuError> {
        pollster::block_on(Self::headless_with_features_async(wanted))
    }

    /// The async form of [`GpuContext::headless_with_features`], for a caller with an executor
    /// of its own.
    ///
    /// ```no_run
    /// # async fn f() -> Result<(), aokit::GpuError> {
    /// let gpu = aokit::GpuContext::headless_with_features_async(wgpu::Features::empty()).await?;
    /// # Ok(()) }
    /// ```
    pub async fn headless_with_features_async(wanted: wgpu::Features) -> Result<Self, GpuError> {
        Self::open(wanted, None).await
    }

    /// [`GpuContext::headless`] on an adapter of `kind` only: [`AdapterKind::Software`] runs on
    /// lavapipe or llvmpipe even where a GPU is present (results to compare across machines,
    /// or a GPU kept free), and fails with [`GpuError::NoAdapter`] where there is none.
    ///
    /// ```no_run
    /// use aokit::{AdapterKind, GpuContext};
    /// let gpu = GpuContext::headless_of_kind(AdapterKind::Software)?;
    /// assert_eq!(gpu.adapter_kind(), AdapterKind::Software);
    /// # Ok::<(), aokit::GpuError>(())
    /// ```
    pub fn headless_of_kind(kind: AdapterKind) -> Result<Self, GpuError> {
        pollster::block_on(Self::open(wgpu::Features::empty(), Some(kind)))
    }

    async fn open(wanted: wgpu::Features, kind: Option<AdapterKind>) -> Result<Self, GpuError> {
        let descriptor = wgpu::InstanceDescriptor::new_without_display_handle_from_env();
        let backends = descriptor.backends;
        let instance = wgpu::Instance::new(descriptor);
        // Without WGPU_BACKEND, GL is asked only when no primary backend has an adapter: probing
        // EGL is slow and noisy on headless machines, and Vulkan covers lavapipe.
        let mut adapters = instance
            .enumerate_adapters(backends & wgpu::Backends::PRIMARY)
            .await;
        let of_kind = |adapter: &wgpu::Adapter| {
            kind.is_none_or(|kind| adapter_kind(&adapter.get_info()) == kind)
        };
        adapters.retain(of_kind);
        if adapters.is_empty() {
            adapters = instance.enumerate_adapters(backends).await;
            adapters.retain(of_kind);
        }
        let adapter = choose_adapter(adapters, std::env::var("WGPU_ADAPTER_NAME").ok()).map_err(
            |e| match e {
                Choice::None => GpuError::NoAdapter {
                    backends: format!("{backends:?}"),
                },
                Choice::NoneNamed { wanted, found } => GpuError::NoAdapterNamed { wanted, found },
                Choice::NoneUsable { found } => GpuError::NoUsableAdapter { found },
            },
        )?;
        let adapter_info = adapter.get_info();
        let (device, queue) = adapter
            .request_device(&wgpu::DeviceDescriptor {
                label: Some("aokit"),
                // Timestamps where the adapter has them: tools report per-pass GPU time. Adapter
                // format features where they give R16Float storage, which the fp16 depth MIP
                // chain writes (not a storage format of WebGPU's core).
                required_features: adapter.features()
                    & (wgpu::Features::TIMESTAMP_QUERY | fp16_storage_feature(&adapter) | wanted),
                required_limits: adapter.limits(),
                ..Default::default()
            })
            .await
            .map_err(|source| GpuError::RequestDevice {
                adapter: adapter_info.name.clone(),
                source,
            })?;
        Ok(Self {
            device,
            queue,
            adapter_info,
        })
    }

    /// Hardware or software.
    ///
    /// ```no_run
    /// use aokit::{AdapterKind, GpuContext};
    /// let gpu = GpuContext::headless()?;
    /// // A software rasteriser takes seconds a frame at 1080p: benchmark a smaller image there.
    /// let size = match gpu.adapter_kind() {
    ///     AdapterKind::Hardware => [1920, 1080],
    ///     AdapterKind::Software => [480, 270],
    /// };
    /// println!("{}x{} on {}", size[0], size[1], gpu.describe());
    /// # Ok::<(), aokit::GpuError>(())
    /// ```
    pub fn adapter_kind(&self) -> AdapterKind {
        adapter_kind(&self.adapter_info)
    }

    /// `name (backend, driver)`, for logs and reports.
    ///
    /// ```no_run
    /// let gpu = aokit::GpuContext::headless()?;
    /// // Benchmarks are only comparable on the same adapter: record which one.
    /// let header = format!("# adapter: {}", gpu.describe());
    /// # Ok::<(), aokit::GpuError>(())
    /// ```
    pub fn describe(&self) -> String {
        let info = &self.adapter_info;
        let driver = [info.driver.as_str(), info.driver_info.as_str()]
            .into_iter()
            .filter(|s| !s.is_empty())
            .collect::<Vec<_>>()
            .join(" ");
        format!("{} ({:?}, {})", info.name, info.backend, driver)
    }
}

/// `Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES` where the adapter can write `R16Float`
/// storage textures with it, else none.
fn fp16_storage_feature(adapter: &wgpu::Adapter) -> wgpu::Features {
    let writable = adapter
        .get_texture_format_features(wgpu::TextureFormat::R16Float)
        .flags
        .contains(wgpu::TextureFormatFeatureFlags::STORAGE_WRITE_ONLY);
    if writable {
        wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES
    } else {
        wgpu::Features::empty()
    }
}

fn adapter_kind(info: &wgpu::AdapterInfo) -> AdapterKind {
    if info.device_type == wgpu::DeviceType::Cpu {
        AdapterKind::Software
    } else {
        AdapterKind::Hardware
    }
}

enum Choice {
    None,
    NoneNamed { wanted: String, found: String },
    NoneUsable { found: String },
}

/// The storage texture formats aokit's passes need, in WebGPU's core and in wgpu's GL backend:
/// the two-channel targets take [`PairFormat`]'s and the optional fp16 depth MIP chain
/// `R16Float` (`AoError::Fp16DepthMipsUnsupported` covers it).
pub(crate) const STORAGE_FORMATS: [wgpu::TextureFormat; 6] = [
    wgpu::TextureFormat::R32Float,
    wgpu::TextureFormat::R32Uint,
    wgpu::TextureFormat::Rgba8Unorm,
    wgpu::TextureFormat::Rgba16Float,
    wgpu::TextureFormat::Rgba32Float,
    wgpu::TextureFormat::Rgba32Uint,
];

/// Whether `device` can write storage textures of `format`. A device does not tell its format
/// features, so this probes: a bind group layout with a storage entry of a format the device
/// lacks fails validation.
fn writes_storage(device: &wgpu::Device, format: wgpu::TextureFormat) -> bool {
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let _probe = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("aokit storage format probe"),
        entries: &[bind::storage_texture(0, format)],
    });
    pollster::block_on(scope.pop()).is_none()
}

/// The formats of [`STORAGE_FORMATS`] that `device` cannot write.
pub(crate) fn missing_storage_formats(device: &wgpu::Device) -> Vec<wgpu::TextureFormat> {
    STORAGE_FORMATS
        .into_iter()
        .filter(|&format| !writes_storage(device, format))
        .collect()
}

/// How a device stores aokit's two-channel float targets: the spatial filter's AO and depth
/// after its first pass, the guided filter's window lines, the temporal history and the
/// working resolution's motion vectors. Each pass that writes one compiles its program for the
/// format (`pair_storage` in the WGSL).
///
/// ```no_run
/// let gpu = aokit::GpuContext::headless()?;
/// let pair = aokit::gpu::PairFormat::of(&gpu.device);
/// println!("two-channel targets in {:?}", pair.texture_format());
/// # Ok::<(), aokit::GpuError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PairFormat {
    /// Two 32-bit floats: WebGPU's core has it, and every backend but GL.
    Rg32Float,
    /// Four 32-bit floats, the last two unused: twice the bytes, for wgpu's GL backend, whose
    /// storage textures have no two-channel formats (GLSL ES 3.1's image formats).
    Rgba32Float,
}

impl PairFormat {
    /// `Rg32Float` where `device` can write it, else `Rgba32Float`.
    ///
    /// ```no_run
    /// # fn f(device: &wgpu::Device) {
    /// use aokit::gpu::PairFormat;
    /// // wgpu's GL backend has no two-channel storage formats.
    /// let pair = PairFormat::of(device);
    /// assert!(pair == PairFormat::Rg32Float || pair == PairFormat::Rgba32Float);
    /// # }
    /// ```
    pub fn of(device: &wgpu::Device) -> Self {
        if writes_storage(device, wgpu::TextureFormat::Rg32Float) {
            Self::Rg32Float
        } else {
            Self::Rgba32Float
        }
    }

    /// The texture format of the targets.
    ///
    /// ```
    /// use aokit::gpu::PairFormat;
    /// assert_eq!(PairFormat::Rg32Float.texture_format(), wgpu::TextureFormat::Rg32Float);
    /// assert_eq!(PairFormat::Rgba32Float.texture_format(), wgpu::TextureFormat::Rgba32Float);
    /// ```
    pub fn texture_format(self) -> wgpu::TextureFormat {
        match self {
            Self::Rg32Float => wgpu::TextureFormat::Rg32Float,
            Self::Rgba32Float => wgpu::TextureFormat::Rgba32Float,
        }
    }
}

/// Why `adapter` cannot run aokit's passes, or `None` when it can.
fn unusable(adapter: &wgpu::Adapter) -> Option<String> {
    let downlevel = adapter.get_downlevel_capabilities();
    if !downlevel
        .flags
        .contains(wgpu::DownlevelFlags::COMPUTE_SHADERS)
    {
        return Some("no compute shaders".into());
    }
    let missing: Vec<String> = STORAGE_FORMATS
        .iter()
        .filter(|&&format| {
            !adapter
                .get_texture_format_features(format)
                .flags
                .contains(wgpu::TextureFormatFeatureFlags::STORAGE_WRITE_ONLY)
        })
        .map(|format| format!("{format:?}"))
        .collect();
    (!missing.is_empty()).then(|| format!("cannot write {} storage textures", missing.join(", ")))
}

/// Ranks adapters so that real GPUs win and software rasterisers are the last resort.
fn rank(info: &wgpu::AdapterInfo) -> u32 {
    match info.device_type {
        wgpu::DeviceType::DiscreteGpu => 0,
        wgpu::DeviceType::IntegratedGpu => 1,
        wgpu::DeviceType::VirtualGpu => 2,
        wgpu::DeviceType::Other => 3,
        wgpu::DeviceType::Cpu => 4,
    }
}

fn choose_adapter(
    adapters: Vec<wgpu::Adapter>,
    wanted_name: Option<String>,
) -> Result<wgpu::Adapter, Choice> {
    let mut refused = Vec::new();
    let adapters: Vec<wgpu::Adapter> = adapters
        .into_iter()
        .filter(|adapter| match unusable(adapter) {
            Some(why) => {
                let info = adapter.get_info();
                refused.push(format!("{} ({:?}): {why}", info.name, info.backend));
                false
            }
            None => true,
        })
        .collect();
    if adapters.is_empty() && !refused.is_empty() {
        return Err(Choice::NoneUsable {
            found: refused.join("; "),
        });
    }
    if let Some(wanted) = wanted_name.filter(|w| !w.is_empty()) {
        let needle = wanted.to_lowercase();
        // The adapters passed over too, with why: the one wanted may be among them.
        let found = adapters
            .iter()
            .map(|a| a.get_info().name)
            .chain(refused.iter().map(|why| format!("{why} (passed over)")))
            .collect::<Vec<_>>()
            .join(", ");
        return adapters
            .into_iter()
            .find(|a| a.get_info().name.to_lowercase().contains(&needle))
            .ok_or(Choice::NoneNamed { wanted, found });
    }
    adapters
        .into_iter()
        // Vulkan before GL on the same device: compute and storage textures are first-class there.
        .min_by_key(|a| {
            let info = a.get_info();
            (rank(&info), info.backend != wgpu::Backend::Vulkan)
        })
        .ok_or(Choice::None)
}

/// A 2D texture with one mip level and one sample, the kind every aokit pass uses.
///
/// ```no_run
/// # fn f(device: &wgpu::Device) {
/// use aokit::gpu::create_texture_2d;
/// // A depth target for a renderer's own raster pass, which the AO pipeline then reads.
/// let depth = create_texture_2d(device, "depth", [1920, 1080], wgpu::TextureFormat::Depth32Float,
///     wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING);
/// # }
/// ```
pub fn create_texture_2d(
    device: &wgpu::Device,
    label: &str,
    size: [u32; 2],
    format: wgpu::TextureFormat,
    usage: wgpu::TextureUsages,
) -> wgpu::Texture {
    create_texture_2d_mips(device, label, size, 1, format, usage)
}

/// A 2D texture with `levels` mip levels and one sample, as the depth MIP chain and `msvo`'s
/// per-level targets use; [`mip_view`] views one level for a pass to write or read.
///
/// ```no_run
/// # fn f(device: &wgpu::Device) {
/// use aokit::gpu::{create_texture_2d_mips, mip_view};
/// // A four-level pyramid of linear depth, each level written by its own compute pass.
/// let pyramid = create_texture_2d_mips(device, "depth pyramid", [1920, 1080], 4,
///     wgpu::TextureFormat::R32Float,
///     wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::TEXTURE_BINDING);
/// let level_2 = mip_view(&pyramid, 2);
/// # }
/// ```
pub fn create_texture_2d_mips(
    device: &wgpu::Device,
    label: &str,
    size: [u32; 2],
    levels: u32,
    format: wgpu::TextureFormat,
    usage: wgpu::TextureUsages,
) -> wgpu::Texture {
    device.create_texture(&wgpu::TextureDescriptor {
        label: Some(label),
        size: wgpu::Extent3d {
            width: size[0],
            height: size[1],
            depth_or_array_layers: 1,
        },
        mip_level_count: levels,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage,
        view_formats: &[],
    })
}

/// A view of a 1x1 texture of `format` and `usage`: bound where a pass's layout has a texture
/// the current settings do not use (bent normals off, no motion vectors, no depth MIP chain),
/// never read or written.
///
/// ```no_run
/// # fn f(device: &wgpu::Device) {
/// // The layout takes motion vectors; this frame has none.
/// let none = aokit::gpu::stand_in_view(device, "no motion", wgpu::TextureFormat::Rg16Float,
///     wgpu::TextureUsages::TEXTURE_BINDING);
/// # }
/// ```
pub fn stand_in_view(
    device: &wgpu::Device,
    label: &str,
    format: wgpu::TextureFormat,
    usage: wgpu::TextureUsages,
) -> wgpu::TextureView {
    create_texture_2d(device, label, [1, 1], format, usage).create_view(&Default::default())
}

/// A view of mip level `level` of `texture` alone: what a storage binding needs, and what a
/// pass reading one level as its level 0 binds.
///
/// ```no_run
/// # fn f(texture: &wgpu::Texture) {
/// let finest = aokit::gpu::mip_view(texture, 0);
/// # }
/// ```
pub fn mip_view(texture: &wgpu::Texture, level: u32) -> wgpu::TextureView {
    texture.create_view(&wgpu::TextureViewDescriptor {
        base_mip_level: level,
        mip_level_count: Some(1),
        ..Default::default()
    })
}

/// A 2D texture filled from tightly packed rows of `bytes` (one mip level), with
/// `TEXTURE_BINDING | COPY_DST` usage.
///
/// ```no_run
/// # fn f(device: &wgpu::Device, queue: &wgpu::Queue) -> Result<(), aokit::GpuError> {
/// use aokit::gpu::upload_texture_2d;
/// // Linear depth from a file or a CPU renderer, as the AO pipeline accepts it.
/// let size = [320, 240];
/// let depth = vec![5.0f32; 320 * 240];
/// let texture = upload_texture_2d(device, queue, "depth", size, wgpu::TextureFormat::R32Float,
///                                 bytemuck::cast_slice(&depth))?;
/// # Ok(()) }
/// ```
pub fn upload_texture_2d(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    label: &str,
    size: [u32; 2],
    format: wgpu::TextureFormat,
    bytes: &[u8],
) -> Result<wgpu::Texture, GpuError> {
    let texel = texel_size(format)?;
    let expected = u64::from(size[0]) * u64::from(size[1]) * u64::from(texel);
    if bytes.len() as u64 != expected {
        return Err(GpuError::Upload(format!(
            "{label}: {} bytes given for a {}x{} {format:?} texture of {expected} bytes",
            bytes.len(),
            size[0],
            size[1]
        )));
    }
    let texture = create_texture_2d(
        device,
        label,
        size,
        format,
        wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
    );
    queue.write_texture(
        texture.as_image_copy(),
        bytes,
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(size[0] * texel),
            rows_per_image: Some(size[1]),
        },
        wgpu::Extent3d {
            width: size[0],
            height: size[1],
            depth_or_array_layers: 1,
        },
    );
    Ok(texture)
}

/// A uniform buffer the size of `T`, to be filled with `queue.write_buffer`.
///
/// ```no_run
/// # fn f(device: &wgpu::Device, queue: &wgpu::Queue) {
/// use aokit::gpu::create_uniform_buffer;
/// // Mirrors a WGSL `struct Tint { color: vec4<f32> }`.
/// #[repr(C)]
/// #[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
/// struct Tint { color: [f32; 4] }
/// let buffer = create_uniform_buffer::<Tint>(device, "tint");
/// queue.write_buffer(&buffer, 0, bytemuck::bytes_of(&Tint { color: [1.0, 0.5, 0.2, 1.0] }));
/// # }
/// ```
pub fn create_uniform_buffer<T: bytemuck::Pod>(device: &wgpu::Device, label: &str) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size: std::mem::size_of::<T>() as u64,
        usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    })
}

/// The sampler the passes read depth and AO through: nearest texel, coordinates clamped to the
/// edge (wgpu's default sampler), so gathers and off-screen samples repeat edge texels instead
/// of wrapping to the other side of the image.
pub(crate) fn create_point_clamp_sampler(device: &wgpu::Device, label: &str) -> wgpu::Sampler {
    device.create_sampler(&wgpu::SamplerDescriptor {
        label: Some(label),
        ..Default::default()
    })
}

/// Bytes per texel of the formats aokit reads back.
fn texel_size(format: wgpu::TextureFormat) -> Result<u32, GpuError> {
    format
        .block_copy_size(Some(wgpu::TextureAspect::All))
        .or_else(|| format.block_copy_size(Some(wgpu::TextureAspect::DepthOnly)))
        .ok_or_else(|| {
            GpuError::Readback(format!("format {format:?} cannot be copied to a buffer"))
        })
}

/// The bindings of `shader::DEPTH_TO_FLOAT`: the depth, the `R32Float` copy written.
pub(crate) fn depth_to_float_layout() -> [wgpu::BindGroupLayoutEntry; 2] {
    [
        bind::texture(0, wgpu::TextureSampleType::Float { filterable: false }),
        bind::storage_texture(1, wgpu::TextureFormat::R32Float),
    ]
}

/// `texture`'s depth in an `R32Float` texture of its size, copied by a compute pass.
fn depth_to_float(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    texture: &wgpu::Texture,
) -> wgpu::Texture {
    let size = [texture.width(), texture.height()];
    let format = wgpu::TextureFormat::R32Float;
    let usage = wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC;
    let copy = create_texture_2d(device, "aokit depth copy", size, format, usage);
    let kernel = ComputeKernel::new(
        device,
        &crate::shader::DEPTH_TO_FLOAT,
        &depth_to_float_layout(),
    );
    let depth = texture.create_view(&wgpu::TextureViewDescriptor {
        aspect: wgpu::TextureAspect::DepthOnly,
        ..Default::default()
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    kernel.dispatch(
        device,
        &mut encoder,
        &[
            wgpu::BindingResource::TextureView(&depth),
            wgpu::BindingResource::TextureView(&copy.create_view(&Default::default())),
        ],
        size,
        None,
    );
    queue.submit([encoder.finish()]);
    copy
}

/// Maps `slice` of a `MAP_READ` buffer, blocking until the GPU has finished with it: with
/// all submitted work (`submission` `None`), or with that submission and those before it, so
/// that later submissions keep running meanwhile.
pub(crate) fn map_for_reading(
    device: &wgpu::Device,
    slice: &wgpu::BufferSlice<'_>,
    submission: Option<wgpu::SubmissionIndex>,
) -> Result<(), GpuError> {
    let (sender, receiver) = std::sync::mpsc::channel();
    slice.map_async(wgpu::MapMode::Read, move |result| {
        let _ = sender.send(result);
    });
    device
        .poll(wgpu::PollType::Wait {
            submission_index: submission,
            timeout: None,
        })
        .map_err(|e| GpuError::Readback(e.to_string()))?;
    receiver
        .recv()
        .map_err(|e| GpuError::Readback(e.to_string()))?
        .map_err(|e| GpuError::Readback(e.to_string()))
}

/// A texture's copy on its way to the CPU: recorded into the commands that write the texture,
/// read once they have run. Recording it with a frame's work and reading it after the next
/// frame is submitted keeps the GPU busy while the CPU waits; [`read_texture`] does both at
/// once.
///
/// ```no_run
/// # fn f(device: &wgpu::Device, queue: &wgpu::Queue, texture: &wgpu::Texture)
/// #     -> Result<(), aokit::GpuError> {
/// use aokit::gpu::TextureReadback;
/// let mut encoder = device.create_command_encoder(&Default::default());
/// // ... the passes that write `texture` ...
/// let readback = TextureReadback::encode(device, &mut encoder, texture)?;
/// let submission = queue.submit([encoder.finish()]);
/// // ... submit the next frame here: the GPU runs it while this one is read ...
/// let texels: Vec<f32> = readback.f32_texels(device, Some(submission))?;
/// # Ok(()) }
/// ```
pub struct TextureReadback {
    buffer: wgpu::Buffer,
    format: wgpu::TextureFormat,
    /// Bytes of one row of texels, and of one row in the buffer (padded for the copy).
    row: u32,
    padded_row: u32,
}

impl TextureReadback {
    /// Records a copy of mip level 0 of the 2D `texture` (its depth aspect for a depth
    /// texture) into a new buffer; `texture` needs `COPY_SRC` usage.
    ///
    /// ```no_run
    /// # fn f(device: &wgpu::Device, encoder: &mut wgpu::CommandEncoder,
    /// #      ao: &wgpu::Texture) -> Result<(), aokit::GpuError> {
    /// let readback = aokit::gpu::TextureReadback::encode(device, encoder, ao)?;
    /// # Ok(()) }
    /// ```
    pub fn encode(
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        texture: &wgpu::Texture,
    ) -> Result<Self, GpuError> {
        let texel = texel_size(texture.format())?;
        let (width, height) = (texture.width(), texture.height());
        let row = width * texel;
        let padded_row =
            row.div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT) * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("aokit readback"),
            size: u64::from(padded_row) * u64::from(height),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let aspect = if texture.format().is_depth_stencil_format() {
            wgpu::TextureAspect::DepthOnly
        } else {
            wgpu::TextureAspect::All
        };
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &buffer,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(padded_row),
                    rows_per_image: Some(height),
                },
            },
            wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: 1,
            },
        );
        Ok(Self {
            buffer,
            format: texture.format(),
            row,
            padded_row,
        })
    }

    /// The texels' bytes, tightly packed row by row, once `submission` (the one holding the
    /// copy; `None`: all work submitted so far) has run. Blocks until then.
    ///
    /// ```no_run
    /// # fn f(device: &wgpu::Device, readback: aokit::gpu::TextureReadback)
    /// #     -> Result<(), aokit::GpuError> {
    /// let bytes = readback.bytes(device, None)?;
    /// # Ok(()) }
    /// ```
    pub fn bytes(
        self,
        device: &wgpu::Device,
        submission: Option<wgpu::SubmissionIndex>,
    ) -> Result<Vec<u8>, GpuError> {
        let slice = self.buffer.slice(..);
        map_for_reading(device, &slice, submission)?;
        let mapped = slice
            .get_mapped_range()
            .map_err(|e| GpuError::Readback(e.to_string()))?;
        let mut out =
            Vec::with_capacity(mapped.len() / self.padded_row as usize * self.row as usize);
        for chunk in mapped.chunks(self.padded_row as usize) {
            out.extend_from_slice(&chunk[..self.row as usize]);
        }
        drop(mapped);
        self.buffer.unmap();
        Ok(out)
    }

    /// [`TextureReadback::bytes`] of a single-channel float texture (`R32Float`, `R16Float`
    /// or `Depth32Float`) as `f32` texels, as [`read_texture_f32`] reads them.
    ///
    /// ```no_run
    /// # fn f(device: &wgpu::Device, readback: aokit::gpu::TextureReadback,
    /// #      submission: wgpu::SubmissionIndex) -> Result<(), aokit::GpuError> {
    /// let ao: Vec<f32> = readback.f32_texels(device, Some(submission))?;
    /// # Ok(()) }
    /// ```
    pub fn f32_texels(
        self,
        device: &wgpu::Device,
        submission: Option<wgpu::SubmissionIndex>,
    ) -> Result<Vec<f32>, GpuError> {
        let format = self.format;
        f32_texels(format, &self.bytes(device, submission)?)
    }

    /// [`TextureReadback::bytes`] of an `Rgba16Float` texture (the bent normals) as `f32`
    /// texels, as [`read_texture_rgba16f`] reads them.
    ///
    /// ```no_run
    /// # fn f(device: &wgpu::Device, readback: aokit::gpu::TextureReadback)
    /// #     -> Result<(), aokit::GpuError> {
    /// for [x, y, z, ao] in readback.rgba16f_texels(device, None)? {
    ///     // The mean unoccluded direction, and the kernel's AO alongside.
    /// }
    /// # Ok(()) }
    /// ```
    pub fn rgba16f_texels(
        self,
        device: &wgpu::Device,
        submission: Option<wgpu::SubmissionIndex>,
    ) -> Result<Vec<[f32; 4]>, GpuError> {
        let format = self.format;
        half_texels(
            format,
            wgpu::TextureFormat::Rgba16Float,
            &self.bytes(device, submission)?,
        )
    }
}

/// Copies mip level 0 of a 2D texture to the CPU, tightly packed, row by row.
///
/// Blocks until the GPU has finished. Depth textures return their depth aspect (on a device that
/// copies no depth texture to a buffer, wgpu's GL backend, an f32 depth texture made with
/// `TEXTURE_BINDING` through a compute copy).
///
/// ```no_run
/// # fn f(device: &wgpu::Device, queue: &wgpu::Queue, normals: &wgpu::Texture,
/// #      encoding: aokit::NormalEncoding) -> Result<(), aokit::GpuError> {
/// // A G-buffer's normals, decoded on the CPU from the texels' bytes.
/// let bytes = aokit::gpu::read_texture(device, queue, normals)?;
/// let decoded = aokit::normals::decode_texels(encoding, &bytes);
/// # Ok(()) }
/// ```
pub fn read_texture(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    texture: &wgpu::Texture,
) -> Result<Vec<u8>, GpuError> {
    // A copy the device refuses is an error of this call, not a panic in wgpu's default
    // handler; wgpu's GL backend refuses depth textures, whose f32 depth a compute pass then
    // copies into an R32Float texture first.
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
        label: Some("aokit readback"),
    });
    let readback = TextureReadback::encode(device, &mut encoder, texture);
    let commands = encoder.finish();
    if let Some(error) = pollster::block_on(scope.pop()) {
        let float_depth = matches!(
            texture.format(),
            wgpu::TextureFormat::Depth32Float | wgpu::TextureFormat::Depth32FloatStencil8
        );
        if float_depth
            && texture
                .usage()
                .contains(wgpu::TextureUsages::TEXTURE_BINDING)
        {
            return read_texture(device, queue, &depth_to_float(device, queue, texture));
        }
        return Err(GpuError::Readback(format!(
            "{:?} texture: {error}",
            texture.format()
        )));
    }
    let readback = readback?;
    let submission = queue.submit([commands]);
    readback.bytes(device, Some(submission))
}

/// Reads back a single-channel float texture (`R32Float`, `R16Float` or `Depth32Float`) as
/// `f32` texels.
///
/// ```no_run
/// # fn f(device: &wgpu::Device, queue: &wgpu::Queue, outputs: &aokit::AoOutputs<'_>)
/// #     -> Result<(), aokit::GpuError> {
/// // After the frame's commands were submitted.
/// let ao = aokit::gpu::read_texture_f32(device, queue, outputs.ao)?;
/// let mean = ao.iter().sum::<f32>() / ao.len() as f32;
/// # Ok(()) }
/// ```
pub fn read_texture_f32(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    texture: &wgpu::Texture,
) -> Result<Vec<f32>, GpuError> {
    f32_texels(texture.format(), &read_texture(device, queue, texture)?)
}

/// Single-channel float texels of `format` (`R32Float`, `R16Float` or `Depth32Float`) from
/// their bytes.
fn f32_texels(format: wgpu::TextureFormat, bytes: &[u8]) -> Result<Vec<f32>, GpuError> {
    match format {
        wgpu::TextureFormat::R32Float | wgpu::TextureFormat::Depth32Float => {
            Ok(bytemuck::pod_collect_to_vec(bytes))
        }
        wgpu::TextureFormat::R16Float => {
            let texels: Vec<[f32; 1]> = half_texels(format, format, bytes)?;
            Ok(texels.into_iter().map(|[x]| x).collect())
        }
        other => Err(GpuError::Readback(format!(
            "expected an R32Float, R16Float or Depth32Float texture, got {other:?}"
        ))),
    }
}

/// Reads back an `Rgba16Float` texture (the bent normals) as `f32` texels.
///
/// ```no_run
/// # fn f(device: &wgpu::Device, queue: &wgpu::Queue, outputs: &aokit::AoOutputs<'_>)
/// #     -> Result<(), aokit::GpuError> {
/// if let Some(bent) = outputs.bent_normals {
///     for [x, y, z, ao] in aokit::gpu::read_texture_rgba16f(device, queue, bent)? {
///         // The mean unoccluded direction, and the kernel's AO alongside.
///         let direction = glam::Vec3::new(x, y, z);
///     }
/// }
/// # Ok(()) }
/// ```
pub fn read_texture_rgba16f(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    texture: &wgpu::Texture,
) -> Result<Vec<[f32; 4]>, GpuError> {
    read_half_texels(device, queue, texture, wgpu::TextureFormat::Rgba16Float)
}

/// Reads back an `Rg16Float` texture (motion vectors) as `f32` texels.
///
/// ```no_run
/// # fn f(device: &wgpu::Device, queue: &wgpu::Queue, motion: &wgpu::Texture)
/// #     -> Result<(), aokit::GpuError> {
/// let offsets = aokit::gpu::read_texture_rg16f(device, queue, motion)?;
/// let fastest = offsets.iter().map(|[x, y]| x.hypot(*y)).fold(0.0, f32::max);
/// println!("surfaces moved up to {fastest} pixels since the last frame");
/// # Ok(()) }
/// ```
pub fn read_texture_rg16f(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    texture: &wgpu::Texture,
) -> Result<Vec<[f32; 2]>, GpuError> {
    read_half_texels(device, queue, texture, wgpu::TextureFormat::Rg16Float)
}

/// Reads back a texture of `N` half floats per texel, which must be in `format`.
fn read_half_texels<const N: usize>(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    texture: &wgpu::Texture,
    format: wgpu::TextureFormat,
) -> Result<Vec<[f32; N]>, GpuError> {
    half_texels(
        texture.format(),
        format,
        &read_texture(device, queue, texture)?,
    )
}

/// Texels of `N` half floats from the bytes of a texture in `actual`, which must be `format`.
fn half_texels<const N: usize>(
    actual: wgpu::TextureFormat,
    format: wgpu::TextureFormat,
    bytes: &[u8],
) -> Result<Vec<[f32; N]>, GpuError> {
    if actual != format {
        return Err(GpuError::Readback(format!(
            "expected an {format:?} texture, got {actual:?}"
        )));
    }
    let halves: Vec<u16> = bytemuck::pod_collect_to_vec(bytes);
    Ok(halves
        .chunks_exact(N)
        .map(|t| std::array::from_fn(|i| f16_to_f32(t[i])))
        .collect())
}

/// IEEE 754 binary16 to `f32`, exactly (every half is an `f32`).
pub(crate) fn f16_to_f32(bits: u16) -> f32 {
    let sign = if bits & 0x8000 != 0 { -1.0 } else { 1.0 };
    let exponent = i32::from((bits >> 10) & 0x1f);
    let mantissa = f32::from(bits & 0x3ff);
    sign * match exponent {
        0 => mantissa * 2f32.powi(-24),
        31 if mantissa == 0.0 => f32::INFINITY,
        31 => f32::NAN,
        _ => (1.0 + mantissa / 1024.0) * 2f32.powi(exponent - 15),
    }
}

/// `f32` to IEEE 754 binary16, rounded to nearest with ties to even, as GPUs store `f32` values
/// in half-float textures; beyond the largest half it gives infinity.
pub(crate) fn f32_to_f16(value: f32) -> u16 {
    let sign = if value.is_sign_negative() { 0x8000 } else { 0 };
    let magnitude = value.abs();
    if magnitude.is_nan() {
        return sign | 0x7e00;
    }
    // 65520 is halfway between the largest half, 65504, and the next step, 2^16.
    if magnitude >= 65520.0 {
        return sign | 0x7c00;
    }
    // Below 2^-14 halves are subnormal, in steps of 2^-24; a rounding up to 1024 steps yields
    // the smallest normal's bits, as it should.
    if magnitude < 2f32.powi(-14) {
        return sign | (magnitude * 2f32.powi(24)).round_ties_even() as u16;
    }
    // 11 significant bits: steps of 2^(exponent - 10). Scaling by a power of two is exact, and a
    // rounding up to 2048 carries into the exponent through the addition.
    let exponent = ((magnitude.to_bits() >> 23) & 0xff) as i32 - 127;
    let steps = (magnitude * 2f32.powi(10 - exponent)).round_ties_even() as u16;
    sign | ((((exponent + 15) as u16) << 10) + steps - 1024)
}

#[cfg(test)]
mod half_tests {
    use super::{f16_to_f32, f32_to_f16};

    #[test]
    fn floats_round_to_the_nearest_half_and_back() {
        for bits in (0..0x7c00u16).chain(0x8000..0xfc00) {
            assert_eq!(f32_to_f16(f16_to_f32(bits)), bits, "{bits:#x}");
        }
        // Halfway between 1 and the next half (1 + 2^-10): ties go to the even one, 1.
        assert_eq!(f32_to_f16(1.0 + 2f32.powi(-11)), 0x3c00);
        assert_eq!(f32_to_f16(1.0 + 3.0 * 2f32.powi(-11)), 0x3c02);
        assert_eq!(f32_to_f16(0.1), 0x2e66);
        assert_eq!(f32_to_f16(-65519.0), 0xfbff);
        assert_eq!(f32_to_f16(65520.0), 0x7c00);
        assert_eq!(f32_to_f16(2f32.powi(-25)), 0);
        assert_eq!(f32_to_f16(3.0 * 2f32.powi(-25)), 2);
    }

    #[test]
    fn halves_convert_exactly() {
        assert_eq!(f16_to_f32(0x3c00), 1.0);
        assert_eq!(f16_to_f32(0xc000), -2.0);
        assert_eq!(f16_to_f32(0x3555), 0.333_251_95);
        assert_eq!(f16_to_f32(0x0001), 2f32.powi(-24));
        assert_eq!(f16_to_f32(0x7c00), f32::INFINITY);
        assert!(f16_to_f32(0x7e00).is_nan());
    }
}

#[cfg(test)]
mod adapter_tests {
    use super::{PairFormat, STORAGE_FORMATS, missing_storage_formats, unusable};

    /// wgpu's GL backend (llvmpipe's here) lacks `Rg32Float` storage textures alone: aokit
    /// takes its adapter, stores the two-channel targets in `Rgba32Float` there, and finds
    /// every other format it writes. The frames it renders there are compared with Vulkan's in
    /// `aokit-scene/tests/gpu/backends.rs`.
    #[test]
    fn gl_adapters_are_usable_with_four_channel_pairs() {
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
            backends: wgpu::Backends::GL,
            ..wgpu::InstanceDescriptor::new_without_display_handle()
        });
        let adapters = pollster::block_on(instance.enumerate_adapters(wgpu::Backends::GL));
        if adapters.is_empty() {
            eprintln!("skipped: no GL adapter on this machine");
        }
        for adapter in adapters {
            assert_eq!(unusable(&adapter), None, "{:?}", adapter.get_info());
            let (device, _queue) =
                pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor::default()))
                    .expect("a GL device");
            assert_eq!(missing_storage_formats(&device), []);
            assert_eq!(PairFormat::of(&device), PairFormat::Rgba32Float);
            assert!(
                !STORAGE_FORMATS.contains(&wgpu::TextureFormat::Rg32Float),
                "Rg32Float is PairFormat's to choose, not a requirement"
            );
        }
    }
}
