//! The spatial denoiser: a separable bilateral blur of the AO, horizontal then vertical, each
//! pass a compute kernel that stages its row segment or four column segments in workgroup memory
//! (`shaders/filter/spatial_filter.wgsl`; formulas and measurements in docs/denoise.md).

use std::collections::HashMap;

use super::Weights;
use crate::gpu::{PairFormat, create_uniform_buffer, stand_in_view};
use crate::passes::kernel::method::AO_FORMAT;
use crate::passes::{ComputeKernel, PassContext, bind};
use crate::settings::{SpatialKind, SpatialSettings};
use crate::shader;
use crate::uniforms::SpatialUniforms;

// The horizontal pass's output holds AO in r and linear depth in g, in the device's
// `PairFormat`, so that the vertical pass reads one texture. Two halves packed in an `R32Uint`
// (`Rg16Float` is no storage format in core WebGPU) scored the same to four decimals and would
// move 28 bytes a pixel instead of 36, but a half overflows past a depth of 65504 units, which
// scenes in millimetres reach (docs/denoise.md).

/// What the kernels compile in (the shader's `override`s): the radius and the weights.
type Variant = (u32, Weights);

/// Where the vertical pass writes the filtered AO.
#[derive(Clone, Copy, Debug)]
pub enum SpatialOutput<'a> {
    /// The AO alone, `R32Float`, as the AO kernels write it.
    Ao(&'a wgpu::TextureView),
    /// The AO in r and the linear depth in g, in the pass's [`PairFormat`]: what the temporal
    /// filter reads in one load (`TemporalInput::Packed`).
    ///
    /// [`TemporalInput::Packed`]: crate::passes::filter::temporal_filter::TemporalInput::Packed
    AoAndDepth(&'a wgpu::TextureView),
}

/// The bindings both passes share: view uniforms, filter settings, normals, and each pass's
/// first input (the AO along rows, the packed AO and depth along columns).
fn shared_layout() -> [wgpu::BindGroupLayoutEntry; 4] {
    [
        bind::uniform(0),
        bind::uniform(1),
        bind::texture(2, wgpu::TextureSampleType::Uint),
        bind::texture(3, wgpu::TextureSampleType::Float { filterable: false }),
    ]
}

/// The bindings of `shader::SPATIAL_FILTER_HORIZONTAL[pair as usize]`: the shared ones, the
/// linear depth, the packed AO and depth written.
pub(crate) fn horizontal_layout(pair: PairFormat) -> Vec<wgpu::BindGroupLayoutEntry> {
    let own = [
        bind::texture(4, wgpu::TextureSampleType::Float { filterable: false }),
        bind::storage_texture(5, pair.texture_format()),
    ];
    [&shared_layout()[..], &own].concat()
}

/// The bindings of `shader::SPATIAL_FILTER_VERTICAL[pair as usize]`: the shared ones and both
/// outputs, the one not written bound to a stand-in.
pub(crate) fn vertical_layout(pair: PairFormat) -> Vec<wgpu::BindGroupLayoutEntry> {
    let own = [
        bind::storage_texture(4, AO_FORMAT),
        bind::storage_texture(5, pair.texture_format()),
    ];
    [&shared_layout()[..], &own].concat()
}

/// The kernels of the filter and its settings buffer.
pub struct SpatialFilterPass {
    /// Per variant, compiled the first time settings that enable the filter ask for it: the
    /// horizontal pass, and the vertical pass writing `SpatialOutput::Ao` and
    /// `SpatialOutput::AoAndDepth`.
    kernels: HashMap<Variant, [ComputeKernel; 3]>,
    /// The variant of the settings last given, when they enable the filter.
    current: Option<Variant>,
    uniforms: wgpu::Buffer,
    /// The format of the horizontal pass's output and of `SpatialOutput::AoAndDepth`.
    pair: PairFormat,
    /// Bound in place of the vertical pass's output it does not write.
    ao_stand_in: wgpu::TextureView,
    packed_stand_in: wgpu::TextureView,
}

impl SpatialFilterPass {
    /// Creates the settings buffer and uploads `settings`, compiling the kernels if they
    /// enable the bilateral kind; the horizontal pass writes `pair`.
    pub fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        settings: &SpatialSettings,
        pair: PairFormat,
    ) -> Self {
        let stand_in = |format| {
            let usage = wgpu::TextureUsages::STORAGE_BINDING;
            stand_in_view(device, "aokit spatial filter stand-in", format, usage)
        };
        let mut pass = Self {
            kernels: HashMap::new(),
            current: None,
            uniforms: create_uniform_buffer::<SpatialUniforms>(device, "aokit spatial settings"),
            pair,
            ao_stand_in: stand_in(AO_FORMAT),
            packed_stand_in: stand_in(pair.texture_format()),
        };
        pass.set_settings(device, queue, settings);
        pass
    }

    /// Uploads validated settings for later `encode`s, compiling the kernels the first time
    /// settings of the bilateral kind ask for their radius, depth weight and normal weight.
    pub fn set_settings(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        settings: &SpatialSettings,
    ) {
        let enabled = settings.enabled && settings.kind == SpatialKind::Bilateral;
        self.current = enabled.then(|| (settings.radius, Weights::of(settings)));
        if let Some(variant) = self.current {
            let (radius, weights) = variant;
            let constants = [&[("RADIUS", f64::from(radius))][..], &weights.constants()].concat();
            let pair = self.pair;
            self.kernels.entry(variant).or_insert_with(|| {
                let vertical = |packed_output: bool| {
                    let packed = ("PACKED_OUTPUT", f64::from(u8::from(packed_output)));
                    ComputeKernel::with_constants(
                        device,
                        &shader::SPATIAL_FILTER_VERTICAL[pair as usize],
                        &vertical_layout(pair),
                        &[&constants[..], &[packed]].concat(),
                    )
                };
                [
                    ComputeKernel::with_constants(
                        device,
                        &shader::SPATIAL_FILTER_HORIZONTAL[pair as usize],
                        &horizontal_layout(pair),
                        &constants,
                    ),
                    vertical(false),
                    vertical(true),
                ]
            });
        }
        queue.write_buffer(
            &self.uniforms,
            0,
            bytemuck::bytes_of(&SpatialUniforms::new(settings)),
        );
    }

    /// Records both passes: `ao` and `linear_depth` (with `normals`, oct32, for the normal
    /// weight) filtered along rows into `packed` (the pass's [`PairFormat`]), then along
    /// columns into `output`.
    ///
    /// # Panics
    /// When the settings last given do not enable the bilateral kind.
    ///
    /// See [`SpatialFilterPass`] for an example.
    pub fn encode(
        &self,
        ctx: &mut PassContext<'_>,
        ao: &wgpu::TextureView,
        linear_depth: &wgpu::TextureView,
        normals: &wgpu::TextureView,
        packed: &wgpu::TextureView,
        output: SpatialOutput<'_>,
    ) {
        let [horizontal, to_ao, to_pair] = self
            .current
            .map(|variant| &self.kernels[&variant])
            .expect("the spatial filter runs only with settings that enable it");
        let (vertical, ao_out, packed_out) = match output {
            SpatialOutput::Ao(ao) => (to_ao, ao, &self.packed_stand_in),
            SpatialOutput::AoAndDepth(pair) => (to_pair, &self.ao_stand_in, pair),
        };
        let view = wgpu::BindingResource::TextureView;
        ctx.dispatch(
            horizontal,
            &[
                self.uniforms.as_entire_binding(),
                view(normals),
                view(ao),
                view(linear_depth),
                view(packed),
            ],
        );
        ctx.dispatch(
            vertical,
            &[
                self.uniforms.as_entire_binding(),
                view(normals),
                view(packed),
                view(ao_out),
                view(packed_out),
            ],
        );
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use glam::Vec3;

    use super::*;
    use crate::gpu::{create_texture_2d, read_texture, read_texture_f32, upload_texture_2d};
    use crate::normals::pack_oct32;
    use crate::settings::{DepthWeight, MAX_SPATIAL_RADIUS};
    use crate::uniforms::ViewUniforms;
    use crate::{GpuContext, Projection};

    /// Neither side a multiple of the 64-pixel segments, so partial workgroups run both ways.
    pub(crate) const SIZE: [u32; 2] = [100, 70];
    /// Columns left of this are a near plane, the rest a far one.
    pub(crate) const STEP_X: u32 = 40;

    #[test]
    fn constants_match_wgsl() {
        for pass in [
            shader::SPATIAL_FILTER_HORIZONTAL[0],
            shader::SPATIAL_FILTER_HORIZONTAL[1],
            shader::SPATIAL_FILTER_VERTICAL[0],
            shader::SPATIAL_FILTER_VERTICAL[1],
        ] {
            let module = pass.validate().unwrap();
            let constant = |name| shader::u32_constant(&module, name);
            assert_eq!(constant("MAX_RADIUS"), Some(MAX_SPATIAL_RADIUS));
            assert_eq!(
                constant("DEPTH_GAUSSIAN"),
                Some(DepthWeight::Gaussian as u32)
            );
            assert_eq!(
                constant("DEPTH_THRESHOLD"),
                Some(DepthWeight::Threshold as u32)
            );
        }
        assert_eq!(
            shader::SPATIAL_FILTER_HORIZONTAL[0].workgroup_size(),
            Ok([64, 1, 1])
        );
        assert_eq!(
            shader::SPATIAL_FILTER_VERTICAL[0].workgroup_size(),
            Ok([4, 64, 1])
        );
    }

    /// One synthetic frame, row by row: AO, linear depth (0: sky) and view-space normals.
    pub(crate) struct Image {
        pub ao: Vec<f32>,
        pub depth: Vec<f32>,
        pub normals: Vec<Vec3>,
    }

    /// A value in [0, 1) that looks random from pixel to pixel.
    pub(crate) fn hash(x: u32, y: u32) -> f32 {
        let h =
            (x.wrapping_mul(73_856_093) ^ y.wrapping_mul(19_349_663)).wrapping_mul(2_654_435_761);
        (h >> 8) as f32 / (1u32 << 24) as f32
    }

    /// Sky in the top 10 rows and a 3x3 hole; below, a near plane (depth about 2, facing the
    /// eye) left of `STEP_X` and a slanted far one (depth 6 to 8) right of it, with AO from
    /// `ao(near, x, y)`.
    pub(crate) fn image(ao: impl Fn(bool, u32, u32) -> f32) -> Image {
        let mut image = Image {
            ao: Vec::new(),
            depth: Vec::new(),
            normals: Vec::new(),
        };
        for y in 0..SIZE[1] {
            for x in 0..SIZE[0] {
                let sky = y < 10 || ((60..63).contains(&x) && (30..33).contains(&y));
                let near = x < STEP_X;
                let (depth, normal) = match (sky, near) {
                    (true, _) => (0.0, Vec3::Z),
                    (false, true) => (2.0 + 0.002 * y as f32, Vec3::Z),
                    (false, false) => (6.0 + 0.03 * x as f32, Vec3::new(0.6, 0.0, 0.8)),
                };
                image.depth.push(depth);
                image.ao.push(if sky { 1.0 } else { ao(near, x, y) });
                image.normals.push(normal);
            }
        }
        image
    }

    /// `image` on the GPU, with an intermediate and an output texture for a filter's two
    /// passes to write.
    pub(crate) struct Textures {
        pub ao: wgpu::TextureView,
        pub depth: wgpu::TextureView,
        pub normals: wgpu::TextureView,
        pub packed: wgpu::TextureView,
        pub output: wgpu::TextureView,
    }

    /// Runs `encode` on `image`'s textures at `SIZE` and reads back the output.
    pub(crate) fn run_filter(
        gpu: &GpuContext,
        image: &Image,
        encode: impl FnOnce(&mut PassContext<'_>, &Textures),
    ) -> Vec<f32> {
        let (device, queue) = (&gpu.device, &gpu.queue);
        let upload = |label, format, bytes: &[u8]| {
            upload_texture_2d(device, queue, label, SIZE, format, bytes)
                .unwrap()
                .create_view(&Default::default())
        };
        let packed_normals: Vec<u32> = image.normals.iter().map(|&n| pack_oct32(n)).collect();
        let usage = wgpu::TextureUsages::STORAGE_BINDING
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC;
        let output = create_texture_2d(device, "output", SIZE, AO_FORMAT, usage);
        let pair = PairFormat::of(device);
        let textures = Textures {
            ao: upload(
                "ao",
                wgpu::TextureFormat::R32Float,
                bytemuck::cast_slice(&image.ao),
            ),
            depth: upload(
                "depth",
                wgpu::TextureFormat::R32Float,
                bytemuck::cast_slice(&image.depth),
            ),
            normals: upload(
                "normals",
                wgpu::TextureFormat::R32Uint,
                bytemuck::cast_slice(&packed_normals),
            ),
            packed: create_texture_2d(device, "packed", SIZE, pair.texture_format(), usage)
                .create_view(&Default::default()),
            output: output.create_view(&Default::default()),
        };
        let view_uniforms = create_uniform_buffer::<ViewUniforms>(device, "view");
        let projection = Projection::perspective(1.0, SIZE[0] as f32 / SIZE[1] as f32, 0.1, None);
        queue.write_buffer(
            &view_uniforms,
            0,
            bytemuck::bytes_of(&ViewUniforms::new(&projection, SIZE, 0)),
        );
        let mut encoder = device.create_command_encoder(&Default::default());
        encode(
            &mut PassContext {
                device,
                encoder: &mut encoder,
                view_uniforms: &view_uniforms,
                size: SIZE,
                timer: None,
            },
            &textures,
        );
        queue.submit([encoder.finish()]);
        read_texture_f32(device, queue, &output).unwrap()
    }

    /// The filtered AO of `image`, from both passes on the GPU.
    fn filter(gpu: &GpuContext, settings: &SpatialSettings, image: &Image) -> Vec<f32> {
        let pair = PairFormat::of(&gpu.device);
        let pass = SpatialFilterPass::new(&gpu.device, &gpu.queue, settings, pair);
        run_filter(gpu, image, |ctx, t| {
            let output = SpatialOutput::Ao(&t.output);
            pass.encode(ctx, &t.ao, &t.depth, &t.normals, &t.packed, output);
        })
    }

    /// The extremes of the kernel: radius 1 and 8, both depth weights, with a normal weight.
    fn settings() -> Vec<SpatialSettings> {
        let base = SpatialSettings {
            enabled: true,
            kind: SpatialKind::Bilateral,
            ..SpatialSettings::default()
        };
        vec![
            SpatialSettings { radius: 1, ..base },
            SpatialSettings {
                radius: 8,
                sigma: 4.0,
                ..base
            },
            SpatialSettings {
                radius: 8,
                sigma: 4.0,
                depth_weight: DepthWeight::Threshold,
                ..base
            },
            SpatialSettings {
                radius: 8,
                normal_power: 4.0,
                ..base
            },
        ]
    }

    pub(crate) fn gpu() -> GpuContext {
        GpuContext::headless()
            .expect("tests need a wgpu adapter (apt-get install mesa-vulkan-drivers)")
    }

    pub(crate) fn standard_deviation(values: impl Iterator<Item = f32> + Clone) -> f32 {
        let n = values.clone().count() as f32;
        let mean = values.clone().sum::<f32>() / n;
        (values.map(|v| (v - mean) * (v - mean)).sum::<f32>() / n).sqrt()
    }

    #[test]
    fn the_packed_output_holds_the_same_ao_and_the_depth() {
        let gpu = gpu();
        let noisy = image(|near, x, y| if near { 0.2 } else { 0.7 } + 0.1 * hash(x, y));
        let pair = PairFormat::of(&gpu.device);
        let usage = wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC;
        for settings in settings() {
            let ao = filter(&gpu, &settings, &noisy);
            let pass = SpatialFilterPass::new(&gpu.device, &gpu.queue, &settings, pair);
            let packed = create_texture_2d(&gpu.device, "out", SIZE, pair.texture_format(), usage);
            let packed_view = packed.create_view(&Default::default());
            run_filter(&gpu, &noisy, |ctx, t| {
                let output = SpatialOutput::AoAndDepth(&packed_view);
                pass.encode(ctx, &t.ao, &t.depth, &t.normals, &t.packed, output);
            });
            let bytes = read_texture(&gpu.device, &gpu.queue, &packed).unwrap();
            let texels: &[f32] = bytemuck::cast_slice(&bytes);
            let channels = texels.len() / ao.len();
            for (i, texel) in texels.chunks(channels).enumerate() {
                assert_eq!(texel[0], ao[i], "{settings:?}: AO of pixel {i}");
                assert_eq!(texel[1], noisy.depth[i], "{settings:?}: depth of pixel {i}");
            }
        }
    }

    #[test]
    fn a_depth_step_is_not_blurred_across_and_sky_stays_one() {
        let gpu = gpu();
        let noisy = image(|near, x, y| if near { 0.2 } else { 0.7 } + 0.1 * hash(x, y));
        for settings in settings() {
            let filtered = filter(&gpu, &settings, &noisy);
            let mut sides = [Vec::new(), Vec::new()];
            for (i, &ao) in filtered.iter().enumerate() {
                let near = (i as u32 % SIZE[0]) < STEP_X;
                if noisy.depth[i] == 0.0 {
                    assert_eq!(ao, 1.0, "{settings:?}: sky pixel {i}");
                    continue;
                }
                let low = if near { 0.2 } else { 0.7 };
                assert!(
                    (low - 1e-6..=low + 0.1 + 1e-6).contains(&ao),
                    "{settings:?}: pixel {i} on the {} side reads {ao}",
                    if near { "near" } else { "far" }
                );
                sides[usize::from(near)].push((ao, noisy.ao[i]));
            }
            // And it does blur: each side is smoother than it was.
            for side in &sides {
                let after = standard_deviation(side.iter().map(|v| v.0));
                let before = standard_deviation(side.iter().map(|v| v.1));
                assert!(after < 0.7 * before, "{settings:?}: {before} -> {after}");
            }
        }
    }

    #[test]
    fn constant_ao_stays_constant() {
        let gpu = gpu();
        let flat = image(|_, _, _| 0.37);
        for settings in settings() {
            for (i, &ao) in filter(&gpu, &settings, &flat).iter().enumerate() {
                let expected = if flat.depth[i] == 0.0 { 1.0 } else { 0.37 };
                assert!(
                    (ao - expected).abs() < 1e-6,
                    "{settings:?}: pixel {i} reads {ao}"
                );
            }
        }
    }
}
