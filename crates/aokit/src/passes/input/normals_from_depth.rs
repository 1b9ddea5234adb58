//! Normals reconstructed from linear depth, for inputs without a normal buffer or when
//! [`NormalsSettings::source`](crate::NormalsSettings::source) asks for them.

use std::collections::HashMap;

use crate::passes::{ComputeKernel, PassContext, bind};
use crate::settings::NormalSource;
use crate::shader;

/// Format of the normals the AO kernels read, reconstructed or decoded: oct32, as a G-buffer
/// would hold them.
pub const NORMALS_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Uint;

/// The reconstruction [`NormalSource::Buffer`] falls back to without a normal texture: the one
/// with the lowest angular error against the G-buffer normals and the lowest AO error on the
/// built-in scenes and Sponza (docs/normals.md).
pub const BEST_RECONSTRUCTION: NormalSource = NormalSource::Depth5tap;

/// The bindings of `shader::NORMALS_FROM_DEPTH`: view uniforms, the linear depth, the normals
/// written.
pub(crate) fn layout() -> [wgpu::BindGroupLayoutEntry; 3] {
    [
        bind::uniform(0),
        bind::texture(1, wgpu::TextureSampleType::Float { filterable: false }),
        bind::storage_texture(2, NORMALS_FORMAT),
    ]
}

/// Writes oct32 view-space normals from linear depth.
pub struct NormalsFromDepthPass {
    /// One kernel per reconstruction, compiled the first time it is used.
    kernels: HashMap<NormalSource, ComputeKernel>,
}

impl NormalsFromDepthPass {
    /// Compiles the fallback reconstruction, [`BEST_RECONSTRUCTION`]; others compile on first use.
    pub fn new(device: &wgpu::Device) -> Self {
        let mut pass = Self {
            kernels: HashMap::new(),
        };
        pass.kernel(device, BEST_RECONSTRUCTION);
        pass
    }

    fn kernel(&mut self, device: &wgpu::Device, source: NormalSource) -> &ComputeKernel {
        self.kernels.entry(source).or_insert_with(|| {
            ComputeKernel::with_constants(
                device,
                &shader::NORMALS_FROM_DEPTH,
                &layout(),
                &[("SOURCE", f64::from(source as u32))],
            )
        })
    }

    /// Records the reconstruction `source` names ([`BEST_RECONSTRUCTION`] for
    /// [`NormalSource::Buffer`]), from `linear_depth` (`R32Float`, 0 where there is no
    /// surface) into `output`, an oct32 storage texture ([`NORMALS_FORMAT`]).
    pub fn encode(
        &mut self,
        ctx: &mut PassContext<'_>,
        source: NormalSource,
        linear_depth: &wgpu::TextureView,
        output: &wgpu::TextureView,
    ) {
        let source = match source {
            NormalSource::Buffer => BEST_RECONSTRUCTION,
            depth => depth,
        };
        let kernel = self.kernel(ctx.device, source);
        ctx.dispatch(
            kernel,
            &[
                wgpu::BindingResource::TextureView(linear_depth),
                wgpu::BindingResource::TextureView(output),
            ],
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn source_codes_match_wgsl() {
        let module = shader::NORMALS_FROM_DEPTH.validate().unwrap();
        for source in [
            NormalSource::DepthNaive,
            NormalSource::Depth3tap,
            NormalSource::Depth5tap,
        ] {
            let name = format!("SOURCE_{}", source.name().replace('-', "_").to_uppercase());
            assert_eq!(
                shader::u32_constant(&module, &name),
                Some(source as u32),
                "{name}"
            );
        }
    }
}
