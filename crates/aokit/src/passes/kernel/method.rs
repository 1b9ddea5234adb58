//! The AO method kernels: linear depth and normals in, AO (and bent normals) out.
//!
//! Every method shares one binding layout and one settings buffer (`AoUniforms`), so one pass
//! runs whichever kernel the settings name. Kernels compile the first time their method is
//! used and stay compiled, so switching methods at runtime costs a compile only once.

use std::collections::HashMap;

use crate::gpu::{create_uniform_buffer, stand_in_view};
use crate::noise;
use crate::passes::input::back_faces::THICKNESS_FORMAT;
use crate::passes::input::linear_depth::LINEAR_DEPTH_FORMAT;
use crate::passes::kernel::depth_mips::{atlas_format, atlas_holds_level_0};
use crate::passes::{ComputeKernel, PassContext, bind};
use crate::settings::{AoSettings, Method, NoiseKind, OffscreenSamples, SampleDepth, SliceMarch};
use crate::shader;
use crate::uniforms::AoUniforms;

/// Format of the AO the kernels write: 1 = unoccluded.
pub const AO_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Float;
/// Format of the AO and linear depth the per-pixel kernels pack into one texel for the
/// spatial filter's edges kind ([`AoSettings::spatial`]'s `packed_input`;
/// `shaders/common/ao_and_depth.wgsl` has the layout of the bits).
pub const AO_AND_DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Uint;
/// Format of the bent normals: view-space xyz, AO in w. Half floats hold a unit vector to
/// about 0.05 degrees, finer than any AO estimate.
pub const BENT_NORMALS_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;
/// How a kernel reads the depth MIP atlas: the `DEPTH_MIPS_*` codes of `common/ao.wgsl`, set
/// as its `DEPTH_MIPS` override.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum DepthMipsRead {
    /// It reads none.
    Off = 0,
    /// Every level from the atlas, which holds level 0 too.
    Atlas = 1,
    /// Levels past 0 from the atlas, level 0 from the working depth.
    Coarse = 2,
}

impl DepthMipsRead {
    fn of(settings: &AoSettings) -> Self {
        match atlas_format(settings) {
            None => Self::Off,
            Some(format) if atlas_holds_level_0(format) => Self::Atlas,
            Some(_) => Self::Coarse,
        }
    }
}

/// What a compiled kernel was specialised for besides its method: how it reads the depth MIP
/// atlas, how its samples read depth and what they take off screen (`None` for the methods
/// that read depth one way only), for the lean slice march the slice and step counts, whether it writes bent normals, and its
/// noise. Each is an `override` of the WGSL: code a setting turns off is not in the kernel.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
struct Variant {
    depth_mips_read: DepthMipsRead,
    sample_depth: Option<SampleDepth>,
    offscreen_samples: Option<OffscreenSamples>,
    lean: Option<Lean>,
    bent_normals: bool,
    /// Whether it writes the AO and depth packed as well (common/ao_entry.wgsl), which only
    /// the frame knows (`MethodPass::encode`).
    packed_ao_and_depth: bool,
    /// The noise kind's and its temporal offset's codes (common/noise.wgsl).
    noise: [u32; 2],
}

impl Variant {
    fn of(settings: &AoSettings) -> Self {
        let sample_depth = settings
            .method
            .marches_slices()
            .then_some(settings.sample_depth);
        let offscreen_samples = settings
            .method
            .marches_slices()
            .then_some(settings.offscreen_samples);
        let uniforms = AoUniforms::new(settings);
        let lean = (sample_depth == Some(SampleDepth::Nearest)
            && settings.slice_march == SliceMarch::Lean)
            .then_some(Lean {
                slices: uniforms.count,
                steps: uniforms.steps,
                step_power: settings.step_power.to_bits(),
                thickness_blend: uniforms.thickness > 0.0,
                orthographic: false,
            });
        Self {
            depth_mips_read: DepthMipsRead::of(settings),
            sample_depth,
            offscreen_samples,
            lean,
            bent_normals: settings.bent_normals,
            packed_ao_and_depth: false,
            noise: [
                noise::kind_code(settings.noise.kind),
                noise::temporal_code(settings.noise.temporal),
            ],
        }
    }

    /// The override constants that compile this variant.
    fn constants(self) -> Vec<(&'static str, f64)> {
        let [noise_kind, noise_temporal] = self.noise;
        let mut constants = vec![
            ("DEPTH_MIPS", f64::from(self.depth_mips_read as u32)),
            ("BENT_NORMALS", f64::from(u8::from(self.bent_normals))),
            (
                "PACKED_AO_AND_DEPTH",
                f64::from(u8::from(self.packed_ao_and_depth)),
            ),
            ("NOISE_KIND", f64::from(noise_kind)),
            ("NOISE_TEMPORAL", f64::from(noise_temporal)),
        ];
        if let Some(sample_depth) = self.sample_depth {
            let nearest = sample_depth == SampleDepth::Nearest;
            constants.push(("NEAREST_DEPTH", f64::from(u8::from(nearest))));
        }
        if let Some(offscreen) = self.offscreen_samples {
            constants.push(("OFFSCREEN", f64::from(offscreen as u32)));
        }
        if let Some(lean) = self.lean {
            constants.extend([
                ("LEAN", 1.0),
                ("SLICES", f64::from(lean.slices)),
                ("STEPS", f64::from(lean.steps)),
                ("STEP_POWER", f64::from(f32::from_bits(lean.step_power))),
                ("THICKNESS_BLEND", f64::from(u8::from(lean.thickness_blend))),
                ("ORTHOGRAPHIC", f64::from(u8::from(lean.orthographic))),
            ]);
        }
        constants
    }
}

/// What the lean slice march compiles in: slices, steps per side, the step power's bits (a
/// float is no hash key), whether the thickness is above 0 (GTAO's blend; the other kernels
/// ignore it) and whether the projection is orthographic, which only the frame knows
/// (`MethodPass::encode`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
struct Lean {
    slices: u32,
    steps: u32,
    step_power: u32,
    thickness_blend: bool,
    orthographic: bool,
}

/// Kernels a [`MethodPass`] keeps compiled: more than a renderer switches between (methods,
/// noise kinds, the depth chain on and off), and a bound on what a slider or a search through a
/// value compiled in (the step power) would otherwise keep, a pipeline of every value it
/// passed through.
const MAX_KERNELS: usize = 16;

/// Runs the kernel of the current method.
pub struct MethodPass {
    /// By method and variant.
    kernels: HashMap<(Method, Variant), ComputeKernel>,
    /// The variant of the current settings' kernel, as it reads with the atlas bound.
    variant: Variant,
    uniforms: wgpu::Buffer,
    point_clamp: wgpu::Sampler,
    /// Bound in place of the bent normals when they are off: the kernels never write it.
    bent_placeholder: wgpu::TextureView,
    /// Bound in place of the packed AO and depth when no filter reads them.
    packed_placeholder: wgpu::TextureView,
    /// Noise tiles uploaded so far, by kind and side, so that switching back costs nothing.
    noise_tiles: HashMap<(NoiseKind, u32), wgpu::TextureView>,
    /// The tile of the current noise kind; `None` for the kinds computed in the shader.
    noise_tile: Option<(NoiseKind, u32)>,
    /// Bound in place of a noise tile for the kinds computed in the shader.
    noise_placeholder: wgpu::TextureView,
    /// Bound in place of the depth MIP atlas when the kernel reads none.
    depth_mips_placeholder: wgpu::TextureView,
    /// Bound in place of the back faces' thickness when VBAO does not read it.
    thickness_placeholder: wgpu::TextureView,
}

/// The bindings every AO kernel declares (`common/ao.wgsl`), 0 to 8.
pub(crate) fn layout() -> [wgpu::BindGroupLayoutEntry; 9] {
    [
        bind::uniform(0),
        bind::uniform(1),
        bind::texture(2, wgpu::TextureSampleType::Float { filterable: false }),
        bind::texture(3, wgpu::TextureSampleType::Uint),
        bind::storage_texture(4, AO_FORMAT),
        bind::sampler(5, wgpu::SamplerBindingType::NonFiltering),
        bind::storage_texture(6, BENT_NORMALS_FORMAT),
        bind::texture(7, wgpu::TextureSampleType::Float { filterable: false }),
        bind::texture(8, wgpu::TextureSampleType::Float { filterable: false }),
    ]
}

/// [`layout`] and what `method`'s per-pixel kernel declares besides: the packed AO and depth
/// (`common/ao_entry.wgsl`) at 9, VBAO's back-face thickness at 10.
pub(crate) fn method_layout(method: Method) -> Vec<wgpu::BindGroupLayoutEntry> {
    let mut entries = layout().to_vec();
    entries.push(bind::storage_texture(9, AO_AND_DEPTH_FORMAT));
    if method == Method::Vbao {
        entries.push(bind::texture(
            10,
            wgpu::TextureSampleType::Float { filterable: false },
        ));
    }
    entries
}

impl MethodPass {
    /// Creates the shared resources and compiles the kernel of `settings.method` (none when the
    /// separable HBAO passes run instead).
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue, settings: &AoSettings) -> Self {
        let point_clamp = crate::gpu::create_point_clamp_sampler(device, "aokit point clamp");
        let placeholder = |label, format, usage| stand_in_view(device, label, format, usage);
        let mut pass = Self {
            kernels: HashMap::new(),
            variant: Variant::of(settings),
            uniforms: create_uniform_buffer::<AoUniforms>(device, "aokit method settings"),
            point_clamp,
            bent_placeholder: placeholder(
                "aokit bent normals placeholder",
                BENT_NORMALS_FORMAT,
                wgpu::TextureUsages::STORAGE_BINDING,
            ),
            packed_placeholder: placeholder(
                "aokit packed ao and depth placeholder",
                AO_AND_DEPTH_FORMAT,
                wgpu::TextureUsages::STORAGE_BINDING,
            ),
            noise_tiles: HashMap::new(),
            noise_tile: None,
            noise_placeholder: placeholder(
                "aokit noise placeholder",
                noise::TILE_FORMAT,
                wgpu::TextureUsages::TEXTURE_BINDING,
            ),
            depth_mips_placeholder: placeholder(
                "aokit depth mips placeholder",
                LINEAR_DEPTH_FORMAT,
                wgpu::TextureUsages::TEXTURE_BINDING,
            ),
            thickness_placeholder: placeholder(
                "aokit back-face thickness placeholder",
                THICKNESS_FORMAT,
                wgpu::TextureUsages::TEXTURE_BINDING,
            ),
        };
        pass.set_settings(device, queue, settings);
        pass
    }

    /// Uploads validated settings, compiling their method's kernel and making their noise tile
    /// if either is new; they apply to every later `encode`.
    pub fn set_settings(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        settings: &AoSettings,
    ) {
        // The separable HBAO passes and MSVO's passes run instead of the method's kernel
        // (`SeparableHbaoPass`, `MsvoPass`).
        if !settings.separable_hbao() && settings.method != Method::Msvo {
            self.variant = Variant::of(settings);
            // Perspective, the usual case, compiled now; an orthographic frame compiles its
            // own the first time it comes.
            self.kernel(device, settings.method, self.variant);
        }
        self.noise_tile = noise::tile(&settings.noise).map(|tile| {
            let key = (settings.noise.kind, tile.size);
            self.noise_tiles
                .entry(key)
                .or_insert_with(|| tile.upload(device, queue).create_view(&Default::default()));
            key
        });
        queue.write_buffer(
            &self.uniforms,
            0,
            bytemuck::bytes_of(&AoUniforms::new(settings)),
        );
    }

    /// Records `method`'s kernel (the method of the settings last given, whose kernel
    /// `set_settings` compiled, or compiled here the first time a frame is `orthographic`)
    /// from `linear_depth`
    /// (`R32Float`) and oct32 `normals` into `ao` ([`AO_FORMAT`]) and, when the settings turn
    /// [`AoSettings::bent_normals`] on for a method that has them, into `bent_normals`
    /// ([`BENT_NORMALS_FORMAT`]), which must then be given. With
    /// [`AoSettings::depth_mips`] on, far samples read `depth_mips`, the chain's atlas
    /// (`DepthMipsPass::create_atlas`), which must then be given. With
    /// [`VbaoSettings::back_faces`](crate::VbaoSettings::back_faces) on, VBAO reads its
    /// occluders' thickness from `thickness` (`BackFacesPass`), which must then be given.
    /// Given `ao_and_depth` ([`AO_AND_DEPTH_FORMAT`]), the kernel writes its AO and the linear
    /// depth packed there as well, for the edges kind of the spatial filter to read.
    #[allow(clippy::too_many_arguments)]
    pub fn encode(
        &mut self,
        ctx: &mut PassContext<'_>,
        method: Method,
        orthographic: bool,
        linear_depth: &wgpu::TextureView,
        normals: &wgpu::TextureView,
        ao: &wgpu::TextureView,
        bent_normals: Option<&wgpu::TextureView>,
        depth_mips: Option<&wgpu::TextureView>,
        thickness: Option<&wgpu::TextureView>,
        ao_and_depth: Option<&wgpu::TextureView>,
    ) {
        let variant = Variant {
            depth_mips_read: match depth_mips {
                Some(_) => self.variant.depth_mips_read,
                None => DepthMipsRead::Off,
            },
            lean: self.variant.lean.map(|lean| Lean {
                orthographic,
                ..lean
            }),
            packed_ao_and_depth: ao_and_depth.is_some(),
            ..self.variant
        };
        self.kernel(ctx.device, method, variant);
        let kernel = &self.kernels[&(method, variant)];
        let mut resources = self
            .bindings(linear_depth, normals, ao, bent_normals, depth_mips)
            .to_vec();
        resources.push(wgpu::BindingResource::TextureView(
            ao_and_depth.unwrap_or(&self.packed_placeholder),
        ));
        if method == Method::Vbao {
            resources.push(wgpu::BindingResource::TextureView(
                thickness.unwrap_or(&self.thickness_placeholder),
            ));
        }
        ctx.dispatch(kernel, &resources);
    }

    /// Compiles `method`'s kernel for `variant` unless it is already; with [`MAX_KERNELS`] kept,
    /// the others go first.
    fn kernel(&mut self, device: &wgpu::Device, method: Method, variant: Variant) {
        if !self.kernels.contains_key(&(method, variant)) && self.kernels.len() >= MAX_KERNELS {
            self.kernels.clear();
        }
        self.kernels.entry((method, variant)).or_insert_with(|| {
            ComputeKernel::with_constants(
                device,
                &shader::method(method),
                &method_layout(method),
                &variant.constants(),
            )
        });
    }

    /// Bindings 1 to 8 of [`layout`] for the current settings, with `ao`, `bent_normals` and
    /// `depth_mips` as [`MethodPass::encode`] takes them: what every AO kernel reads and
    /// writes.
    pub(crate) fn bindings<'a>(
        &'a self,
        linear_depth: &'a wgpu::TextureView,
        normals: &'a wgpu::TextureView,
        ao: &'a wgpu::TextureView,
        bent_normals: Option<&'a wgpu::TextureView>,
        depth_mips: Option<&'a wgpu::TextureView>,
    ) -> [wgpu::BindingResource<'a>; 8] {
        [
            self.uniforms.as_entire_binding(),
            wgpu::BindingResource::TextureView(linear_depth),
            wgpu::BindingResource::TextureView(normals),
            wgpu::BindingResource::TextureView(ao),
            wgpu::BindingResource::Sampler(&self.point_clamp),
            wgpu::BindingResource::TextureView(bent_normals.unwrap_or(&self.bent_placeholder)),
            wgpu::BindingResource::TextureView(
                self.noise_tile
                    .map_or(&self.noise_placeholder, |key| &self.noise_tiles[&key]),
            ),
            wgpu::BindingResource::TextureView(depth_mips.unwrap_or(&self.depth_mips_placeholder)),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_slice_methods_are_the_kernels_with_a_nearest_read() {
        for method in Method::ALL {
            let program = shader::method(method);
            assert_eq!(
                program.parts.contains(&shader::SLICE),
                method.marches_slices(),
                "{method:?}"
            );
        }
    }

    #[test]
    fn off_screen_samples_compile_into_the_slice_kernels_only() {
        // The override exists in common/slice.wgsl only: a kernel without it would refuse it.
        let code = |settings: &AoSettings| {
            let constants = Variant::of(settings).constants();
            constants
                .into_iter()
                .find(|(name, _)| *name == "OFFSCREEN")
                .map(|(_, value)| value)
        };
        let mut settings = AoSettings::preset(Method::Gtao, crate::Preset::High);
        let module = shader::method(Method::Gtao).validate().unwrap();
        for (offscreen, name) in [
            (OffscreenSamples::Unoccluded, "OFFSCREEN_UNOCCLUDED"),
            (OffscreenSamples::Extend, "OFFSCREEN_EXTEND"),
            (OffscreenSamples::Clamp, "OFFSCREEN_CLAMP"),
        ] {
            settings.offscreen_samples = offscreen;
            let wgsl = shader::u32_constant(&module, name).unwrap();
            assert_eq!(code(&settings), Some(f64::from(wgsl)), "{name}");
        }
        settings.method = Method::Ssao;
        assert_eq!(code(&settings), None);
    }

    #[test]
    fn the_lean_variant_tells_a_thickness_of_0_from_the_others_only() {
        let at = |thickness| {
            let mut settings = AoSettings::preset(Method::Gtao, crate::Preset::High);
            settings.gtao.thickness = thickness;
            Variant::of(&settings)
        };
        assert_eq!(at(0.1), at(0.7));
        assert_ne!(at(0.0), at(0.1));
    }

    #[test]
    fn a_pass_keeps_at_most_max_kernels_compiled() {
        let gpu = crate::passes::filter::spatial_filter::tests::gpu();
        let mut settings = AoSettings::preset(Method::Gtao, crate::Preset::Low);
        let mut pass = MethodPass::new(&gpu.device, &gpu.queue, &settings);
        // A search through step powers, one variant each.
        for k in 0..MAX_KERNELS + 4 {
            settings.step_power = 1.0 + 0.25 * k as f32;
            pass.kernel(&gpu.device, Method::Gtao, Variant::of(&settings));
            assert!(
                pass.kernels.len() <= MAX_KERNELS,
                "{} kernels",
                pass.kernels.len()
            );
            assert!(
                pass.kernels
                    .contains_key(&(Method::Gtao, Variant::of(&settings)))
            );
        }
    }

    #[test]
    fn depth_mips_read_codes_match_wgsl() {
        let module = shader::method(Method::Gtao).validate().unwrap();
        for (name, read) in [
            ("DEPTH_MIPS_OFF", DepthMipsRead::Off),
            ("DEPTH_MIPS_ATLAS", DepthMipsRead::Atlas),
            ("DEPTH_MIPS_COARSE", DepthMipsRead::Coarse),
        ] {
            assert_eq!(
                shader::u32_constant(&module, name),
                Some(read as u32),
                "{name}"
            );
        }
        let mut settings = AoSettings::default();
        assert_eq!(DepthMipsRead::of(&settings), DepthMipsRead::Off);
        settings.depth_mips = crate::DepthMips::Fp32;
        assert_eq!(DepthMipsRead::of(&settings), DepthMipsRead::Atlas);
        settings.depth_mips = crate::DepthMips::Fp16;
        assert_eq!(DepthMipsRead::of(&settings), DepthMipsRead::Coarse);
    }
}
