//! XeGTAO's passes through wgpu, as its reference integration runs them: the depth prefilter,
//! the main pass at a quality level, and the denoiser passes, the last one writing the final
//! term; on aokit's depth buffer and normals, timed with aokit's [`PassTimer`].

use std::borrow::Cow;

use anyhow::{Result, bail};
use aokit::gpu::{create_texture_2d, create_texture_2d_mips, mip_view};
use aokit::passes::bind;
use aokit::{AoError, DeviceLoss, GpuError, PassTime, PassTimer, Projection};

use super::constants::GtaoConstants;
use super::source::Shaders;
use super::{PeerSettings, ShaderPath};

/// The wrapper's bindings (peers/xegtao.hlsl). Each pass's run from 0 without gaps: wgpu's
/// Vulkan backend numbers a layout's bindings by their rank, and SPIR-V passed through keeps
/// its own numbers. The `WRITE_ONLY` lists are the storage textures a pass only writes.
pub mod binding {
    pub const CONSTANTS: u32 = 0;
    pub const SAMPLER: u32 = 1;

    pub mod prefilter {
        pub const RAW_DEPTH: u32 = 2;
        pub const DEPTH_MIPS: [u32; 5] = [3, 4, 5, 6, 7];
        pub const WRITE_ONLY: &[u32] = &DEPTH_MIPS;
    }

    pub mod main {
        pub const VIEW_DEPTH: u32 = 2;
        pub const NORMALS: u32 = 3;
        pub const AO_TERM: u32 = 4;
        pub const EDGES: u32 = 5;
        pub const WRITE_ONLY: &[u32] = &[AO_TERM, EDGES];
    }

    /// Both denoiser passes: the last one's output is the final term.
    pub mod denoise {
        pub const AO_TERM: u32 = 2;
        pub const EDGES: u32 = 3;
        pub const OUTPUT: u32 = 4;
        pub const WRITE_ONLY: &[u32] = &[OUTPUT];
    }
}

/// Working depth: view depth in half floats, with XeGTAO's five MIP levels.
const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R16Float;
const DEPTH_MIP_LEVELS: u32 = 5;
/// The AO term between passes: visibility / 1.5 in 8 bits.
const TERM_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R8Uint;
/// Depth edges for the denoiser, four 2-bit weights.
const EDGES_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R8Unorm;
/// The final term: 32 bits, as the wrapper explains.
const FINAL_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Uint;

/// One compute pass: its pipeline and layout.
struct Pass {
    name: &'static str,
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
}

/// XeGTAO on one image size, with its working textures.
pub struct XeGtao {
    size: [u32; 2],
    settings: PeerSettings,
    prefilter: Pass,
    main: Pass,
    denoise: Pass,
    denoise_last: Pass,
    constants: wgpu::Buffer,
    sampler: wgpu::Sampler,
    depth: wgpu::Texture,
    terms: [wgpu::Texture; 2],
    edges: wgpu::Texture,
    output: wgpu::Texture,
    timer: Option<PassTimer>,
}

/// Layout entries of each pass, in the wrapper's bindings.
fn prefilter_entries() -> Vec<wgpu::BindGroupLayoutEntry> {
    let mut entries = vec![
        bind::uniform(binding::CONSTANTS),
        bind::sampler(binding::SAMPLER, wgpu::SamplerBindingType::NonFiltering),
        // The hardware depth buffer, its depth aspect read as floats.
        bind::texture(
            binding::prefilter::RAW_DEPTH,
            wgpu::TextureSampleType::Float { filterable: false },
        ),
    ];
    entries.extend(
        binding::prefilter::DEPTH_MIPS
            .iter()
            .map(|&b| bind::storage_texture(b, DEPTH_FORMAT)),
    );
    entries
}

fn main_entries() -> Vec<wgpu::BindGroupLayoutEntry> {
    vec![
        bind::uniform(binding::CONSTANTS),
        bind::sampler(binding::SAMPLER, wgpu::SamplerBindingType::NonFiltering),
        bind::texture(
            binding::main::VIEW_DEPTH,
            wgpu::TextureSampleType::Float { filterable: true },
        ),
        bind::texture(binding::main::NORMALS, wgpu::TextureSampleType::Uint),
        bind::storage_texture(binding::main::AO_TERM, TERM_FORMAT),
        bind::storage_texture(binding::main::EDGES, EDGES_FORMAT),
    ]
}

/// The denoiser's layout, writing `format`.
fn denoise_entries(format: wgpu::TextureFormat) -> Vec<wgpu::BindGroupLayoutEntry> {
    vec![
        bind::uniform(binding::CONSTANTS),
        bind::sampler(binding::SAMPLER, wgpu::SamplerBindingType::NonFiltering),
        bind::texture(binding::denoise::AO_TERM, wgpu::TextureSampleType::Uint),
        bind::texture(
            binding::denoise::EDGES,
            wgpu::TextureSampleType::Float { filterable: true },
        ),
        bind::storage_texture(binding::denoise::OUTPUT, format),
    ]
}

/// A compute pipeline from SPIR-V `words`, through naga or passed through; wgpu's validation
/// errors and the driver's own failures come back as errors.
fn pass(
    device: &wgpu::Device,
    name: &'static str,
    entry_point: &str,
    words: &[u32],
    path: ShaderPath,
    entries: &[wgpu::BindGroupLayoutEntry],
    lost: &DeviceLoss,
) -> Result<Pass> {
    let internal = device.push_error_scope(wgpu::ErrorFilter::Internal);
    let validation = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let module = match path {
        ShaderPath::Naga => device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(name),
            source: wgpu::ShaderSource::SpirV(Cow::Borrowed(words)),
        }),
        // SAFETY: the SPIR-V is glslang's output for aokit's wrapper, whose bindings the
        // layout below describes, numbered as wgpu's Vulkan backend numbers them (see
        // `binding`); the same module passes naga's validation on the naga path.
        ShaderPath::Passthrough => unsafe {
            device.create_shader_module_passthrough(wgpu::ShaderModuleDescriptorPassthrough {
                label: Some(name),
                entry_points: Cow::Owned(vec![wgpu::PassthroughShaderEntryPoint {
                    name: Cow::Borrowed(entry_point),
                    workgroup_size: (8, 8, 1),
                }]),
                spirv: Some(Cow::Borrowed(words)),
                ..Default::default()
            })
        },
    };
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some(name),
        entries,
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(name),
        layout: Some(
            &device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some(name),
                bind_group_layouts: &[Some(&layout)],
                immediate_size: 0,
            }),
        ),
        module: &module,
        entry_point: Some(entry_point),
        compilation_options: Default::default(),
        cache: None,
    });
    let hint = match path {
        ShaderPath::Passthrough => " (through naga it may: --set peer.shader=naga)",
        ShaderPath::Naga => "",
    };
    if let Some(error) = pollster::block_on(validation.pop()) {
        bail!(
            "XeGTAO's {name} pass cannot run through {} on this device: {error}{hint}",
            path.name()
        );
    }
    // A driver that cannot compile the SPIR-V (NVIDIA's 580 driver answers glslang's passed
    // through with "NVVM compilation failed") fails the pipeline, and wgpu takes the device for
    // lost without an error to catch: caught here, it stops the run with the reason rather
    // than a panic at the next use of the device.
    if let Err(AoError::DeviceLost { reason: message }) = lost.check() {
        bail!(
            "the driver failed to build XeGTAO's {name} pass from the SPIR-V given it {}, and \
             the device is lost: {message}{hint}",
            match path {
                ShaderPath::Passthrough => "as it is",
                ShaderPath::Naga => "through naga",
            }
        );
    }
    if let Some(error) = pollster::block_on(internal.pop()) {
        bail!(
            "the driver could not build XeGTAO's {name} pass from the SPIR-V given {}:              {error}{hint}",
            match path {
                ShaderPath::Passthrough => "it as it is",
                ShaderPath::Naga => "it through naga",
            }
        );
    }
    Ok(Pass {
        name,
        pipeline,
        layout,
    })
}

impl XeGtao {
    /// Builds the passes from `shaders` by `path` for images of `size`.
    pub fn new(
        device: &wgpu::Device,
        shaders: &Shaders,
        path: ShaderPath,
        settings: &PeerSettings,
        size: [u32; 2],
    ) -> Result<Self> {
        if path == ShaderPath::Passthrough
            && !device
                .features()
                .contains(wgpu::Features::PASSTHROUGH_SHADERS)
        {
            bail!("the adapter cannot pass SPIR-V through (no PASSTHROUGH_SHADERS): use naga");
        }
        if !device
            .features()
            .contains(wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES)
        {
            bail!(
                "XeGTAO writes R16Float, R8Uint and R8Unorm storage textures, which this device \
                 cannot (it lacks TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES)"
            );
        }
        let storage = wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::TEXTURE_BINDING;
        let readable = storage | wgpu::TextureUsages::COPY_SRC;
        let term = |label| create_texture_2d(device, label, size, TERM_FORMAT, storage);
        let lost = DeviceLoss::watch(device);
        Ok(Self {
            size,
            settings: settings.clone(),
            prefilter: pass(
                device,
                "xegtao_prefilter",
                "prefilter",
                &shaders.prefilter,
                path,
                &prefilter_entries(),
                &lost,
            )?,
            main: pass(
                device,
                "xegtao_main",
                "main_pass",
                &shaders.main,
                path,
                &main_entries(),
                &lost,
            )?,
            denoise: pass(
                device,
                "xegtao_denoise",
                "denoise",
                &shaders.denoise,
                path,
                &denoise_entries(TERM_FORMAT),
                &lost,
            )?,
            denoise_last: pass(
                device,
                "xegtao_denoise_last",
                "denoise_last",
                &shaders.denoise_last,
                path,
                &denoise_entries(FINAL_FORMAT),
                &lost,
            )?,
            constants: device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("xegtao constants"),
                size: std::mem::size_of::<GtaoConstants>() as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            }),
            // XeGTAO's point-clamp sampler.
            sampler: device.create_sampler(&wgpu::SamplerDescriptor {
                label: Some("xegtao point clamp"),
                ..Default::default()
            }),
            depth: create_texture_2d_mips(
                device,
                "xegtao working depth",
                size,
                DEPTH_MIP_LEVELS,
                DEPTH_FORMAT,
                readable,
            ),
            terms: [term("xegtao ao term"), term("xegtao ao term pong")],
            edges: create_texture_2d(device, "xegtao edges", size, EDGES_FORMAT, storage),
            output: create_texture_2d(device, "xegtao output", size, FINAL_FORMAT, readable),
            timer: None,
        })
    }

    /// Times each pass from now on, where the device has timestamps; `false` where not.
    pub fn enable_timing(&mut self, device: &wgpu::Device, queue: &wgpu::Queue) -> bool {
        self.timer = PassTimer::new(device, queue);
        self.timer.is_some()
    }

    /// The passes of the last frame encoded, `None` without timing.
    pub fn last_pass_times(
        &self,
        device: &wgpu::Device,
    ) -> Option<Result<Vec<PassTime>, GpuError>> {
        self.timer.as_ref().map(|timer| timer.read(device))
    }

    /// Records one frame on `depth` (hardware depth, as `projection` wrote it) and `normals`
    /// (aokit's oct32 view-space normals).
    pub fn encode(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        depth: &wgpu::Texture,
        normals: &wgpu::Texture,
        projection: &Projection,
    ) -> Result<()> {
        if [depth.width(), depth.height()] != self.size {
            bail!("the depth buffer is not the size XeGTAO was set up for");
        }
        let constants = GtaoConstants::new(
            projection,
            self.size,
            self.settings.radius,
            self.settings.denoise_passes,
        )?;
        queue.write_buffer(&self.constants, 0, bytemuck::bytes_of(&constants));
        if let Some(timer) = &mut self.timer {
            timer.begin_frame();
        }
        let depth_view = depth.create_view(&wgpu::TextureViewDescriptor {
            aspect: wgpu::TextureAspect::DepthOnly,
            ..Default::default()
        });
        let mip_views: Vec<wgpu::TextureView> = (0..DEPTH_MIP_LEVELS)
            .map(|level| mip_view(&self.depth, level))
            .collect();
        let mut inputs = vec![(binding::prefilter::RAW_DEPTH, &depth_view)];
        inputs.extend(
            binding::prefilter::DEPTH_MIPS
                .iter()
                .copied()
                .zip(&mip_views),
        );
        let [w, h] = self.size;
        let prefilter = self.bind_group(device, &self.prefilter, &inputs);
        self.dispatch(
            encoder,
            Step::Prefilter,
            &prefilter,
            [w.div_ceil(16), h.div_ceil(16)],
        );

        let view = |t: &wgpu::Texture| t.create_view(&Default::default());
        let (depth_all, normals, edges) = (view(&self.depth), view(normals), view(&self.edges));
        let terms = [view(&self.terms[0]), view(&self.terms[1])];
        let output = view(&self.output);
        let main = self.bind_group(
            device,
            &self.main,
            &[
                (binding::main::VIEW_DEPTH, &depth_all),
                (binding::main::NORMALS, &normals),
                (binding::main::AO_TERM, &terms[0]),
                (binding::main::EDGES, &edges),
            ],
        );
        self.dispatch(encoder, Step::Main, &main, [w.div_ceil(8), h.div_ceil(8)]);

        // As XeGTAO's integration: at least one pass, the last writing the output; the term
        // ping-pongs between the two working textures before it.
        let passes = self.settings.denoise_passes.max(1);
        for i in 0..passes {
            let last = i + 1 == passes;
            let (source, target) = (&terms[i as usize % 2], &terms[(i as usize + 1) % 2]);
            let (pass, step, out) = if last {
                (
                    &self.denoise_last,
                    Step::DenoiseLast,
                    (binding::denoise::OUTPUT, &output),
                )
            } else {
                (
                    &self.denoise,
                    Step::Denoise,
                    (binding::denoise::OUTPUT, target),
                )
            };
            let group = self.bind_group(
                device,
                pass,
                &[
                    (binding::denoise::AO_TERM, source),
                    (binding::denoise::EDGES, &edges),
                    out,
                ],
            );
            self.dispatch(encoder, step, &group, [w.div_ceil(16), h.div_ceil(8)]);
        }
        if let Some(timer) = &self.timer {
            timer.resolve(encoder);
        }
        Ok(())
    }

    /// A bind group of `pass`: the constants and sampler, then `views` at their bindings.
    fn bind_group(
        &self,
        device: &wgpu::Device,
        pass: &Pass,
        views: &[(u32, &wgpu::TextureView)],
    ) -> wgpu::BindGroup {
        let mut entries = vec![
            wgpu::BindGroupEntry {
                binding: binding::CONSTANTS,
                resource: self.constants.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: binding::SAMPLER,
                resource: wgpu::BindingResource::Sampler(&self.sampler),
            },
        ];
        entries.extend(views.iter().map(|&(binding, view)| wgpu::BindGroupEntry {
            binding,
            resource: wgpu::BindingResource::TextureView(view),
        }));
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(pass.name),
            layout: &pass.layout,
            entries: &entries,
        })
    }

    fn dispatch(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        step: Step,
        group: &wgpu::BindGroup,
        groups: [u32; 2],
    ) {
        let pass = match step {
            Step::Prefilter => &self.prefilter,
            Step::Main => &self.main,
            Step::Denoise => &self.denoise,
            Step::DenoiseLast => &self.denoise_last,
        };
        let timestamp_writes = self.timer.as_mut().and_then(|t| t.pass(pass.name));
        let mut compute = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some(pass.name),
            timestamp_writes,
        });
        compute.set_pipeline(&pass.pipeline);
        compute.set_bind_group(0, group, &[]);
        compute.dispatch_workgroups(groups[0], groups[1], 1);
    }

    /// The final visibility of the last frame submitted, 1 = unoccluded, row by row. XeGTAO
    /// stores it as 255 * the term, in an 8-bit texel that clamps at 255.
    pub fn read_visibility(&self, device: &wgpu::Device, queue: &wgpu::Queue) -> Result<Vec<f32>> {
        let bytes = aokit::gpu::read_texture(device, queue, &self.output)?;
        let texels: Vec<u32> = bytemuck::pod_collect_to_vec(&bytes);
        Ok(texels
            .into_iter()
            .map(|v| v.min(255) as f32 / 255.0)
            .collect())
    }

    /// The working depth's MIP 0 of the last frame submitted: XeGTAO's view depth.
    #[cfg(test)]
    pub fn read_working_depth(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
    ) -> Result<Vec<f32>> {
        Ok(aokit::gpu::read_texture_f32(device, queue, &self.depth)?)
    }
}

/// Which pass a dispatch runs.
#[derive(Clone, Copy)]
enum Step {
    Prefilter,
    Main,
    Denoise,
    DenoiseLast,
}
