//! The temporal filter: blends each pixel's AO with its reprojected history (see
//! `shaders/filter/temporal_filter.wgsl`), and the per-view history it keeps.

use glam::Mat4;

use crate::gpu::{PairFormat, create_texture_2d, create_uniform_buffer, stand_in_view};
use crate::passes::kernel::method::AO_FORMAT;
use crate::passes::{ComputeKernel, PassContext, bind};
use crate::projection::Projection;
use crate::settings::TemporalSettings;
use crate::shader;
use crate::uniforms::TemporalUniforms;

/// Format of the motion vectors a renderer may hand in: pixels from a pixel to where its surface
/// was in the previous frame.
pub const MOTION_VECTOR_FORMATS: [wgpu::TextureFormat; 2] = [
    wgpu::TextureFormat::Rg16Float,
    wgpu::TextureFormat::Rg32Float,
];

/// One view's history: last frame's filtered AO and depth, and the camera that saw them.
/// [`TemporalFilterPass::encode`] makes it on the first frame.
pub struct History {
    size: [u32; 2],
    /// Ping-pong pair: one is read while the other is written.
    textures: [(wgpu::Texture, wgpu::TextureView); 2],
    /// Which of `textures` holds the last frame.
    latest: usize,
    /// The camera of the last frame, `None` until a frame was filtered.
    camera: Option<(Mat4, Projection)>,
    /// Filtered AO of the last frame, `R32Float`.
    output: (wgpu::Texture, wgpu::TextureView),
    /// 1 where the last frame rejected its history, `R32Float`.
    rejected: (wgpu::Texture, wgpu::TextureView),
}

impl History {
    /// The history holds AO and linear depth in `pair`, full precision so depth comparisons
    /// after many frames still tell surfaces apart.
    fn new(device: &wgpu::Device, size: [u32; 2], pair: PairFormat) -> Self {
        let usage = wgpu::TextureUsages::STORAGE_BINDING
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC;
        let make = |label, format| {
            let texture = create_texture_2d(device, label, size, format, usage);
            let view = texture.create_view(&Default::default());
            (texture, view)
        };
        Self {
            size,
            textures: [
                make("aokit history a", pair.texture_format()),
                make("aokit history b", pair.texture_format()),
            ],
            latest: 0,
            camera: None,
            output: make("aokit temporal ao", AO_FORMAT),
            rejected: make("aokit history rejected", AO_FORMAT),
        }
    }

    /// The filtered AO, `R32Float`, valid after [`TemporalFilterPass::encode`] ran.
    pub fn ao(&self) -> &(wgpu::Texture, wgpu::TextureView) {
        &self.output
    }

    /// Where the last frame rejected its history (1) or used it (0), `R32Float`. See
    /// [`History`] for an example.
    pub fn rejected(&self) -> &(wgpu::Texture, wgpu::TextureView) {
        &self.rejected
    }
}

/// The camera and motion of one frame, as the temporal filter needs them.
pub struct FrameMotion<'a> {
    /// World-to-view transform of this frame.
    pub view_from_world: Mat4,
    /// Projection of this frame.
    pub projection: Projection,
    /// Per-pixel motion to the previous frame, when the renderer has it, and where the frame's
    /// pixel (0, 0) lies in it (a guard band's width, or 0).
    pub motion_vectors: Option<(&'a wgpu::TextureView, u32)>,
    /// Start over: the history shows something else (a camera cut, a teleport).
    pub reset: bool,
}

/// The current frame's AO and linear depth, as the temporal filter reads them.
#[derive(Clone, Copy, Debug)]
pub enum TemporalInput<'a> {
    /// The AO (`R32Float`) and the linear depth (`R32Float`) in two textures.
    Separate {
        /// The AO.
        ao: &'a wgpu::TextureView,
        /// The linear depth.
        linear_depth: &'a wgpu::TextureView,
    },
    /// Both in one texture of the pass's [`PairFormat`], AO in r and depth in g, as the spatial
    /// filter writes them for it (`SpatialOutput::AoAndDepth`): 10 loads a pixel, not 19.
    ///
    /// [`PairFormat`]: crate::gpu::PairFormat
    Packed(&'a wgpu::TextureView),
}

/// The bindings of `shader::TEMPORAL_FILTER[pair as usize]`.
pub(crate) fn layout(pair: PairFormat) -> [wgpu::BindGroupLayoutEntry; 10] {
    let float = wgpu::TextureSampleType::Float { filterable: false };
    [
        bind::uniform(0),
        bind::uniform(1),
        bind::texture(2, float),
        bind::texture(3, float),
        bind::texture(4, float),
        bind::texture(5, float),
        bind::sampler(6, wgpu::SamplerBindingType::NonFiltering),
        bind::storage_texture(7, AO_FORMAT),
        bind::storage_texture(8, pair.texture_format()),
        bind::storage_texture(9, AO_FORMAT),
    ]
}

/// Runs the temporal filter.
pub struct TemporalFilterPass {
    settings: TemporalSettings,
    /// For [`TemporalInput::Separate`] and [`TemporalInput::Packed`].
    kernels: [ComputeKernel; 2],
    uniforms: wgpu::Buffer,
    point_clamp: wgpu::Sampler,
    /// Bound in place of motion vectors when there are none: never read.
    motion_placeholder: wgpu::TextureView,
    /// The format of the histories.
    pair: PairFormat,
}

impl TemporalFilterPass {
    /// Compiles the kernel for each [`TemporalInput`], for histories in `pair`.
    pub fn new(device: &wgpu::Device, settings: &TemporalSettings, pair: PairFormat) -> Self {
        let layout = layout(pair);
        let kernel = |packed: bool| {
            ComputeKernel::with_constants(
                device,
                &shader::TEMPORAL_FILTER[pair as usize],
                &layout,
                &[("PACKED_INPUT", f64::from(u8::from(packed)))],
            )
        };
        Self {
            settings: *settings,
            kernels: [kernel(false), kernel(true)],
            uniforms: create_uniform_buffer::<TemporalUniforms>(device, "aokit temporal settings"),
            point_clamp: crate::gpu::create_point_clamp_sampler(
                device,
                "aokit temporal point clamp",
            ),
            motion_placeholder: stand_in_view(
                device,
                "aokit motion placeholder",
                MOTION_VECTOR_FORMATS[0],
                wgpu::TextureUsages::TEXTURE_BINDING,
            ),
            pair,
        }
    }

    /// Settings for later frames.
    pub fn set_settings(&mut self, settings: &TemporalSettings) {
        self.settings = *settings;
    }

    /// Filters `input` into `history` (made or remade when missing or of another size), using
    /// and then replacing the history's previous frame.
    pub fn encode(
        &self,
        ctx: &mut PassContext<'_>,
        queue: &wgpu::Queue,
        history: &mut Option<History>,
        frame: &FrameMotion<'_>,
        input: TemporalInput<'_>,
    ) {
        if history.as_ref().map(|h| h.size) != Some(ctx.size) {
            *history = Some(History::new(ctx.device, ctx.size, self.pair));
        }
        let history = history.as_mut().expect("history was just made");
        let previous = history.camera.filter(|_| !frame.reset);
        let uniforms = TemporalUniforms::new(
            &self.settings,
            previous.map(|(view, projection)| {
                (prev_view_from_view(view, frame.view_from_world), projection)
            }),
            frame.motion_vectors.map(|(_, offset)| offset),
        );
        queue.write_buffer(&self.uniforms, 0, bytemuck::bytes_of(&uniforms));
        let (read, write) = (history.latest, 1 - history.latest);
        // Packed, the depth binding is not read: the packed texture stands in for it.
        let (kernel, ao, linear_depth) = match input {
            TemporalInput::Separate { ao, linear_depth } => (&self.kernels[0], ao, linear_depth),
            TemporalInput::Packed(packed) => (&self.kernels[1], packed, packed),
        };
        ctx.dispatch(
            kernel,
            &[
                self.uniforms.as_entire_binding(),
                wgpu::BindingResource::TextureView(ao),
                wgpu::BindingResource::TextureView(linear_depth),
                wgpu::BindingResource::TextureView(&history.textures[read].1),
                wgpu::BindingResource::TextureView(
                    frame
                        .motion_vectors
                        .map_or(&self.motion_placeholder, |(view, _)| view),
                ),
                wgpu::BindingResource::Sampler(&self.point_clamp),
                wgpu::BindingResource::TextureView(&history.output.1),
                wgpu::BindingResource::TextureView(&history.textures[write].1),
                wgpu::BindingResource::TextureView(&history.rejected.1),
            ],
        );
        history.latest = write;
        history.camera = Some((frame.view_from_world, frame.projection));
    }
}

/// The transform from this frame's view space to the previous frame's, in double precision:
/// the two world transforms nearly cancel for a slow camera, and `f32` would leave their
/// rounding as motion.
fn prev_view_from_view(previous_view_from_world: Mat4, view_from_world: Mat4) -> Mat4 {
    (previous_view_from_world.as_dmat4() * view_from_world.as_dmat4().inverse()).as_mat4()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gpu::{read_texture_f32, upload_texture_2d};
    use crate::passes::filter::spatial_filter::tests::{Image, SIZE, gpu, hash, image};
    use crate::uniforms::ViewUniforms;
    use glam::Vec3;

    /// The spatial filter's test image with noise that changes every frame.
    fn frame_image(frame: u32) -> Image {
        image(|near, x, y| (if near { 0.3 } else { 0.6 }) + 0.2 * hash(x + 7 * frame, y))
    }

    /// Three frames of a camera sliding sideways over the spatial filter's test image with fresh
    /// noise each frame, filtered from what `upload` makes of each frame's AO and depth: one
    /// texture and, for separate input, the depth's. The AO each frame wrote.
    fn filter_frames(
        gpu: &crate::GpuContext,
        upload: impl Fn(&[f32], &[f32]) -> (wgpu::TextureView, Option<wgpu::TextureView>),
    ) -> Vec<Vec<f32>> {
        let (device, queue) = (&gpu.device, &gpu.queue);
        let pass =
            TemporalFilterPass::new(device, &TemporalSettings::default(), PairFormat::of(device));
        let projection = Projection::perspective(1.0, SIZE[0] as f32 / SIZE[1] as f32, 0.1, None);
        let view_uniforms = create_uniform_buffer::<ViewUniforms>(device, "view");
        let mut history = None;
        let mut frames = Vec::new();
        for frame in 0..3u32 {
            let noisy = frame_image(frame);
            let (ao, depth) = upload(&noisy.ao, &noisy.depth);
            let eye = Vec3::new(0.05 * frame as f32, 0.0, 0.0);
            let view_from_world = glam::camera::rh::view::look_to_mat4(eye, Vec3::NEG_Z, Vec3::Y);
            queue.write_buffer(
                &view_uniforms,
                0,
                bytemuck::bytes_of(&ViewUniforms::new(&projection, SIZE, frame)),
            );
            let mut encoder = device.create_command_encoder(&Default::default());
            let input = match &depth {
                None => TemporalInput::Packed(&ao),
                Some(linear_depth) => TemporalInput::Separate {
                    ao: &ao,
                    linear_depth,
                },
            };
            pass.encode(
                &mut PassContext {
                    device,
                    encoder: &mut encoder,
                    view_uniforms: &view_uniforms,
                    size: SIZE,
                    timer: None,
                },
                queue,
                &mut history,
                &FrameMotion {
                    view_from_world,
                    projection,
                    motion_vectors: None,
                    reset: false,
                },
                input,
            );
            queue.submit([encoder.finish()]);
            let filtered = &history.as_ref().unwrap().ao().0;
            frames.push(read_texture_f32(device, queue, filtered).unwrap());
        }
        frames
    }

    #[test]
    fn packed_and_separate_inputs_filter_alike() {
        let gpu = gpu();
        let (device, queue) = (&gpu.device, &gpu.queue);
        let upload = |label, format, texels: &[f32]| {
            let bytes = bytemuck::cast_slice(texels);
            upload_texture_2d(device, queue, label, SIZE, format, bytes)
                .unwrap()
                .create_view(&Default::default())
        };
        let r32 = wgpu::TextureFormat::R32Float;
        let separate = filter_frames(&gpu, |ao, depth| {
            (upload("ao", r32, ao), Some(upload("depth", r32, depth)))
        });
        let pair = PairFormat::of(device).texture_format();
        let channels = (pair.block_copy_size(None).unwrap() / 4) as usize;
        let packed = filter_frames(&gpu, |ao, depth| {
            let mut texels = vec![0.0; ao.len() * channels];
            for (i, texel) in texels.chunks_mut(channels).enumerate() {
                (texel[0], texel[1]) = (ao[i], depth[i]);
            }
            (upload("packed", pair, &texels), None)
        });
        assert_eq!(separate, packed);
        // The history did take part: later frames are not the current frame's AO alone.
        let current = frame_image(2).ao;
        assert!(separate[2].iter().zip(&current).any(|(a, b)| a != b));
    }

    #[test]
    fn a_still_camera_maps_view_space_to_itself() {
        let view =
            glam::camera::rh::view::look_at_mat4(Vec3::new(3.0, 2.0, 9.0), Vec3::ZERO, Vec3::Y);
        let m = prev_view_from_view(view, view);
        assert!(m.abs_diff_eq(Mat4::IDENTITY, 1e-6), "{m}");
        let moved =
            glam::camera::rh::view::look_at_mat4(Vec3::new(3.5, 2.0, 9.0), Vec3::ZERO, Vec3::Y);
        let p = Vec3::new(0.2, -0.1, -8.0);
        let world = view.inverse().transform_point3(p);
        let expected = moved.transform_point3(world);
        let got = prev_view_from_view(moved, view).transform_point3(p);
        assert!((got - expected).length() < 1e-4, "{got} vs {expected}");
    }
}
