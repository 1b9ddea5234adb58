//! Separable HBAO (`hbao.variant = separable`): a pass over rows, then one over columns, each
//! reading lines of linear depth from workgroup memory
//! (`shaders/kernel/separable_hbao/hbao_separable.wgsl`; docs/methods/hbao.md has what it trades
//! for the speed).

use crate::gpu::create_texture_2d;
use crate::passes::kernel::method::{MethodPass, layout};
use crate::passes::{ComputeKernel, PassContext, bind};
use crate::shader;

/// Format of the rows pass's output, the +x and -x directions' occlusion before shaping: the AO
/// kernels' own format, since the sum of two directions reaches past 1 and half floats would
/// round it to 1/1024 near 2.
pub const ROW_OCCLUSION_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Float;

/// The bindings of `shader::HBAO_ROWS`: every AO kernel's, and the row occlusion written.
pub(crate) fn rows_layout() -> Vec<wgpu::BindGroupLayoutEntry> {
    [
        &layout()[..],
        &[bind::storage_texture(9, ROW_OCCLUSION_FORMAT)],
    ]
    .concat()
}

/// The bindings of `shader::HBAO_COLUMNS`: every AO kernel's, and the row occlusion read.
pub(crate) fn columns_layout() -> Vec<wgpu::BindGroupLayoutEntry> {
    let row_occlusion = bind::texture(9, wgpu::TextureSampleType::Float { filterable: false });
    [&layout()[..], &[row_occlusion]].concat()
}

/// The two kernels and the rows pass's output, which follows the size the passes run at.
pub struct SeparableHbaoPass {
    rows: ComputeKernel,
    columns: ComputeKernel,
    row_occlusion: Option<(wgpu::Texture, wgpu::TextureView)>,
}

impl SeparableHbaoPass {
    /// Compiles both kernels: the bindings of every AO kernel, and the rows pass's output at
    /// binding 9, written by the first and read by the second.
    pub fn new(device: &wgpu::Device) -> Self {
        Self {
            rows: ComputeKernel::new(device, &shader::HBAO_ROWS, &rows_layout()),
            columns: ComputeKernel::new(device, &shader::HBAO_COLUMNS, &columns_layout()),
            row_occlusion: None,
        }
    }

    /// Records both passes over `ctx`'s size, from `linear_depth` (`R32Float`) and oct32
    /// `normals` into `ao` (`R32Float`), with the settings buffer and noise of `method`, which
    /// was given the settings that chose this variant.
    pub fn encode(
        &mut self,
        ctx: &mut PassContext<'_>,
        method: &MethodPass,
        linear_depth: &wgpu::TextureView,
        normals: &wgpu::TextureView,
        ao: &wgpu::TextureView,
    ) {
        let size = ctx.size;
        if self
            .row_occlusion
            .as_ref()
            .is_none_or(|(texture, _)| [texture.width(), texture.height()] != size)
        {
            let texture = create_texture_2d(
                ctx.device,
                "aokit hbao row occlusion",
                size,
                ROW_OCCLUSION_FORMAT,
                wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::TEXTURE_BINDING,
            );
            let view = texture.create_view(&Default::default());
            self.row_occlusion = Some((texture, view));
        }
        let (_, row_occlusion) = self.row_occlusion.as_ref().expect("made just above");
        // HBAO has no bent normals: the settings refuse them, and the placeholder is bound.
        let shared = method.bindings(linear_depth, normals, ao, None, None);
        let resources = [
            &shared[..],
            &[wgpu::BindingResource::TextureView(row_occlusion)],
        ]
        .concat();
        ctx.dispatch(&self.rows, &resources);
        // Both kernels' workgroups are a segment of a line along x (`hbao_separable.wgsl`): the
        // columns pass takes its columns as the rows of the transposed grid.
        ctx.size = [size[1], size[0]];
        ctx.dispatch(&self.columns, &resources);
        ctx.size = size;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::SEPARABLE_HBAO_MAX_RADIUS_PX;

    #[test]
    fn the_apron_and_the_line_match_wgsl() {
        for pass in [shader::HBAO_ROWS, shader::HBAO_COLUMNS] {
            let module = pass.validate().unwrap();
            let constant = |name| shader::u32_constant(&module, name);
            assert_eq!(constant("MAX_RADIUS"), Some(SEPARABLE_HBAO_MAX_RADIUS_PX));
            assert_eq!(constant("LINE"), Some(128));
            // Along x in both passes: `encode` transposes the columns pass's grid for it.
            assert_eq!(pass.workgroup_size(), Ok([128, 1, 1]), "{}", pass.name);
        }
    }
}
