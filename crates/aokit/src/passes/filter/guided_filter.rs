//! The spatial denoiser's guided kind: He, Sun and Tang's guided filter of the AO with the log of
//! linear depth as the guide, as two compute passes that stage their windows in workgroup
//! memory (`shaders/filter/guided_filter.wgsl`; formulas and measurements in docs/denoise.md).

use std::collections::HashMap;

use crate::gpu::{PairFormat, create_uniform_buffer};
use crate::passes::kernel::method::AO_FORMAT;
use crate::passes::{ComputeKernel, PassContext, bind};
use crate::settings::{SpatialKind, SpatialSettings};
use crate::shader;
use crate::uniforms::GuidedUniforms;

/// The bindings of either pass, `output` the format it writes: view uniforms, filter settings,
/// the pass's first input (the AO, then the lines), the linear depth, and its output.
pub(crate) fn layout(output: wgpu::TextureFormat) -> [wgpu::BindGroupLayoutEntry; 5] {
    let float = wgpu::TextureSampleType::Float { filterable: false };
    [
        bind::uniform(0),
        bind::uniform(1),
        bind::texture(2, float),
        bind::texture(3, float),
        bind::storage_texture(4, output),
    ]
}

/// The two kernels of the filter and its settings buffer.
pub struct GuidedFilterPass {
    /// Per window radius (the shader's `RADIUS`), compiled the first time settings of the
    /// guided kind ask for it.
    kernels: HashMap<u32, [ComputeKernel; 2]>,
    /// The radius of the settings last given, when they select the guided kind.
    current: Option<u32>,
    uniforms: wgpu::Buffer,
    /// The format of the first pass's output: each window's slope in r and the value of its
    /// line at the window's centre in g, both f32 like the AO. The bilateral kind's, so the
    /// pipeline's one intermediate texture serves both kinds.
    pair: PairFormat,
}

impl GuidedFilterPass {
    /// Creates the settings buffer and uploads `settings`, compiling the kernels if they select
    /// the guided kind; the first pass writes `pair`.
    pub fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        settings: &SpatialSettings,
        pair: PairFormat,
    ) -> Self {
        let mut pass = Self {
            kernels: HashMap::new(),
            current: None,
            uniforms: create_uniform_buffer::<GuidedUniforms>(device, "aokit guided settings"),
            pair,
        };
        pass.set_settings(device, queue, settings);
        pass
    }

    /// Uploads validated settings for later `encode`s, compiling the kernels the first time
    /// settings of the guided kind ask for their radius.
    pub fn set_settings(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        settings: &SpatialSettings,
    ) {
        let enabled = settings.enabled && settings.kind == SpatialKind::Guided;
        self.current = enabled.then_some(settings.guided_radius);
        if let Some(radius) = self.current {
            let constants = [("RADIUS", f64::from(radius))];
            self.kernels.entry(radius).or_insert_with(|| {
                [
                    ComputeKernel::with_constants(
                        device,
                        &shader::GUIDED_FILTER_COEFFICIENTS[self.pair as usize],
                        &layout(self.pair.texture_format()),
                        &constants,
                    ),
                    ComputeKernel::with_constants(
                        device,
                        &shader::GUIDED_FILTER_OUTPUT,
                        &layout(AO_FORMAT),
                        &constants,
                    ),
                ]
            });
        }
        queue.write_buffer(
            &self.uniforms,
            0,
            bytemuck::bytes_of(&GuidedUniforms::new(settings)),
        );
    }

    /// Records both passes: every window's line fitted to `ao` against `linear_depth` into
    /// `coefficients` (the pass's [`PairFormat`]), then each pixel's average of the lines of the
    /// windows that hold it into `output` (`R32Float`, as the AO kernels write).
    ///
    /// # Panics
    /// When the settings last given do not select the guided kind.
    pub fn encode(
        &self,
        ctx: &mut PassContext<'_>,
        ao: &wgpu::TextureView,
        linear_depth: &wgpu::TextureView,
        coefficients: &wgpu::TextureView,
        output: &wgpu::TextureView,
    ) {
        let [fit, average] = self
            .current
            .map(|radius| &self.kernels[&radius])
            .expect("the guided filter runs only with settings that select it");
        let view = wgpu::BindingResource::TextureView;
        let uniforms = self.uniforms.as_entire_binding();
        ctx.dispatch(
            fit,
            &[
                uniforms.clone(),
                view(ao),
                view(linear_depth),
                view(coefficients),
            ],
        );
        ctx.dispatch(
            average,
            &[
                uniforms,
                view(coefficients),
                view(linear_depth),
                view(output),
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
    use crate::settings::MAX_SPATIAL_RADIUS;

    #[test]
    fn constants_match_wgsl() {
        for pass in [
            shader::GUIDED_FILTER_COEFFICIENTS[0],
            shader::GUIDED_FILTER_COEFFICIENTS[1],
            shader::GUIDED_FILTER_OUTPUT,
        ] {
            let module = pass.validate().unwrap();
            assert_eq!(
                shader::u32_constant(&module, "MAX_RADIUS"),
                Some(MAX_SPATIAL_RADIUS)
            );
            assert_eq!(pass.workgroup_size(), Ok([16, 16, 1]));
        }
    }

    /// The filtered AO of `image`, from both passes on the GPU.
    fn filter(gpu: &GpuContext, settings: &SpatialSettings, image: &Image) -> Vec<f32> {
        let pair = PairFormat::of(&gpu.device);
        let pass = GuidedFilterPass::new(&gpu.device, &gpu.queue, settings, pair);
        run_filter(gpu, image, |ctx, t| {
            pass.encode(ctx, &t.ao, &t.depth, &t.packed, &t.output);
        })
    }

    fn guided(guided_radius: u32, guided_epsilon: f32) -> SpatialSettings {
        SpatialSettings {
            enabled: true,
            kind: SpatialKind::Guided,
            guided_radius,
            guided_epsilon,
            ..SpatialSettings::default()
        }
    }

    /// Windows of every size, with epsilons that keep the test image's 3x depth step (a log
    /// depth variance of about 0.3 in windows astride it); the step test's settings.
    fn edge_keeping() -> Vec<SpatialSettings> {
        vec![
            guided(1, SpatialSettings::default().guided_epsilon),
            guided(3, 1e-3),
            guided(8, 1e-2),
            guided(4, 1e-8),
        ]
    }

    #[test]
    fn constant_ao_stays_constant() {
        let gpu = gpu();
        let flat = image(|_, _, _| 0.37);
        // An epsilon far above every window's variance too: the filter is then a plain mean of
        // means, which must keep a constant as well.
        for settings in edge_keeping().into_iter().chain([guided(5, 10.0)]) {
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
        for settings in edge_keeping() {
            let filtered = filter(&gpu, &settings, &noisy);
            let mut sides = [Vec::new(), Vec::new()];
            // Squared errors against each side's noise-free mean, within 2 pixels of the step.
            let (mut edge_before, mut edge_after, mut edge_pixels) = (0.0, 0.0, 0.0);
            for (i, &ao) in filtered.iter().enumerate() {
                let x = i as u32 % SIZE[0];
                let near = x < STEP_X;
                if noisy.depth[i] == 0.0 {
                    assert_eq!(ao, 1.0, "{settings:?}: sky pixel {i}");
                    continue;
                }
                // A line fitted across the step tilts a little over each side's own slope
                // (the far plane's depth grows 3.6% a pixel): 0.02 of slack, against the 0.5
                // a blur across the step would add.
                let low = level(near);
                assert!(
                    (low - 0.02..=low + 0.12).contains(&ao),
                    "{settings:?}: pixel {i} on the {} side reads {ao}",
                    if near { "near" } else { "far" }
                );
                if x.abs_diff(STEP_X) <= 2 {
                    let truth = low + 0.05;
                    edge_before += (noisy.ao[i] - truth).powi(2);
                    edge_after += (ao - truth).powi(2);
                    edge_pixels += 1.0;
                }
                sides[usize::from(near)].push((ao, noisy.ao[i]));
            }
            let (before, after) = (edge_before / edge_pixels, edge_after / edge_pixels);
            assert!(
                after < 0.7 * before,
                "{settings:?}: edge MSE {before} -> {after}"
            );
            for side in &sides {
                let after = standard_deviation(side.iter().map(|v| v.0));
                let before = standard_deviation(side.iter().map(|v| v.1));
                assert!(after < 0.5 * before, "{settings:?}: {before} -> {after}");
            }
        }
    }

    #[test]
    fn extreme_inputs_stay_finite_and_in_the_unit_range() {
        let gpu = gpu();
        // AO 0 or 1 at random over depths from 1e-3 to 1e6, beside sky: least-squares lines
        // with steep slopes, which overshoot [0, 1] without the clamp.
        let mut wild = image(|_, x, y| (hash(x, y) < 0.5) as u8 as f32);
        for (i, depth) in wild.depth.iter_mut().enumerate() {
            if *depth != 0.0 {
                let (x, y) = (i as u32 % SIZE[0], i as u32 / SIZE[0]);
                *depth = 10f32.powf(9.0 * hash(y, x) - 3.0);
            }
        }
        for settings in [guided(1, 1e-12), guided(4, 1e-4), guided(8, 1e3)] {
            for (i, &ao) in filter(&gpu, &settings, &wild).iter().enumerate() {
                assert!(
                    (0.0..=1.0).contains(&ao),
                    "{settings:?}: pixel {i} reads {ao}"
                );
            }
        }
    }
}
