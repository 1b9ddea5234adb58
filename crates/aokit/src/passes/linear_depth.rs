//! Prepare pass: the renderer's depth to linear view depth, 0 where there is no surface.

use super::{ComputeKernel, PassContext, bind};
use crate::shader::{self, ShaderSource};

/// Format of the linear depth the AO kernels read.
pub const LINEAR_DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Float;

/// Converts hardware depth (any depth format) or linear depth (`R32Float`) to the linear depth
/// the kernels read. Multisampled depth contributes its sample 0: the depth of one surface, as
/// a resolve that averages would not give at silhouettes.
pub struct LinearDepthPass {
    from_hardware: ComputeKernel,
    from_linear: ComputeKernel,
    /// The multisampled variants, compiled the first time such a depth comes in.
    from_hardware_multisampled: Option<ComputeKernel>,
    from_linear_multisampled: Option<ComputeKernel>,
}

/// The kernel of `source` reading its depth as `sample_type`.
fn kernel(
    device: &wgpu::Device,
    source: &ShaderSource,
    sample_type: wgpu::TextureSampleType,
    multisampled: bool,
) -> ComputeKernel {
    ComputeKernel::new(
        device,
        source,
        &[
            bind::uniform(0),
            bind::texture_with_samples(1, sample_type, multisampled),
            bind::storage_texture(2, LINEAR_DEPTH_FORMAT),
        ],
    )
}

const DEPTH: wgpu::TextureSampleType = wgpu::TextureSampleType::Depth;
const LINEAR: wgpu::TextureSampleType = wgpu::TextureSampleType::Float { filterable: false };

impl LinearDepthPass {
    /// Compiles the single-sampled variants.
    pub fn new(device: &wgpu::Device) -> Self {
        Self {
            from_hardware: kernel(device, &shader::LINEAR_DEPTH, DEPTH, false),
            from_linear: kernel(device, &shader::IMPORT_DEPTH, LINEAR, false),
            from_hardware_multisampled: None,
            from_linear_multisampled: None,
        }
    }

    /// Records the pass for `depth`, a depth texture or an `R32Float` linear-depth texture,
    /// single-sampled or multisampled.
    pub fn encode(
        &mut self,
        ctx: &mut PassContext<'_>,
        depth: &wgpu::Texture,
        output: &wgpu::TextureView,
    ) {
        let hardware = depth.format().has_depth_aspect();
        let device = ctx.device;
        let kernel = match (hardware, depth.sample_count() > 1) {
            (true, false) => &self.from_hardware,
            (false, false) => &self.from_linear,
            (true, true) => self.from_hardware_multisampled.get_or_insert_with(|| {
                kernel(device, &shader::LINEAR_DEPTH_MULTISAMPLED, DEPTH, true)
            }),
            (false, true) => self.from_linear_multisampled.get_or_insert_with(|| {
                kernel(device, &shader::IMPORT_DEPTH_MULTISAMPLED, LINEAR, true)
            }),
        };
        let input = depth.create_view(&wgpu::TextureViewDescriptor {
            aspect: if hardware {
                wgpu::TextureAspect::DepthOnly
            } else {
                wgpu::TextureAspect::All
            },
            ..Default::default()
        });
        ctx.dispatch(
            kernel,
            &[
                wgpu::BindingResource::TextureView(&input),
                wgpu::BindingResource::TextureView(output),
            ],
        );
    }
}
