//! The spatial denoiser's `edges` kind: one 3x3 edge-aware pass with the bilateral kind's
//! weights (`shaders/filter/edge_filter.wgsl`; measurements in docs/denoise.md).

use std::collections::HashMap;

use super::Weights;
use crate::gpu::{create_uniform_buffer, stand_in_view};
use crate::passes::kernel::method::{AO_AND_DEPTH_FORMAT, AO_FORMAT};
use crate::passes::{ComputeKernel, PassContext, bind};
use crate::settings::{SpatialKind, SpatialSettings};
use crate::shader;
use crate::uniforms::SpatialUniforms;

/// The bindings of `shader::EDGE_FILTER`: view uniforms, filter settings, the AO, the linear
/// depth, the normals, the filtered AO written, the point-clamp sampler its gathers read
/// through, the AO and depth packed.
pub(crate) fn layout() -> [wgpu::BindGroupLayoutEntry; 8] {
    let float = wgpu::TextureSampleType::Float { filterable: false };
    let uint = wgpu::TextureSampleType::Uint;
    [
        bind::uniform(0),
        bind::uniform(1),
        bind::texture(2, float),
        bind::texture(3, float),
        bind::texture(4, uint),
        bind::storage_texture(5, AO_FORMAT),
        bind::sampler(6, wgpu::SamplerBindingType::NonFiltering),
        bind::texture(7, uint),
    ]
}

/// The filter's kernels and its settings buffer.
pub struct EdgeFilterPass {
    /// Per weights' variant (the shader's overrides) and whether it reads the AO and depth
    /// packed, compiled the first time a frame asks for it.
    kernels: HashMap<(Weights, bool), ComputeKernel>,
    /// The variant of the settings last given, when they select the edges kind.
    current: Option<Weights>,
    uniforms: wgpu::Buffer,
    point_clamp: wgpu::Sampler,
    /// Bound in place of the packed AO and depth when the pass reads the two textures.
    packed_placeholder: wgpu::TextureView,
}

impl EdgeFilterPass {
    /// Creates the settings buffer and uploads `settings`, compiling a kernel if they select
    /// the edges kind.
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue, settings: &SpatialSettings) -> Self {
        let mut pass = Self {
            kernels: HashMap::new(),
            current: None,
            uniforms: create_uniform_buffer::<SpatialUniforms>(device, "aokit edge filter"),
            point_clamp: crate::gpu::create_point_clamp_sampler(
                device,
                "aokit edge filter point clamp",
            ),
            packed_placeholder: stand_in_view(
                device,
                "aokit edge filter packed placeholder",
                AO_AND_DEPTH_FORMAT,
                wgpu::TextureUsages::TEXTURE_BINDING,
            ),
        };
        pass.set_settings(device, queue, settings);
        pass
    }

    /// Uploads validated settings for later `encode`s, compiling the kernel the first time
    /// settings of the edges kind ask for its variant.
    pub fn set_settings(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        settings: &SpatialSettings,
    ) {
        let enabled = settings.enabled && settings.kind == SpatialKind::Edges;
        self.current = enabled.then(|| Weights::of(settings));
        if let Some(weights) = self.current {
            self.kernel(device, weights, settings.packed_input);
        }
        queue.write_buffer(
            &self.uniforms,
            0,
            bytemuck::bytes_of(&SpatialUniforms::new(settings)),
        );
    }

    /// Compiles the variant of `weights` that reads the AO and depth packed or not, unless it
    /// is already.
    fn kernel(&mut self, device: &wgpu::Device, weights: Weights, packed: bool) {
        self.kernels.entry((weights, packed)).or_insert_with(|| {
            let packed = ("PACKED_INPUT", f64::from(u8::from(packed)));
            ComputeKernel::with_constants(
                device,
                &shader::EDGE_FILTER,
                &layout(),
                &[&weights.constants()[..], &[packed]].concat(),
            )
        });
    }

    /// Records the pass: `ao` filtered across its 3x3 neighbourhoods of `linear_depth` and
    /// oct32 `normals` into `output` (`R32Float`, as the AO kernels write). Given
    /// `ao_and_depth`, the two as a per-pixel kernel packs them into one texel
    /// ([`SpatialSettings::packed_input`]), the AO and depth are read from it instead.
    ///
    /// # Panics
    /// When the settings last given do not select the edges kind.
    pub fn encode(
        &mut self,
        ctx: &mut PassContext<'_>,
        ao: &wgpu::TextureView,
        linear_depth: &wgpu::TextureView,
        normals: &wgpu::TextureView,
        ao_and_depth: Option<&wgpu::TextureView>,
        output: &wgpu::TextureView,
    ) {
        let weights = self
            .current
            .expect("the edge filter runs only with settings that select it");
        let packed = ao_and_depth.is_some();
        self.kernel(ctx.device, weights, packed);
        let view = wgpu::BindingResource::TextureView;
        ctx.dispatch(
            &self.kernels[&(weights, packed)],
            &[
                self.uniforms.as_entire_binding(),
                view(ao),
                view(linear_depth),
                view(normals),
                view(output),
                wgpu::BindingResource::Sampler(&self.point_clamp),
                view(ao_and_depth.unwrap_or(&self.packed_placeholder)),
            ],
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::GpuContext;
    use crate::passes::filter::spatial_filter::tests::{
        Image, SIZE, STEP_X, gpu, hash, image, run_filter, standard_deviation,
    };
    use crate::settings::DepthWeight;
    use glam::Vec3;

    #[test]
    fn constants_match_wgsl() {
        let module = shader::EDGE_FILTER.validate().unwrap();
        for (name, weight) in [
            ("DEPTH_GAUSSIAN", DepthWeight::Gaussian),
            ("DEPTH_THRESHOLD", DepthWeight::Threshold),
        ] {
            assert_eq!(
                shader::u32_constant(&module, name),
                Some(weight as u32),
                "{name}"
            );
        }
    }

    fn filter(gpu: &GpuContext, settings: &SpatialSettings, image: &Image) -> Vec<f32> {
        let mut pass = EdgeFilterPass::new(&gpu.device, &gpu.queue, settings);
        run_filter(gpu, image, |ctx, t| {
            pass.encode(ctx, &t.ao, &t.depth, &t.normals, None, &t.output);
        })
    }

    /// The edges kind with each depth weight, with and without normals.
    fn variants() -> Vec<SpatialSettings> {
        let edges = SpatialSettings {
            enabled: true,
            kind: SpatialKind::Edges,
            ..SpatialSettings::default()
        };
        vec![
            edges,
            SpatialSettings {
                normal_power: 0.0,
                ..edges
            },
            SpatialSettings {
                depth_weight: DepthWeight::Threshold,
                ..edges
            },
        ]
    }

    #[test]
    fn a_normal_power_of_two_weighs_as_its_logarithm_does() {
        // Normals tilted from pixel to pixel, so that the normal weight differs from 1.
        let mut tilted = image(|near, x, y| if near { 0.3 } else { 0.6 } + 0.2 * hash(x, y));
        for (i, n) in tilted.normals.iter_mut().enumerate() {
            let (x, y) = (i as u32 % SIZE[0], i as u32 / SIZE[0]);
            let tilt = glam::Vec3::new(hash(x, y) - 0.5, hash(y, x) - 0.5, 0.0);
            *n = (*n + 0.6 * tilt).normalize();
        }
        let at = |normal_power| SpatialSettings {
            normal_power,
            ..variants()[0]
        };
        // 16 compiles to four squarings, 16.0001 to a log2 and an exp2.
        let squared = filter(&gpu(), &at(16.0), &tilted);
        let logarithm = filter(&gpu(), &at(16.0001), &tilted);
        let without = filter(&gpu(), &at(0.0), &tilted);
        let largest = |a: &[f32], b: &[f32]| {
            a.iter()
                .zip(b)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0f32, f32::max)
        };
        assert!(largest(&squared, &logarithm) < 1e-4);
        assert!(largest(&squared, &without) > 1e-2);
    }

    #[test]
    fn across_a_crease_the_edge_neighbours_drop_out_and_the_diagonals_weigh_by_depth() {
        // One depth on both sides of column STEP_X, where the normal turns by 106 degrees: the
        // normal weight drops the neighbour across the crease that shares an edge; the diagonal
        // ones take no normal weight (edge_facings), so they count as on a plane.
        let mut crease = image(|near, _, _| if near { 0.2 } else { 0.7 });
        for (i, (depth, normal)) in crease.depth.iter_mut().zip(&mut crease.normals).enumerate() {
            if *depth != 0.0 {
                let left = (i as u32 % SIZE[0]) < STEP_X;
                *depth = 3.0;
                *normal = Vec3::new(if left { -0.8 } else { 0.8 }, 0.0, 0.6);
            }
        }
        let settings = variants()[0];
        let filtered = filter(&gpu(), &settings, &crease);
        // The spatial factor of an edge neighbour; a diagonal one's is its square.
        let k = (-0.5 / (settings.sigma * settings.sigma)).exp();
        // Beside the crease: the centre, three edge and two diagonal neighbours on its own
        // side, two diagonal ones across.
        let beside = |own: f32, across: f32| {
            (own * (1.0 + 3.0 * k + 2.0 * k * k) + across * 2.0 * k * k)
                / (1.0 + 3.0 * k + 4.0 * k * k)
        };
        for y in 12..SIZE[1] - 2 {
            for x in [STEP_X - 2, STEP_X - 1, STEP_X, STEP_X + 1] {
                let i = (y * SIZE[0] + x) as usize;
                let expected = match x {
                    x if x == STEP_X - 1 => beside(0.2, 0.7),
                    x if x == STEP_X => beside(0.7, 0.2),
                    _ => crease.ao[i],
                };
                assert!(
                    (filtered[i] - expected).abs() < 1e-4,
                    "({x}, {y}) reads {} for {expected}",
                    filtered[i]
                );
            }
        }
    }

    #[test]
    fn constant_ao_stays_constant_and_sky_stays_one() {
        let gpu = gpu();
        let flat = image(|_, _, _| 0.37);
        for settings in variants() {
            for (i, &ao) in filter(&gpu, &settings, &flat).iter().enumerate() {
                let expected = if flat.depth[i] == 0.0 { 1.0 } else { 0.37 };
                assert!(
                    (ao - expected).abs() < 1e-5,
                    "{settings:?}: pixel {i} reads {ao}"
                );
            }
        }
    }

    #[test]
    fn a_depth_step_keeps_its_step_and_noise_drops_on_both_planes() {
        let gpu = gpu();
        let level = |near| if near { 0.2 } else { 0.7 };
        let noisy = image(|near, x, y| level(near) + 0.1 * hash(x, y));
        for settings in variants() {
            let filtered = filter(&gpu, &settings, &noisy);
            let mut sides = [Vec::new(), Vec::new()];
            for (i, &ao) in filtered.iter().enumerate() {
                if noisy.depth[i] == 0.0 {
                    continue;
                }
                let near = i as u32 % SIZE[0] < STEP_X;
                // Nothing crosses the step: each side stays within its own noise.
                let low = level(near);
                assert!(
                    (low..=low + 0.1).contains(&ao),
                    "{settings:?}: pixel {i} reads {ao}"
                );
                sides[usize::from(near)].push((ao, noisy.ao[i]));
            }
            for side in &sides {
                let after = standard_deviation(side.iter().map(|v| v.0));
                let before = standard_deviation(side.iter().map(|v| v.1));
                // Nine taps at most: about a third of the noise's deviation goes.
                assert!(after < 0.75 * before, "{settings:?}: {before} -> {after}");
            }
        }
    }
}
