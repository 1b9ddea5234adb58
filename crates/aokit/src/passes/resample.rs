//! Between the input's resolution and the working resolution (`shaders/resample/downsample.wgsl`
//! and `shaders/resample/upsample.wgsl`; formulas and measurements in docs/denoise.md): linear
//! depth, normals and motion vectors down to the working resolution by choosing one pixel per
//! block, and AO and bent normals back up guided by the full-resolution depth.

use std::collections::HashMap;

use crate::gpu::{PairFormat, create_uniform_buffer, stand_in_view};
use crate::passes::filter::temporal_filter::MOTION_VECTOR_FORMATS;
use crate::passes::input::linear_depth::{DepthInput, LINEAR_DEPTH_FORMAT};
use crate::passes::input::normals_from_depth::NORMALS_FORMAT;
use crate::passes::kernel::method::{AO_FORMAT, BENT_NORMALS_FORMAT};
use crate::passes::{ComputeKernel, PassContext, bind};
use crate::settings::{AoSettings, Downsample, Upsample};
use crate::shader;
use crate::uniforms::UpsampleUniforms;

/// Where the downsample writes, at working resolution. See [`ResamplePass::downsample`].
pub struct DownsampleTargets<'a> {
    /// Linear depth ([`LINEAR_DEPTH_FORMAT`]).
    pub linear_depth: &'a wgpu::TextureView,
    /// oct32 normals ([`NORMALS_FORMAT`]) of the pixels the depth came from.
    pub normals: &'a wgpu::TextureView,
    /// Motion vectors (the pass's [`PairFormat`]: offsets in working texels, full precision as
    /// the temporal filter's history is) of those pixels, when the temporal filter runs at
    /// working resolution with motion vectors.
    pub motion_vectors: Option<&'a wgpu::TextureView>,
}

/// What a frame's resampling reads and writes besides depth, normals and AO.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ResampleFrame {
    /// The kind of the full-resolution depth both passes read: the renderer's own, or the
    /// linear depth pass's output ([`DepthInput::Linear`]) where that pass ran.
    pub input: DepthInput,
    /// The downsample writes motion vectors.
    pub motion_vectors: bool,
    /// The upsample reads and writes bent normals.
    pub bent_normals: bool,
    /// The upsample writes the full-resolution linear depth, which no pass before it wrote.
    pub write_linear_depth: bool,
}

/// What the downsample compiles in (the shader's `override`s, one kernel per combination):
/// input kind, mode, scale, motion vectors.
type DownsampleKey = (DepthInput, Downsample, u32, bool);
/// What the upsample compiles in: input kind, mode, scale, bent normals, linear depth written.
type UpsampleKey = (DepthInput, Upsample, u32, bool, bool);

/// The bindings of `shader::DOWNSAMPLE[pair as usize][input as usize]`: view uniforms, the
/// depth, normals and motion vectors in, then out.
pub(crate) fn downsample_layout(
    pair: PairFormat,
    input: DepthInput,
) -> [wgpu::BindGroupLayoutEntry; 7] {
    [
        bind::uniform(0),
        input.layout_entry(1),
        bind::texture(2, wgpu::TextureSampleType::Uint),
        bind::texture(3, wgpu::TextureSampleType::Float { filterable: false }),
        bind::storage_texture(4, LINEAR_DEPTH_FORMAT),
        bind::storage_texture(5, NORMALS_FORMAT),
        bind::storage_texture(6, pair.texture_format()),
    ]
}

/// The bindings of `shader::UPSAMPLE[input as usize]`.
pub(crate) fn upsample_layout(input: DepthInput) -> [wgpu::BindGroupLayoutEntry; 11] {
    let float = wgpu::TextureSampleType::Float { filterable: false };
    [
        bind::uniform(0),
        input.layout_entry(1),
        bind::uniform(2),
        bind::texture(3, wgpu::TextureSampleType::Uint),
        bind::texture(4, float),
        bind::texture(5, float),
        bind::texture(6, float),
        bind::storage_texture(7, AO_FORMAT),
        bind::storage_texture(8, BENT_NORMALS_FORMAT),
        bind::sampler(9, wgpu::SamplerBindingType::NonFiltering),
        bind::storage_texture(10, LINEAR_DEPTH_FORMAT),
    ]
}

/// The downsample and upsample kernels and the upsample's settings buffer.
///
/// A half-resolution frame: down, the AO kernel at the working size, and up again.
pub struct ResamplePass {
    /// Each compiled the first time a frame asks for it.
    downsamples: HashMap<DownsampleKey, ComputeKernel>,
    upsamples: HashMap<UpsampleKey, ComputeKernel>,
    /// The kernels of the frame being recorded, set by [`ResamplePass::prepare`].
    current: Option<(DownsampleKey, UpsampleKey)>,
    uniforms: wgpu::Buffer,
    /// The upsample gathers the working texels through it.
    point_clamp: wgpu::Sampler,
    /// 1x1 textures bound in place of motion vectors, bent normals and linear depth that a
    /// frame does not have: the kernels compiled for that frame do not touch them.
    motion_in_placeholder: wgpu::TextureView,
    motion_out_placeholder: wgpu::TextureView,
    bent_in_placeholder: wgpu::TextureView,
    bent_out_placeholder: wgpu::TextureView,
    linear_out_placeholder: wgpu::TextureView,
    /// The format of the downsampled motion vectors.
    pair: PairFormat,
}

impl ResamplePass {
    /// Creates the buffers; the kernels compile as frames ask for them. The downsampled motion
    /// vectors are written in `pair`.
    pub fn new(device: &wgpu::Device, pair: PairFormat) -> Self {
        let placeholder = |label, format, usage| stand_in_view(device, label, format, usage);
        let read = wgpu::TextureUsages::TEXTURE_BINDING;
        let write = wgpu::TextureUsages::STORAGE_BINDING;
        Self {
            downsamples: HashMap::new(),
            upsamples: HashMap::new(),
            current: None,
            uniforms: create_uniform_buffer::<UpsampleUniforms>(device, "aokit upsample settings"),
            point_clamp: crate::gpu::create_point_clamp_sampler(
                device,
                "aokit upsample point clamp",
            ),
            motion_in_placeholder: placeholder(
                "aokit motion placeholder",
                MOTION_VECTOR_FORMATS[0],
                read,
            ),
            motion_out_placeholder: placeholder(
                "aokit working motion placeholder",
                pair.texture_format(),
                write,
            ),
            bent_in_placeholder: placeholder(
                "aokit bent normals placeholder",
                BENT_NORMALS_FORMAT,
                read,
            ),
            bent_out_placeholder: placeholder(
                "aokit upsampled bent normals placeholder",
                BENT_NORMALS_FORMAT,
                write,
            ),
            linear_out_placeholder: placeholder(
                "aokit full-resolution linear depth placeholder",
                LINEAR_DEPTH_FORMAT,
                write,
            ),
            pair,
        }
    }

    /// Compiles the kernels of the frame about to be recorded where they are new, and uploads
    /// the upsample's settings. The views given to the passes must agree with `frame`. Both
    /// passes of a frame use what the last call set (a second upload before the submit would
    /// replace the first).
    pub fn prepare(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        settings: &AoSettings,
        frame: ResampleFrame,
    ) {
        let scale = settings.resolution.scale();
        let down = (
            frame.input,
            settings.downsample,
            scale,
            frame.motion_vectors,
        );
        let up = (
            frame.input,
            settings.upsample,
            scale,
            frame.bent_normals,
            frame.write_linear_depth,
        );
        let scale_constant = ("SCALE", f64::from(scale));
        let flag = |on: bool| f64::from(u8::from(on));
        self.downsamples.entry(down).or_insert_with(|| {
            ComputeKernel::with_constants(
                device,
                &shader::DOWNSAMPLE[self.pair as usize][frame.input as usize],
                &downsample_layout(self.pair, frame.input),
                &[
                    ("MODE", f64::from(settings.downsample as u32)),
                    scale_constant,
                    ("MOTION_VECTORS", flag(frame.motion_vectors)),
                ],
            )
        });
        self.upsamples.entry(up).or_insert_with(|| {
            ComputeKernel::with_constants(
                device,
                &shader::UPSAMPLE[frame.input as usize],
                &upsample_layout(frame.input),
                &[
                    ("MODE", f64::from(settings.upsample as u32)),
                    scale_constant,
                    ("BENT_NORMALS", flag(frame.bent_normals)),
                    ("WRITE_LINEAR_DEPTH", flag(frame.write_linear_depth)),
                ],
            )
        });
        self.current = Some((down, up));
        queue.write_buffer(
            &self.uniforms,
            0,
            bytemuck::bytes_of(&UpsampleUniforms::new(settings)),
        );
    }

    /// Records the downsample of the full-resolution `depth` (of the prepared frame's
    /// [`ResampleFrame::input`] kind), oct32 `normals` and `motion_vectors` (pixels, as
    /// [`AoInputs::motion_vectors`](crate::AoInputs::motion_vectors)) into `targets`; `ctx` is
    /// at working resolution.
    pub fn downsample(
        &self,
        ctx: &mut PassContext<'_>,
        depth: &wgpu::TextureView,
        normals: &wgpu::TextureView,
        motion_vectors: Option<&wgpu::TextureView>,
        targets: &DownsampleTargets<'_>,
    ) {
        let view = wgpu::BindingResource::TextureView;
        ctx.dispatch(
            &self.downsamples[&self.current.expect("prepare comes first").0],
            &[
                view(depth),
                view(normals),
                view(motion_vectors.unwrap_or(&self.motion_in_placeholder)),
                view(targets.linear_depth),
                view(targets.normals),
                view(
                    targets
                        .motion_vectors
                        .unwrap_or(&self.motion_out_placeholder),
                ),
            ],
        );
    }

    /// Records the upsample of working-resolution `ao` into `output`, and of bent normals
    /// (working, full) when given, comparing the full-resolution `depth` (of the prepared
    /// frame's [`ResampleFrame::input`] kind) with `working_depth`, the downsample's; `ctx` is
    /// at full resolution. `normals`, oct32 at full resolution, are the bent normals of pixels
    /// no working texel saw. `linear_depth` receives the full-resolution linear depth when the
    /// frame was prepared with [`ResampleFrame::write_linear_depth`].
    #[allow(clippy::too_many_arguments)]
    pub fn upsample(
        &self,
        ctx: &mut PassContext<'_>,
        depth: &wgpu::TextureView,
        normals: &wgpu::TextureView,
        working_depth: &wgpu::TextureView,
        ao: &wgpu::TextureView,
        output: &wgpu::TextureView,
        bent_normals: Option<(&wgpu::TextureView, &wgpu::TextureView)>,
        linear_depth: Option<&wgpu::TextureView>,
    ) {
        let (bent_in, bent_out) =
            bent_normals.unwrap_or((&self.bent_in_placeholder, &self.bent_out_placeholder));
        let key = self.current.expect("prepare comes first").1;
        let view = wgpu::BindingResource::TextureView;
        ctx.dispatch(
            &self.upsamples[&key],
            &[
                view(depth),
                self.uniforms.as_entire_binding(),
                view(normals),
                view(working_depth),
                view(ao),
                view(bent_in),
                view(output),
                view(bent_out),
                wgpu::BindingResource::Sampler(&self.point_clamp),
                view(linear_depth.unwrap_or(&self.linear_out_placeholder)),
            ],
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gpu::{
        create_texture_2d, f32_to_f16, read_texture, read_texture_rgba16f, upload_texture_2d,
    };
    use crate::normals::pack_oct32;
    use crate::settings::{Downsample, Resolution, Upsample};
    use crate::uniforms::ViewUniforms;
    use crate::{GpuContext, Projection};
    use glam::Vec3;

    /// Odd on both sides at both scales, so the last blocks hang over the image's edge.
    const SIZE: [u32; 2] = [37, 23];

    fn gpu() -> GpuContext {
        GpuContext::headless()
            .expect("tests need a wgpu adapter (apt-get install mesa-vulkan-drivers)")
    }

    /// A value in [0, 1) that looks random from pixel to pixel.
    fn hash(x: u32, y: u32) -> f32 {
        let h =
            (x.wrapping_mul(73_856_093) ^ y.wrapping_mul(19_349_663)).wrapping_mul(2_654_435_761);
        (h >> 8) as f32 / (1u32 << 24) as f32
    }

    fn settings(resolution: Resolution, downsample: Downsample, upsample: Upsample) -> AoSettings {
        AoSettings {
            resolution,
            downsample,
            upsample,
            ..AoSettings::default()
        }
    }

    /// A `ViewUniforms` buffer of `SIZE` at `scale`.
    fn view_uniforms(gpu: &GpuContext, scale: u32) -> wgpu::Buffer {
        let buffer = create_uniform_buffer::<ViewUniforms>(&gpu.device, "view");
        let projection = Projection::perspective(1.0, SIZE[0] as f32 / SIZE[1] as f32, 0.1, None);
        let uniforms = ViewUniforms::scaled(&projection, SIZE, scale, 0);
        gpu.queue
            .write_buffer(&buffer, 0, bytemuck::bytes_of(&uniforms));
        buffer
    }

    fn upload(
        gpu: &GpuContext,
        size: [u32; 2],
        format: wgpu::TextureFormat,
        bytes: &[u8],
    ) -> wgpu::Texture {
        upload_texture_2d(&gpu.device, &gpu.queue, "input", size, format, bytes).unwrap()
    }

    fn target(gpu: &GpuContext, size: [u32; 2], format: wgpu::TextureFormat) -> wgpu::Texture {
        let usage = wgpu::TextureUsages::STORAGE_BINDING
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC;
        create_texture_2d(&gpu.device, "output", size, format, usage)
    }

    fn view(texture: &wgpu::Texture) -> wgpu::TextureView {
        texture.create_view(&Default::default())
    }

    fn read<T: bytemuck::Pod>(gpu: &GpuContext, texture: &wgpu::Texture) -> Vec<T> {
        bytemuck::pod_collect_to_vec(&read_texture(&gpu.device, &gpu.queue, texture).unwrap())
    }

    /// The downsample's depth, "normals" and motion vectors of full-resolution `depth`, with
    /// each pixel's index as its normal bits and its coordinates as its motion.
    fn downsample(
        gpu: &GpuContext,
        pass: &mut ResamplePass,
        settings: &AoSettings,
        depth: &[f32],
    ) -> (Vec<f32>, Vec<u32>, Vec<[f32; 2]>) {
        let working = settings.resolution.working_size(SIZE);
        let index: Vec<u32> = (0..SIZE[0] * SIZE[1]).collect();
        let motion: Vec<[f32; 2]> = index
            .iter()
            .map(|i| [(i % SIZE[0]) as f32, (i / SIZE[0]) as f32])
            .collect();
        let inputs = [
            upload(
                gpu,
                SIZE,
                wgpu::TextureFormat::R32Float,
                bytemuck::cast_slice(depth),
            ),
            upload(gpu, SIZE, NORMALS_FORMAT, bytemuck::cast_slice(&index)),
            upload(
                gpu,
                SIZE,
                wgpu::TextureFormat::Rg32Float,
                bytemuck::cast_slice(&motion),
            ),
        ];
        let outputs = [
            target(gpu, working, LINEAR_DEPTH_FORMAT),
            target(gpu, working, NORMALS_FORMAT),
            target(gpu, working, PairFormat::Rg32Float.texture_format()),
        ];
        let views = outputs.each_ref().map(view);
        let uniforms = view_uniforms(gpu, settings.resolution.scale());
        let frame = ResampleFrame {
            input: DepthInput::Linear,
            motion_vectors: true,
            bent_normals: false,
            write_linear_depth: false,
        };
        pass.prepare(&gpu.device, &gpu.queue, settings, frame);
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        pass.downsample(
            &mut PassContext {
                device: &gpu.device,
                encoder: &mut encoder,
                view_uniforms: &uniforms,
                size: working,
                timer: None,
            },
            &view(&inputs[0]),
            &view(&inputs[1]),
            Some(&view(&inputs[2])),
            &DownsampleTargets {
                linear_depth: &views[0],
                normals: &views[1],
                motion_vectors: Some(&views[2]),
            },
        );
        gpu.queue.submit([encoder.finish()]);
        (
            read(gpu, &outputs[0]),
            read(gpu, &outputs[1]),
            read(gpu, &outputs[2]),
        )
    }

    /// The point rule along one axis of `side` pixels: working texel `c` takes the top-left
    /// pixel of its block's central 2x2, clamped to the image.
    fn point_pixel(c: u32, scale: u32, side: u32) -> u32 {
        (c * scale + scale / 2 - 1).min(side - 1)
    }

    /// The pixel the downsample should take for working texel `(x, y)`, by the definitions in
    /// docs/denoise.md: pixels of the block (clamped to the image) in row order, the first of
    /// equal depths winning.
    fn expected_pixel(depth: &[f32], mode: Downsample, scale: u32, x: u32, y: u32) -> u32 {
        let clamp = |px: u32, py: u32| px.min(SIZE[0] - 1) + py.min(SIZE[1] - 1) * SIZE[0];
        let block = (0..scale * scale).map(|i| clamp(x * scale + i % scale, y * scale + i / scale));
        // No surface (0) counts as farthest.
        let distance = |i: &u32| match depth[*i as usize] {
            0.0 => f32::INFINITY,
            d => d,
        };
        let nearest = || {
            block
                .clone()
                .reduce(|a, b| if distance(&b) < distance(&a) { b } else { a })
        };
        let farthest = || {
            block
                .clone()
                .reduce(|a, b| if distance(&b) > distance(&a) { b } else { a })
        };
        match mode {
            Downsample::Point => {
                point_pixel(x, scale, SIZE[0]) + point_pixel(y, scale, SIZE[1]) * SIZE[0]
            }
            Downsample::Min => nearest().unwrap(),
            Downsample::Max => farthest().unwrap(),
            Downsample::Checkerboard if (x + y).is_multiple_of(2) => nearest().unwrap(),
            Downsample::Checkerboard => farthest().unwrap(),
        }
    }

    #[test]
    fn each_downsample_takes_the_pixel_it_names_with_its_normal_and_motion() {
        let gpu = gpu();
        let mut pass = ResamplePass::new(&gpu.device, PairFormat::Rg32Float);
        // Random depths, a few repeated (ties), and sky in a sprinkling of pixels and in whole
        // blocks of the top rows.
        let depth: Vec<f32> = (0..SIZE[0] * SIZE[1])
            .map(|i| {
                let (x, y) = (i % SIZE[0], i / SIZE[0]);
                let h = hash(x, y);
                if (y < 4 && x < 8) || h < 0.1 {
                    0.0
                } else {
                    1.0 + (8.0 * h).floor()
                }
            })
            .collect();
        for resolution in [Resolution::Half, Resolution::Quarter] {
            let scale = resolution.scale();
            let working = resolution.working_size(SIZE);
            for mode in Downsample::ALL {
                let s = settings(resolution, mode, Upsample::default());
                let (depths, pixels, motion) = downsample(&gpu, &mut pass, &s, &depth);
                for y in 0..working[1] {
                    for x in 0..working[0] {
                        let i = (x + y * working[0]) as usize;
                        let want = expected_pixel(&depth, mode, scale, x, y);
                        let at = format!("{} {} texel ({x}, {y})", resolution.name(), mode.name());
                        assert_eq!(pixels[i], want, "{at}: normal");
                        assert_eq!(depths[i], depth[want as usize], "{at}: depth");
                        let xy = [(want % SIZE[0]) as f32, (want / SIZE[0]) as f32];
                        assert_eq!(motion[i], xy.map(|v| v / scale as f32), "{at}: motion");
                    }
                }
            }
        }
    }

    /// Sky in the top 3 rows, but for the pixel `LOST`; below, a near plane (depth about 2)
    /// left of column `STEP_X`, a far one (depth about 6) right of it, both slightly slanted.
    const STEP_X: u32 = 13;
    /// A surface pixel in the sky that no working texel takes at either scale (a pole thinner
    /// than a block), facing up.
    const LOST: (u32, u32) = (21, 0);

    /// Where `step_depth` shows a surface and which: no surface, near, far, or `LOST`.
    #[derive(PartialEq)]
    enum Region {
        Sky,
        Near,
        Far,
        Lost,
    }

    fn region(x: u32, y: u32) -> Region {
        match (y < 3, x < STEP_X) {
            _ if (x, y) == LOST => Region::Lost,
            (true, _) => Region::Sky,
            (false, true) => Region::Near,
            (false, false) => Region::Far,
        }
    }

    fn step_depth(x: u32, y: u32) -> f32 {
        match region(x, y) {
            Region::Sky => 0.0,
            Region::Near | Region::Lost => 2.0 + 0.01 * y as f32,
            Region::Far => 6.0 + 0.02 * x as f32,
        }
    }

    /// Upsamples working AO `ao(depth, texel)` and bent normals `(0.6, 0, 0.8, ao)` over
    /// working depth taken from `step_depth` by the point rule; returns the full-resolution AO
    /// and bent normals.
    fn upsample(
        gpu: &GpuContext,
        pass: &mut ResamplePass,
        settings: &AoSettings,
        ao: impl Fn(f32, [u32; 2]) -> f32,
    ) -> (Vec<f32>, Vec<[f32; 4]>) {
        let scale = settings.resolution.scale();
        let working = settings.resolution.working_size(SIZE);
        let full_depth: Vec<f32> = (0..SIZE[0] * SIZE[1])
            .map(|i| step_depth(i % SIZE[0], i / SIZE[0]))
            .collect();
        let normals: Vec<u32> = (0..SIZE[0] * SIZE[1])
            .map(|i| match region(i % SIZE[0], i / SIZE[0]) {
                Region::Lost => pack_oct32(Vec3::Y),
                _ => pack_oct32(Vec3::Z),
            })
            .collect();
        let working_depth: Vec<f32> = (0..working[0] * working[1])
            .map(|i| {
                step_depth(
                    point_pixel(i % working[0], scale, SIZE[0]),
                    point_pixel(i / working[0], scale, SIZE[1]),
                )
            })
            .collect();
        let working_ao: Vec<f32> = (0..working[0] * working[1])
            .map(|i| ao(working_depth[i as usize], [i % working[0], i / working[0]]))
            .collect();
        let bent: Vec<u16> = working_ao
            .iter()
            .flat_map(|&a| [0.6, 0.0, 0.8, a].map(f32_to_f16))
            .collect();
        let float = wgpu::TextureFormat::R32Float;
        let inputs = [
            upload(gpu, SIZE, float, bytemuck::cast_slice(&full_depth)),
            upload(gpu, SIZE, NORMALS_FORMAT, bytemuck::cast_slice(&normals)),
            upload(gpu, working, float, bytemuck::cast_slice(&working_depth)),
            upload(gpu, working, float, bytemuck::cast_slice(&working_ao)),
            upload(
                gpu,
                working,
                BENT_NORMALS_FORMAT,
                bytemuck::cast_slice(&bent),
            ),
        ];
        let inputs = inputs.each_ref().map(view);
        let outputs = [
            target(gpu, SIZE, AO_FORMAT),
            target(gpu, SIZE, BENT_NORMALS_FORMAT),
            target(gpu, SIZE, LINEAR_DEPTH_FORMAT),
        ];
        let uniforms = view_uniforms(gpu, 1);
        let frame = ResampleFrame {
            input: DepthInput::Linear,
            motion_vectors: false,
            bent_normals: true,
            write_linear_depth: true,
        };
        pass.prepare(&gpu.device, &gpu.queue, settings, frame);
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        pass.upsample(
            &mut PassContext {
                device: &gpu.device,
                encoder: &mut encoder,
                view_uniforms: &uniforms,
                size: SIZE,
                timer: None,
            },
            &inputs[0],
            &inputs[1],
            &inputs[2],
            &inputs[3],
            &view(&outputs[0]),
            Some((&inputs[4], &view(&outputs[1]))),
            Some(&view(&outputs[2])),
        );
        gpu.queue.submit([encoder.finish()]);
        // Where no linear depth pass ran, the upsample hands on the depth it read.
        assert_eq!(read::<f32>(gpu, &outputs[2]), full_depth);
        (
            read(gpu, &outputs[0]),
            read_texture_rgba16f(&gpu.device, &gpu.queue, &outputs[1]).unwrap(),
        )
    }

    fn every_upsample() -> impl Iterator<Item = AoSettings> {
        [Resolution::Half, Resolution::Quarter]
            .into_iter()
            .flat_map(|r| Upsample::ALL.map(|u| settings(r, Downsample::Point, u)))
    }

    #[test]
    fn upsampling_keeps_each_side_of_a_depth_step_and_sky_stays_one() {
        let gpu = gpu();
        let mut pass = ResamplePass::new(&gpu.device, PairFormat::Rg32Float);
        let near_ao = 0.2;
        let far_ao = 0.8;
        for s in every_upsample() {
            let (ao, _) = upsample(
                &gpu,
                &mut pass,
                &s,
                |d, _| if d < 4.0 { near_ao } else { far_ao },
            );
            for (i, &a) in ao.iter().enumerate() {
                let (x, y) = (i as u32 % SIZE[0], i as u32 / SIZE[0]);
                // The lost pixel: nothing was sampled there, so nothing occludes it.
                let want = match region(x, y) {
                    Region::Sky | Region::Lost => 1.0,
                    Region::Near => near_ao,
                    Region::Far => far_ao,
                };
                assert_eq!(
                    a,
                    want,
                    "{} {}: pixel ({x}, {y})",
                    s.resolution.name(),
                    s.upsample.name()
                );
            }
        }
    }

    #[test]
    fn constant_ao_and_bent_normals_upsample_to_themselves() {
        let gpu = gpu();
        let mut pass = ResamplePass::new(&gpu.device, PairFormat::Rg32Float);
        let constant = 0.37;
        for s in every_upsample() {
            let (ao, bent) = upsample(&gpu, &mut pass, &s, |_, _| constant);
            for (i, (&a, b)) in ao.iter().zip(&bent).enumerate() {
                let (x, y) = (i as u32 % SIZE[0], i as u32 / SIZE[0]);
                let at = format!(
                    "{} {}: pixel ({x}, {y})",
                    s.resolution.name(),
                    s.upsample.name()
                );
                // Half floats: about 3 decimal digits.
                let (want_ao, want_bent) = match region(x, y) {
                    Region::Sky => (1.0, [0.0, 0.0, 0.0, 1.0]),
                    Region::Lost => (1.0, [0.0, 1.0, 0.0, 1.0]),
                    Region::Near | Region::Far => (constant, [0.6, 0.0, 0.8, constant]),
                };
                assert_eq!(a, want_ao, "{at}");
                assert!(
                    b.iter().zip(want_bent).all(|(b, w)| (b - w).abs() < 2e-3),
                    "{at}: {b:?}"
                );
            }
        }
    }

    #[test]
    fn bilinear_upsampling_interpolates_between_texel_centres() {
        let gpu = gpu();
        let mut pass = ResamplePass::new(&gpu.device, PairFormat::Rg32Float);
        let gradient = |[x, y]: [u32; 2]| 0.3 + 0.01 * x as f32 + 0.005 * y as f32;
        for resolution in [Resolution::Half, Resolution::Quarter] {
            let scale = resolution.scale();
            let working = resolution.working_size(SIZE);
            let texel_region = |[x, y]: [u32; 2]| {
                region(
                    point_pixel(x, scale, SIZE[0]),
                    point_pixel(y, scale, SIZE[1]),
                )
            };
            for mode in [Upsample::BilateralBilinear, Upsample::NearestDepth] {
                let s = settings(resolution, Downsample::Point, mode);
                let (ao, _) = upsample(&gpu, &mut pass, &s, |_, texel| gradient(texel));
                let mut checked = 0;
                for (i, &a) in ao.iter().enumerate() {
                    let (x, y) = (i as u32 % SIZE[0], i as u32 / SIZE[0]);
                    // The pixel's centre in texel coordinates, between four texel centres
                    // (clamped to the image, as the shader's sampler clamps).
                    let q = [x, y].map(|c| (c as f32 + 0.5) / scale as f32 - 0.5);
                    let corner = q.map(f32::floor);
                    let f = [q[0] - corner[0], q[1] - corner[1]];
                    let texel = |dx: f32, dy: f32| {
                        [(corner[0] + dx, working[0]), (corner[1] + dy, working[1])]
                            .map(|(c, n)| c.clamp(0.0, (n - 1) as f32) as u32)
                    };
                    let texels = [
                        texel(0.0, 0.0),
                        texel(1.0, 0.0),
                        texel(0.0, 1.0),
                        texel(1.0, 1.0),
                    ];
                    let pixel_region = region(x, y);
                    if matches!(pixel_region, Region::Sky | Region::Lost)
                        || texels.iter().any(|&t| texel_region(t) != pixel_region)
                    {
                        continue;
                    }
                    let weights = [
                        (1.0 - f[0]) * (1.0 - f[1]),
                        f[0] * (1.0 - f[1]),
                        (1.0 - f[0]) * f[1],
                        f[0] * f[1],
                    ];
                    let want: f32 = texels
                        .iter()
                        .zip(weights)
                        .map(|(&t, w)| w * gradient(t))
                        .sum();
                    assert!(
                        (a - want).abs() < 1e-5,
                        "{} {}: pixel ({x}, {y}) {a} against {want}",
                        resolution.name(),
                        mode.name()
                    );
                    checked += 1;
                }
                assert!(checked > ao.len() / 2, "{checked} pixels checked");
            }
        }
    }
}
