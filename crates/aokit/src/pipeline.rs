//! [`AoPipeline`]: owns the passes and the intermediate textures, and wires them per frame.

use std::collections::HashMap;

use crate::error::AoError;
use crate::gpu::{create_texture_2d, create_uniform_buffer};
use crate::inputs::AoInputs;
use crate::passes::PassContext;
use crate::passes::decode_normals::DecodeNormalsPass;
use crate::passes::linear_depth::{LINEAR_DEPTH_FORMAT, LinearDepthPass};
use crate::passes::method::{AO_FORMAT, BENT_NORMALS_FORMAT, MethodPass};
use crate::passes::normals_from_depth::{NORMALS_FORMAT, NormalsFromDepthPass};
use crate::passes::spatial_filter::{PACKED_FORMAT, SpatialFilterPass};
use crate::passes::temporal_filter::{FrameMotion, History, TemporalFilterPass};
use crate::settings::{AoSettings, NormalEncoding, NormalSource};
use crate::timing::{PassTime, PassTimer};
use crate::uniforms::ViewUniforms;

/// Textures sized to the current resolution.
struct Targets {
    size: [u32; 2],
    linear_depth: wgpu::Texture,
    linear_depth_view: wgpu::TextureView,
    ao: wgpu::Texture,
    ao_view: wgpu::TextureView,
    /// oct32 normals decoded from the input or reconstructed from depth.
    normals: wgpu::Texture,
    normals_view: wgpu::TextureView,
    bent_normals: Option<(wgpu::Texture, wgpu::TextureView)>,
    /// The spatial filter's textures, when it is on.
    spatial: Option<SpatialTargets>,
}

/// The spatial filter's AO and depth after the horizontal pass, and its filtered AO.
struct SpatialTargets {
    packed_view: wgpu::TextureView,
    ao: wgpu::Texture,
    ao_view: wgpu::TextureView,
}

impl Targets {
    fn new(device: &wgpu::Device, size: [u32; 2], bent_normals: bool, spatial: bool) -> Self {
        let usage = wgpu::TextureUsages::STORAGE_BINDING
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC;
        let make = |label, format| create_texture_2d(device, label, size, format, usage);
        let linear_depth = make("aokit linear depth", LINEAR_DEPTH_FORMAT);
        let ao = make("aokit ao", AO_FORMAT);
        let normals = make("aokit normals", NORMALS_FORMAT);
        let bent_normals = bent_normals.then(|| {
            let texture = make("aokit bent normals", BENT_NORMALS_FORMAT);
            let view = texture.create_view(&Default::default());
            (texture, view)
        });
        let spatial = spatial.then(|| {
            let ao = make("aokit spatially filtered ao", AO_FORMAT);
            SpatialTargets {
                packed_view: make("aokit spatial filter ao and depth", PACKED_FORMAT)
                    .create_view(&Default::default()),
                ao_view: ao.create_view(&Default::default()),
                ao,
            }
        });
        Self {
            bent_normals,
            spatial,
            normals_view: normals.create_view(&Default::default()),
            normals,
            size,
            linear_depth_view: linear_depth.create_view(&Default::default()),
            linear_depth,
            ao_view: ao.create_view(&Default::default()),
            ao,
        }
    }
}

/// What [`AoPipeline::encode`] produced. The textures stay valid until the next `encode` with a
/// different size.
#[derive(Clone, Copy, Debug)]
pub struct AoOutputs<'a> {
    /// Ambient occlusion, `R32Float`, 1 = unoccluded: [`AoOutputs::raw_ao`] after the spatial
    /// filter when [`SpatialSettings::enabled`](crate::SpatialSettings::enabled), else that
    /// texture itself.
    pub ao: &'a wgpu::Texture,
    /// A view of [`AoOutputs::ao`] for binding.
    pub ao_view: &'a wgpu::TextureView,
    /// The method kernel's AO before any denoising, `R32Float`, for comparing filters or
    /// feeding your own.
    pub raw_ao: &'a wgpu::Texture,
    /// A view of [`AoOutputs::raw_ao`] for binding.
    pub raw_ao_view: &'a wgpu::TextureView,
    /// Linear view depth, `R32Float`, 0 where nothing was drawn.
    pub linear_depth: &'a wgpu::Texture,
    /// The view-space normals the AO kernels used, oct32 (`R32Uint`, see
    /// [`normals::unpack_oct32`](crate::normals::unpack_oct32)): the input texture itself when
    /// it is oct32, else the input decoded or the normals reconstructed from depth.
    pub normals: &'a wgpu::Texture,
    /// A view of [`AoOutputs::normals`] for binding.
    pub normals_view: &'a wgpu::TextureView,
    /// Bent normals when [`AoSettings::bent_normals`] is on: `Rgba16Float`, view-space unit
    /// vector in xyz (the mean unoccluded direction), AO in w.
    pub bent_normals: Option<&'a wgpu::Texture>,
    /// A view of [`AoOutputs::bent_normals`] for binding.
    pub bent_normals_view: Option<&'a wgpu::TextureView>,
    /// With the temporal filter on: `R32Float`, 1 where this frame rejected its history
    /// (disocclusions, the screen's edges, a reset) and showed the current frame alone, 0 where
    /// it blended. A debug view of where ghosting or fresh noise can show.
    pub history_rejected: Option<&'a wgpu::Texture>,
}

/// The AO pipeline for one view.
///
/// ```no_run
/// # fn frame(device: &wgpu::Device, queue: &wgpu::Queue, depth: &wgpu::Texture,
/// #          normals: &wgpu::Texture, projection: aokit::Projection) -> Result<(), aokit::AoError> {
/// use aokit::{AoInputs, AoPipeline, AoSettings};
/// let mut pipeline = AoPipeline::new(device, queue, &AoSettings::default())?;
/// let mut encoder = device.create_command_encoder(&Default::default());
/// let outputs = pipeline.encode(device, queue, &mut encoder, &AoInputs {
///     normals: Some(normals),
///     ..AoInputs::new(depth, projection)
/// })?;
/// // ... bind `outputs.ao_view` in your lighting pass ...
/// queue.submit([encoder.finish()]);
/// # Ok(()) }
/// ```
pub struct AoPipeline {
    settings: AoSettings,
    view_uniforms: wgpu::Buffer,
    linear_depth: LinearDepthPass,
    normals_from_depth: NormalsFromDepthPass,
    decode_normals: DecodeNormalsPass,
    /// A view of the input normals of the last frame, kept for [`AoOutputs::normals_view`] when
    /// the kernels read them as they are.
    input_normals_view: Option<wgpu::TextureView>,
    method: MethodPass,
    spatial: SpatialFilterPass,
    /// Compiled the first time the temporal filter is on.
    temporal: Option<TemporalFilterPass>,
    /// Each view's temporal history, by [`AoInputs::view_id`].
    histories: HashMap<u32, Option<History>>,
    targets: Option<Targets>,
    timer: Option<PassTimer>,
}

impl AoPipeline {
    /// Compiles the passes the settings need.
    pub fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        settings: &AoSettings,
    ) -> Result<Self, AoError> {
        settings.validate()?;
        let view_uniforms = create_uniform_buffer::<ViewUniforms>(device, "aokit view");
        Ok(Self {
            settings: *settings,
            view_uniforms,
            linear_depth: LinearDepthPass::new(device),
            normals_from_depth: NormalsFromDepthPass::new(device),
            decode_normals: DecodeNormalsPass::default(),
            input_normals_view: None,
            method: MethodPass::new(device, queue, settings),
            spatial: SpatialFilterPass::new(device, queue, &settings.spatial),
            temporal: None,
            histories: HashMap::new(),
            targets: None,
            timer: None,
        })
    }

    /// Times every pass with GPU timestamps from now on. Returns `false`, and changes nothing,
    /// when the device was not created with `Features::TIMESTAMP_QUERY`.
    pub fn enable_timing(&mut self, device: &wgpu::Device, queue: &wgpu::Queue) -> bool {
        if self.timer.is_none() {
            self.timer = PassTimer::new(device, queue);
        }
        self.timer.is_some()
    }

    /// GPU time of each pass of the last encoded frame, once its commands were submitted;
    /// `None` unless [`AoPipeline::enable_timing`] succeeded. Blocks until the GPU is done.
    pub fn last_pass_times(
        &self,
        device: &wgpu::Device,
    ) -> Option<Result<Vec<PassTime>, crate::GpuError>> {
        self.timer.as_ref().map(|timer| timer.read(device))
    }

    /// The settings in use.
    pub fn settings(&self) -> &AoSettings {
        &self.settings
    }

    /// Replaces the settings. Only the settings buffer changes, unless the method is one not
    /// used before (its kernel compiles once), the noise needs a tile not used before (it is
    /// generated and uploaded once), bent normals or the spatial filter are switched (their
    /// textures are made or dropped at the next `encode`; the filter's kernels compile the first
    /// time it is on) or the normals need a decode or reconstruction not used before (its kernel
    /// compiles once, at the next `encode`).
    pub fn set_settings(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        settings: &AoSettings,
    ) -> Result<(), AoError> {
        settings.validate()?;
        self.settings = *settings;
        self.method.set_settings(device, queue, settings);
        self.spatial.set_settings(device, queue, &settings.spatial);
        if let Some(temporal) = &mut self.temporal {
            temporal.set_settings(&settings.temporal);
        }
        Ok(())
    }

    /// Records the passes for one frame into `encoder`. Intermediate textures are (re)created
    /// when the input size changes. The outputs borrow the inputs' textures too: with oct32
    /// input normals, [`AoOutputs::normals`] is the input texture.
    pub fn encode<'a>(
        &'a mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        inputs: &AoInputs<'a>,
    ) -> Result<AoOutputs<'a>, AoError> {
        let encoding = self.settings.normals.encoding;
        let size = inputs.validate(encoding)?;
        inputs.projection.validate()?;
        let max = device.limits().max_texture_dimension_2d;
        if size[0] > max || size[1] > max {
            return Err(AoError::TooLarge { size, max });
        }
        let bent = self.settings.bent_normals;
        let spatial = self.settings.spatial.enabled;
        if self
            .targets
            .as_ref()
            .map(|t| (t.size, t.bent_normals.is_some(), t.spatial.is_some()))
            != Some((size, bent, spatial))
        {
            self.targets = Some(Targets::new(device, size, bent, spatial));
        }
        let targets = self.targets.as_ref().expect("targets were just created");
        queue.write_buffer(
            &self.view_uniforms,
            0,
            bytemuck::bytes_of(&ViewUniforms::new(
                &inputs.projection,
                size,
                inputs.frame_index,
            )),
        );

        if let Some(timer) = self.timer.as_mut() {
            timer.begin_frame();
        }
        let mut ctx = PassContext {
            device,
            encoder,
            view_uniforms: &self.view_uniforms,
            size,
            timer: self.timer.as_mut(),
        };
        self.linear_depth
            .encode(&mut ctx, inputs.depth, &targets.linear_depth_view);
        // Input normals the settings use are read as they are when oct32, else decoded; without
        // them (or when the source is depth) the normals are reconstructed.
        let source = self.settings.normals.source;
        self.input_normals_view = inputs
            .normals
            .filter(|_| source == NormalSource::Buffer)
            .map(|n| n.create_view(&Default::default()));
        let (normals, normals_view) = match (inputs.normals, &self.input_normals_view) {
            (Some(texture), Some(view)) if encoding == NormalEncoding::Oct32 => (texture, view),
            (_, Some(view)) => {
                self.decode_normals
                    .encode(&mut ctx, encoding, view, &targets.normals_view);
                (&targets.normals, &targets.normals_view)
            }
            (_, None) => {
                self.normals_from_depth.encode(
                    &mut ctx,
                    source,
                    &targets.linear_depth_view,
                    &targets.normals_view,
                );
                (&targets.normals, &targets.normals_view)
            }
        };
        self.method.encode(
            &mut ctx,
            self.settings.method,
            &targets.linear_depth_view,
            normals_view,
            &targets.ao_view,
            targets.bent_normals.as_ref().map(|(_, view)| view),
        );
        let (ao, ao_view) = match &targets.spatial {
            Some(spatial) => {
                self.spatial.encode(
                    &mut ctx,
                    &targets.ao_view,
                    &targets.linear_depth_view,
                    normals_view,
                    &spatial.packed_view,
                    &spatial.ao_view,
                );
                (&spatial.ao, &spatial.ao_view)
            }
            None => (&targets.ao, &targets.ao_view),
        };
        let mut history_rejected = None;
        let (ao, ao_view) = if self.settings.temporal.enabled {
            let history = self.histories.entry(inputs.view_id).or_insert(None);
            let motion_vectors = inputs
                .motion_vectors
                .map(|t| t.create_view(&Default::default()));
            let temporal = self
                .temporal
                .get_or_insert_with(|| TemporalFilterPass::new(device, &self.settings.temporal));
            temporal.encode(
                &mut ctx,
                queue,
                history,
                &FrameMotion {
                    view_from_world: inputs.view_from_world,
                    projection: inputs.projection,
                    motion_vectors: motion_vectors.as_ref(),
                    reset: inputs.reset_history,
                },
                ao_view,
                &targets.linear_depth_view,
            );
            let history = history
                .as_ref()
                .expect("the temporal filter keeps a history");
            history_rejected = Some(&history.rejected().0);
            (&history.ao().0, &history.ao().1)
        } else {
            // Off, histories go: when it is turned on again the old frames are stale.
            self.histories.clear();
            (ao, ao_view)
        };
        if let Some(timer) = &self.timer {
            timer.resolve(encoder);
        }
        Ok(AoOutputs {
            ao,
            ao_view,
            raw_ao: &targets.ao,
            raw_ao_view: &targets.ao_view,
            linear_depth: &targets.linear_depth,
            normals,
            normals_view,
            bent_normals: targets.bent_normals.as_ref().map(|(texture, _)| texture),
            bent_normals_view: targets.bent_normals.as_ref().map(|(_, view)| view),
            history_rejected,
        })
    }
}
