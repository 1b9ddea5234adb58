//! The compute passes, each a plain struct with `new` and `encode`, and the helpers they share.
//!
//! The pass structs are the pipeline's own; [`ComputeKernel`] and [`bind`] are public so that
//! companion crates write their passes the same way.

// By stage, in the order a frame runs them.
pub(crate) mod filter;
pub(crate) mod input;
pub(crate) mod kernel;
pub(crate) mod output;
pub(crate) mod resample;

use crate::shader::ShaderSource;
use crate::timing::PassTimer;

/// What a pass needs to record itself into a frame.
pub(crate) struct PassContext<'a> {
    /// The device, for bind groups.
    pub device: &'a wgpu::Device,
    /// The encoder the frame is recorded into.
    pub encoder: &'a mut wgpu::CommandEncoder,
    /// The `ViewUniforms` buffer of `size`, bound at binding 0 of every pass.
    pub view_uniforms: &'a wgpu::Buffer,
    /// The resolution the passes dispatch over: the input's, or the working resolution of the
    /// passes between the downsample and the upsample.
    pub size: [u32; 2],
    /// Collects per-pass GPU times when timing is on.
    pub timer: Option<&'a mut PassTimer>,
}

impl PassContext<'_> {
    /// Dispatches `kernel` over `size` with the view uniforms at binding 0 and
    /// `resources` from binding 1 on, timed when the frame is timed.
    pub fn dispatch(&mut self, kernel: &ComputeKernel, resources: &[wgpu::BindingResource<'_>]) {
        let mut bindings = Vec::with_capacity(resources.len() + 1);
        bindings.push(self.view_uniforms.as_entire_binding());
        bindings.extend_from_slice(resources);
        let timestamps = self.timer.as_mut().and_then(|t| t.pass(kernel.name()));
        kernel.dispatch(self.device, self.encoder, &bindings, self.size, timestamps);
    }
}

/// A compute pipeline with its one bind group layout, for one-thread-per-pixel passes whose
/// entry point is `main`. Public so that companion crates write their passes the same way.
///
/// ```no_run
/// use aokit::passes::{ComputeKernel, bind};
/// use aokit::shader::ShaderSource;
///
/// // A companion crate's pass: the AO as a black overlay for a compositor, transparent where
/// // nothing occludes.
/// const AO_OVERLAY: ShaderSource = ShaderSource {
///     name: "ao_overlay",
///     parts: &["
/// @group(0) @binding(0) var ao: texture_2d<f32>;
/// @group(0) @binding(1) var overlay: texture_storage_2d<rgba8unorm, write>;
///
/// @compute @workgroup_size(8, 8)
/// fn main(@builtin(global_invocation_id) id: vec3<u32>) {
///     // The last row and column of workgroups reach past the image.
///     if any(id.xy >= textureDimensions(overlay)) {
///         return;
///     }
///     let a = textureLoad(ao, id.xy, 0).r;
///     textureStore(overlay, id.xy, vec4<f32>(0.0, 0.0, 0.0, 1.0 - a));
/// }"],
/// };
///
/// # fn f(device: &wgpu::Device, encoder: &mut wgpu::CommandEncoder,
/// #      outputs: &aokit::AoOutputs<'_>, overlay: &wgpu::TextureView) {
/// // Compiled once, at load time; the layout lists the bindings in the shader's order.
/// let kernel = ComputeKernel::new(device, &AO_OVERLAY, &[
///     bind::texture(0, wgpu::TextureSampleType::Float { filterable: false }),
///     bind::storage_texture(1, wgpu::TextureFormat::Rgba8Unorm),
/// ]);
/// // Each frame, after `AoPipeline::encode`: one thread per pixel of the AO.
/// kernel.dispatch(
///     device,
///     encoder,
///     &[
///         wgpu::BindingResource::TextureView(outputs.ao_view),
///         wgpu::BindingResource::TextureView(overlay),
///     ],
///     [outputs.ao.width(), outputs.ao.height()],
///     None,
/// );
/// # }
/// ```
pub struct ComputeKernel {
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
    label: &'static str,
    /// Width and height in pixels of the block one workgroup of `main` covers: its workgroup
    /// size times its `TEXELS_PER_THREAD`, read from the WGSL so that the dispatch cannot
    /// disagree with it.
    workgroup_pixels: [u32; 2],
}

impl ComputeKernel {
    /// Compiles `source` with a bind group layout of `entries` at group 0.
    ///
    /// ```no_run
    /// # fn f(device: &wgpu::Device) {
    /// use aokit::passes::{ComputeKernel, bind};
    /// use aokit::shader::ShaderSource;
    /// const CLEAR: ShaderSource = ShaderSource {
    ///     name: "clear",
    ///     parts: &["
    /// @group(0) @binding(0) var target: texture_storage_2d<r32float, write>;
    /// @compute @workgroup_size(8, 8)
    /// fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    ///     textureStore(target, id.xy, vec4<f32>(1.0));
    /// }"],
    /// };
    /// let kernel = ComputeKernel::new(
    ///     device,
    ///     &CLEAR,
    ///     &[bind::storage_texture(0, wgpu::TextureFormat::R32Float)],
    /// );
    /// assert_eq!(kernel.name(), "clear");
    /// # }
    /// ```
    ///
    /// # Panics
    /// When `source` does not parse or has no compute entry point `main`: shader text is part of
    /// the program, and every library shader is validated by the tests.
    pub fn new(
        device: &wgpu::Device,
        source: &ShaderSource,
        entries: &[wgpu::BindGroupLayoutEntry],
    ) -> Self {
        Self::with_constants(device, source, entries, &[])
    }

    /// As [`ComputeKernel::new`], with values for the program's `override` constants, by name.
    ///
    /// ```no_run
    /// use aokit::passes::{ComputeKernel, bind};
    /// use aokit::shader::ShaderSource;
    ///
    /// // A mask of the pixels darker than a threshold the renderer fixes at load time: an
    /// // override constant, which the driver folds into the code.
    /// const DARK_MASK: ShaderSource = ShaderSource {
    ///     name: "dark_mask",
    ///     parts: &["
    /// override THRESHOLD: f32 = 0.5;
    ///
    /// @group(0) @binding(0) var ao: texture_2d<f32>;
    /// @group(0) @binding(1) var mask: texture_storage_2d<r32float, write>;
    ///
    /// @compute @workgroup_size(8, 8)
    /// fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    ///     if any(id.xy >= textureDimensions(mask)) {
    ///         return;
    ///     }
    ///     let dark = select(0.0, 1.0, textureLoad(ao, id.xy, 0).r < THRESHOLD);
    ///     textureStore(mask, id.xy, vec4<f32>(dark, 0.0, 0.0, 0.0));
    /// }"],
    /// };
    ///
    /// # fn f(device: &wgpu::Device) {
    /// let kernel = ComputeKernel::with_constants(
    ///     device,
    ///     &DARK_MASK,
    ///     &[
    ///         bind::texture(0, wgpu::TextureSampleType::Float { filterable: false }),
    ///         bind::storage_texture(1, wgpu::TextureFormat::R32Float),
    ///     ],
    ///     &[("THRESHOLD", 0.3)],
    /// );
    /// # }
    /// ```
    pub fn with_constants(
        device: &wgpu::Device,
        source: &ShaderSource,
        entries: &[wgpu::BindGroupLayoutEntry],
        constants: &[(&str, f64)],
    ) -> Self {
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some(source.name),
            entries,
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(source.name),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let module = source.create_module(device);
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(source.name),
            layout: Some(&pipeline_layout),
            module: &module,
            entry_point: Some("main"),
            compilation_options: wgpu::PipelineCompilationOptions {
                constants,
                ..Default::default()
            },
            cache: None,
        });
        let [width, height, _] = source.workgroup_size().unwrap_or_else(|e| panic!("{e}"));
        let texels = source.texels_per_thread().unwrap_or_else(|e| panic!("{e}"));
        Self {
            pipeline,
            layout,
            label: source.name,
            workgroup_pixels: [width * texels, height * texels],
        }
    }

    /// The shader's name, used for labels and timings.
    ///
    /// ```no_run
    /// # fn f(kernels: &[aokit::passes::ComputeKernel], gpu_ms: &[f64]) {
    /// // A companion crate's pass times, labelled by shader name as aokit's `PassTime`s are.
    /// for (kernel, ms) in kernels.iter().zip(gpu_ms) {
    ///     println!("{:>20} {ms:7.3} ms", kernel.name());
    /// }
    /// # }
    /// ```
    pub fn name(&self) -> &'static str {
        self.label
    }

    /// Binds `resources` in order (binding 0, 1, ...) and dispatches one thread per pixel of
    /// `size`, or per block of pixels where the shader declares `TEXELS_PER_THREAD`
    /// (workgroups of the shader's size, the last row and column partly outside), with
    /// timestamps around the pass when `timestamps` is given.
    ///
    /// ```no_run
    /// # fn f(device: &wgpu::Device, encoder: &mut wgpu::CommandEncoder,
    /// #      kernel: &aokit::passes::ComputeKernel, input: &wgpu::TextureView,
    /// #      output: &wgpu::TextureView, queries: &wgpu::QuerySet) {
    /// // Timed by the renderer's own query set (the device needs `TIMESTAMP_QUERY`):
    /// // timestamps 0 and 1 bracket the pass.
    /// kernel.dispatch(
    ///     device,
    ///     encoder,
    ///     &[
    ///         wgpu::BindingResource::TextureView(input),
    ///         wgpu::BindingResource::TextureView(output),
    ///     ],
    ///     [1920, 1080],
    ///     Some(wgpu::ComputePassTimestampWrites {
    ///         query_set: queries,
    ///         beginning_of_pass_write_index: Some(0),
    ///         end_of_pass_write_index: Some(1),
    ///     }),
    /// );
    /// # }
    /// ```
    pub fn dispatch(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        resources: &[wgpu::BindingResource<'_>],
        size: [u32; 2],
        timestamps: Option<wgpu::ComputePassTimestampWrites<'_>>,
    ) {
        let entries: Vec<wgpu::BindGroupEntry<'_>> = resources
            .iter()
            .enumerate()
            .map(|(binding, resource)| wgpu::BindGroupEntry {
                binding: binding as u32,
                resource: resource.clone(),
            })
            .collect();
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(self.label),
            layout: &self.layout,
            entries: &entries,
        });
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some(self.label),
            timestamp_writes: timestamps,
        });
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &bind_group, &[]);
        let [width, height] = self.workgroup_pixels;
        pass.dispatch_workgroups(size[0].div_ceil(width), size[1].div_ceil(height), 1);
    }
}

/// Bind group layout entries by kind, visible to compute.
///
/// ```
/// use aokit::passes::bind;
/// // A pass that reads its settings, the AO and multisampled depth, samples a lookup
/// // texture, and writes an image. Listed in binding order: `ComputeKernel::dispatch` binds
/// // its resources by position.
/// let entries = [
///     bind::uniform(0),
///     bind::texture(1, wgpu::TextureSampleType::Float { filterable: false }),
///     bind::texture_with_samples(2, wgpu::TextureSampleType::Depth, true),
///     bind::texture(3, wgpu::TextureSampleType::Float { filterable: true }),
///     bind::sampler(4, wgpu::SamplerBindingType::Filtering),
///     bind::storage_texture(5, wgpu::TextureFormat::Rgba8Unorm),
/// ];
/// assert!(entries.iter().all(|e| e.visibility == wgpu::ShaderStages::COMPUTE));
/// ```
pub mod bind {
    /// A uniform buffer, of any size: each dispatch checks it against the shader's struct.
    ///
    /// ```
    /// // `@group(0) @binding(0) var<uniform> view: ViewUniforms;`
    /// let entry = aokit::passes::bind::uniform(0);
    /// assert!(matches!(entry.ty, wgpu::BindingType::Buffer { ty: wgpu::BufferBindingType::Uniform, .. }));
    /// ```
    pub fn uniform(binding: u32) -> wgpu::BindGroupLayoutEntry {
        entry(
            binding,
            wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: false,
                min_binding_size: None,
            },
        )
    }

    /// A single-sampled 2D texture (`texture_2d<T>` or `texture_depth_2d`, by `sample_type`).
    ///
    /// ```
    /// // `@group(0) @binding(3) var normals: texture_2d<u32>;`
    /// let entry = aokit::passes::bind::texture(3, wgpu::TextureSampleType::Uint);
    /// assert!(matches!(entry.ty, wgpu::BindingType::Texture { multisampled: false, .. }));
    /// ```
    pub fn texture(
        binding: u32,
        sample_type: wgpu::TextureSampleType,
    ) -> wgpu::BindGroupLayoutEntry {
        texture_with_samples(binding, sample_type, false)
    }

    /// A 2D texture, multisampled (`texture_multisampled_2d`, read by sample index) or not.
    ///
    /// ```
    /// // `@group(0) @binding(1) var depth: texture_depth_multisampled_2d;`
    /// use aokit::passes::bind;
    /// let entry = bind::texture_with_samples(1, wgpu::TextureSampleType::Depth, true);
    /// assert!(matches!(entry.ty, wgpu::BindingType::Texture { multisampled: true, .. }));
    /// ```
    pub fn texture_with_samples(
        binding: u32,
        sample_type: wgpu::TextureSampleType,
        multisampled: bool,
    ) -> wgpu::BindGroupLayoutEntry {
        entry(
            binding,
            wgpu::BindingType::Texture {
                sample_type,
                view_dimension: wgpu::TextureViewDimension::D2,
                multisampled,
            },
        )
    }

    /// A write-only 2D storage texture of `format`, as the shader's
    /// `texture_storage_2d<format, write>` declares it.
    ///
    /// ```
    /// // `@group(0) @binding(4) var ao_out: texture_storage_2d<r32float, write>;`
    /// let entry = aokit::passes::bind::storage_texture(4, wgpu::TextureFormat::R32Float);
    /// assert!(matches!(
    ///     entry.ty,
    ///     wgpu::BindingType::StorageTexture { access: wgpu::StorageTextureAccess::WriteOnly, .. }
    /// ));
    /// ```
    pub fn storage_texture(
        binding: u32,
        format: wgpu::TextureFormat,
    ) -> wgpu::BindGroupLayoutEntry {
        entry(
            binding,
            wgpu::BindingType::StorageTexture {
                access: wgpu::StorageTextureAccess::WriteOnly,
                format,
                view_dimension: wgpu::TextureViewDimension::D2,
            },
        )
    }

    /// A sampler of binding type `ty`, which must suit the textures it samples.
    ///
    /// ```
    /// // `@group(0) @binding(5) var point_clamp: sampler;` over unfilterable depth.
    /// use aokit::passes::bind;
    /// let entry = bind::sampler(5, wgpu::SamplerBindingType::NonFiltering);
    /// assert_eq!(entry.ty, wgpu::BindingType::Sampler(wgpu::SamplerBindingType::NonFiltering));
    /// ```
    pub fn sampler(binding: u32, ty: wgpu::SamplerBindingType) -> wgpu::BindGroupLayoutEntry {
        entry(binding, wgpu::BindingType::Sampler(ty))
    }

    fn entry(binding: u32, ty: wgpu::BindingType) -> wgpu::BindGroupLayoutEntry {
        wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty,
            count: None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gpu::PairFormat;
    use crate::settings::{Method, NormalEncoding};
    use crate::shader;
    use filter::{edge_filter, guided_filter, spatial_filter, temporal_filter};
    use input::linear_depth::{self, DepthInput};
    use input::{back_faces, decode_normals, normals_from_depth};
    use kernel::{depth_mips, method, msvo, separable_hbao};
    use output::mask;

    const DEPTH_INPUTS: [DepthInput; 4] = [
        DepthInput::Ndc,
        DepthInput::NdcMultisampled,
        DepthInput::Linear,
        DepthInput::LinearMultisampled,
    ];
    const PAIRS: [PairFormat; 2] = [PairFormat::Rg32Float, PairFormat::Rgba32Float];

    /// Every program the library compiles with the layout it is compiled with, found as the
    /// passes find them.
    fn compiled() -> Vec<(ShaderSource, Vec<wgpu::BindGroupLayoutEntry>)> {
        let mut all = Vec::new();
        for input in DEPTH_INPUTS {
            let i = input as usize;
            all.push((
                shader::LINEAR_DEPTH[i],
                linear_depth::layout(input).to_vec(),
            ));
            all.push((shader::BACK_FACES[i], back_faces::layout(input).to_vec()));
            all.push((
                shader::UPSAMPLE[i],
                resample::upsample_layout(input).to_vec(),
            ));
            for pair in PAIRS {
                let layout = resample::downsample_layout(pair, input).to_vec();
                all.push((shader::DOWNSAMPLE[pair as usize][i], layout));
            }
        }
        for pair in PAIRS {
            let p = pair as usize;
            let spatial = [
                (
                    shader::SPATIAL_FILTER_HORIZONTAL[p],
                    spatial_filter::horizontal_layout(pair),
                ),
                (
                    shader::SPATIAL_FILTER_VERTICAL[p],
                    spatial_filter::vertical_layout(pair),
                ),
            ];
            all.extend(spatial);
            let coefficients = guided_filter::layout(pair.texture_format()).to_vec();
            all.push((shader::GUIDED_FILTER_COEFFICIENTS[p], coefficients));
            all.push((
                shader::TEMPORAL_FILTER[p],
                temporal_filter::layout(pair).to_vec(),
            ));
        }
        for encoding in NormalEncoding::ALL {
            let (program, layout) = decode_normals::program(encoding);
            all.push((program, layout.to_vec()));
        }
        for (multisampled, stencil) in [(false, false), (true, false), (false, true), (true, true)]
        {
            let (program, layout) = mask::program(multisampled, stencil);
            all.push((program, layout.to_vec()));
        }
        for format in [wgpu::TextureFormat::R32Float, wgpu::TextureFormat::R16Float] {
            let (program, layout) = depth_mips::program(format);
            all.push((program, layout.to_vec()));
        }
        // MSVO's kernels run in `MsvoPass`, below.
        for m in Method::ALL.into_iter().filter(|&m| m != Method::Msvo) {
            all.push((shader::method(m), method::method_layout(m)));
        }
        let method_layout = method::layout().to_vec();
        all.extend([
            (
                shader::NORMALS_FROM_DEPTH,
                normals_from_depth::layout().to_vec(),
            ),
            (shader::EDGE_FILTER, edge_filter::layout().to_vec()),
            (
                shader::GUIDED_FILTER_OUTPUT,
                guided_filter::layout(method::AO_FORMAT).to_vec(),
            ),
            (shader::HBAO_ROWS, separable_hbao::rows_layout()),
            (shader::HBAO_COLUMNS, separable_hbao::columns_layout()),
            (shader::MSVO_OBSCURANCE, method_layout),
            (shader::MSVO_MERGE, msvo::merge_layout()),
            (shader::DEBUG_VIEW, crate::debug::layout().to_vec()),
            (
                shader::DEPTH_TO_FLOAT,
                crate::gpu::depth_to_float_layout().to_vec(),
            ),
            // Validated, never compiled: renderers paste it into shaders of their own.
            (shader::OCCLUSION_FUNCTIONS, Vec::new()),
        ]);
        all
    }

    #[test]
    fn every_programs_layout_matches_its_wgsl_bindings() {
        let compiled = compiled();
        for (program, layout) in &compiled {
            shader::check_bindings(program, layout).unwrap_or_else(|e| panic!("{e}"));
        }
        for program in shader::ALL {
            assert!(
                compiled
                    .iter()
                    .any(|(p, _)| p.name == program.name && p.parts == program.parts),
                "{} is compiled with no layout this test checks",
                program.name
            );
        }
    }
}
