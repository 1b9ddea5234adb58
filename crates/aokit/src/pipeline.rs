//! [`AoPipeline`]: owns the passes and the intermediate textures, and wires them per frame.

use crate::error::AoError;
use crate::gpu::{create_texture_2d, create_uniform_buffer};
use crate::inputs::AoInputs;
use crate::passes::gtao::{AO_FORMAT, GtaoPass};
use crate::passes::linear_depth::{LINEAR_DEPTH_FORMAT, LinearDepthPass};
use crate::settings::{AoSettings, Method};
use crate::uniforms::ViewUniforms;

/// Textures sized to the current resolution.
struct Targets {
    size: [u32; 2],
    linear_depth: wgpu::Texture,
    linear_depth_view: wgpu::TextureView,
    ao: wgpu::Texture,
    ao_view: wgpu::TextureView,
}

impl Targets {
    fn new(device: &wgpu::Device, size: [u32; 2]) -> Self {
        let usage = wgpu::TextureUsages::STORAGE_BINDING
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC;
        let make = |label, format| create_texture_2d(device, label, size, format, usage);
        let linear_depth = make("aokit linear depth", LINEAR_DEPTH_FORMAT);
        let ao = make("aokit ao", AO_FORMAT);
        Self {
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
    /// Ambient occlusion, `R32Float`, 1 = unoccluded.
    pub ao: &'a wgpu::Texture,
    /// A view of [`AoOutputs::ao`] for binding.
    pub ao_view: &'a wgpu::TextureView,
    /// Linear view depth, `R32Float`, 0 where nothing was drawn.
    pub linear_depth: &'a wgpu::Texture,
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
///     depth, normals, projection, frame_index: 0,
/// })?;
/// // ... bind `outputs.ao_view` in your lighting pass ...
/// queue.submit([encoder.finish()]);
/// # Ok(()) }
/// ```
pub struct AoPipeline {
    settings: AoSettings,
    view_uniforms: wgpu::Buffer,
    linear_depth: LinearDepthPass,
    gtao: GtaoPass,
    targets: Option<Targets>,
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
        let pipeline = Self {
            settings: *settings,
            view_uniforms,
            linear_depth: LinearDepthPass::new(device),
            gtao: GtaoPass::new(device),
            targets: None,
        };
        pipeline.gtao.set_settings(queue, settings);
        Ok(pipeline)
    }

    /// The settings in use.
    pub fn settings(&self) -> &AoSettings {
        &self.settings
    }

    /// Replaces the settings; only uniform buffers change.
    pub fn set_settings(
        &mut self,
        queue: &wgpu::Queue,
        settings: &AoSettings,
    ) -> Result<(), AoError> {
        settings.validate()?;
        self.settings = *settings;
        match settings.method {
            Method::Gtao => self.gtao.set_settings(queue, settings),
        }
        Ok(())
    }

    /// Records the passes for one frame into `encoder`. Intermediate textures are (re)created
    /// when the input size changes.
    pub fn encode(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        inputs: &AoInputs<'_>,
    ) -> Result<AoOutputs<'_>, AoError> {
        let size = inputs.validate()?;
        inputs.projection.validate()?;
        let max = device.limits().max_texture_dimension_2d;
        if size[0] > max || size[1] > max {
            return Err(AoError::TooLarge { size, max });
        }
        if self.targets.as_ref().map(|t| t.size) != Some(size) {
            self.targets = Some(Targets::new(device, size));
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

        let depth_view = inputs.depth.create_view(&wgpu::TextureViewDescriptor {
            aspect: wgpu::TextureAspect::DepthOnly,
            ..Default::default()
        });
        let normals_view = inputs.normals.create_view(&Default::default());
        self.linear_depth.encode(
            device,
            encoder,
            &self.view_uniforms,
            &depth_view,
            &targets.linear_depth_view,
            size,
        );
        match self.settings.method {
            Method::Gtao => self.gtao.encode(
                device,
                encoder,
                &self.view_uniforms,
                &targets.linear_depth_view,
                &normals_view,
                &targets.ao_view,
                size,
            ),
        }
        Ok(AoOutputs {
            ao: &targets.ao,
            ao_view: &targets.ao_view,
            linear_depth: &targets.linear_depth,
        })
    }
}
