//! The lit composite: ambient diffuse and specular light occluded by the AO pipeline's outputs,
//! plus shadowed sunlight. docs/composite.md has the formula.

use std::collections::HashMap;

use aokit::gpu::create_uniform_buffer;
use aokit::passes::{ComputeKernel, bind};
use aokit::{AoOutputs, Projection};
use bytemuck::{Pod, Zeroable};
use glam::{Mat4, Vec3};

use crate::gbuffer::GBuffer;
use crate::shaders;
use crate::shadow::SunView;

/// Format of the lit image: sRGB-encoded by the shader (storage textures cannot be sRGB).
pub const LIT_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// Lighting of the composite, in world space and linear RGB.
///
/// ```no_run
/// # fn f(gpu: &aokit::GpuContext, renderer: &mut aokit_scene::Renderer,
/// #      camera: &aokit_scene::Camera) -> Result<(), aokit_scene::RenderError> {
/// use aokit_scene::composite::{Lighting, SpecularOcclusion};
/// use glam::Vec3;
/// // Late afternoon: a low, warm sun, and glossier surfaces to show specular occlusion.
/// renderer.lighting = Lighting {
///     sun_direction: Vec3::new(-0.8, 0.3, 0.2).normalize(),
///     sun_color: Vec3::new(1.0, 0.7, 0.45),
///     specular_occlusion: SpecularOcclusion::Gtso,
///     roughness: 0.3,
///     ..Lighting::default()
/// };
/// let frame = renderer.render(gpu, camera, [640, 360], 0)?;
/// # Ok(()) }
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lighting {
    /// Direction towards the sun.
    pub sun_direction: Vec3,
    /// Sun irradiance.
    pub sun_color: Vec3,
    /// Radiance of the uniform sky that lights the ambient diffuse and specular terms, the ones
    /// AO darkens.
    pub ambient_color: Vec3,
    /// Background colour.
    pub sky_color: Vec3,
    /// How the AO darkens ambient diffuse light: occluded directions show nearby lit surfaces,
    /// not black, so bright surfaces should lose less light than the raw AO says. GTAO's fit by
    /// default, as in renderers that ship GTAO; the raw AO is still what the pipeline returns
    /// (`ao.png`) whatever this is.
    pub multi_bounce: MultiBounce,
    /// How the AO occludes the ambient specular term.
    pub specular_occlusion: SpecularOcclusion,
    /// Perceptual roughness in `[0, 1]` (GGX `alpha = roughness^2`) of every surface: the
    /// G-buffer has no roughness channel, so one value serves the whole scene. Values outside
    /// `[0, 1]` are clamped by the shader.
    pub roughness: f32,
    /// Specular reflectance at normal incidence (F0), linear RGB: 0.04 for common dielectrics
    /// (index of refraction 1.5), the metal's colour for metals.
    pub specular_color: Vec3,
}

/// How the composite turns the AO into the occlusion of ambient diffuse light.
///
/// ```
/// use aokit_scene::composite::{Lighting, MultiBounce};
/// // As `--multi-bounce` takes it.
/// let form: MultiBounce = "closed-form".parse()?;
/// let lighting = Lighting { multi_bounce: form, ..Lighting::default() };
/// assert_eq!(lighting.multi_bounce.name(), "closed-form");
/// assert_eq!(Lighting::default().multi_bounce, MultiBounce::Gtao);
/// assert!("fit".parse::<MultiBounce>().unwrap_err().contains("none, gtao, closed-form"));
/// # Ok::<(), String>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum MultiBounce {
    /// The raw AO: occluded directions are black, as AO assumes.
    None,
    /// [`multi_bounce_gtao`](aokit::occlusion::multi_bounce_gtao), Jimenez et al.'s fit to
    /// path-traced interreflections. The default: it was fitted for GTAO's AO on scenes whose
    /// occluders vary, and stays moderate for bright albedos.
    #[default]
    Gtao,
    /// [`multi_bounce_closed_form`](aokit::occlusion::multi_bounce_closed_form),
    /// `ao / (1 - albedo (1 - ao))`: exact when the occluders share the shaded point's albedo and
    /// lighting, and much brighter than the fit in dark corners of bright materials.
    ClosedForm,
}

impl MultiBounce {
    /// Every form, in the order the CLI lists them.
    pub const ALL: [MultiBounce; 3] = [
        MultiBounce::None,
        MultiBounce::Gtao,
        MultiBounce::ClosedForm,
    ];

    /// The name used on the command line.
    ///
    /// ```
    /// use aokit_scene::composite::MultiBounce;
    /// let names: Vec<&str> = MultiBounce::ALL.map(MultiBounce::name).to_vec();
    /// assert_eq!(names.join(", "), "none, gtao, closed-form");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            MultiBounce::None => "none",
            MultiBounce::Gtao => "gtao",
            MultiBounce::ClosedForm => "closed-form",
        }
    }

    /// The form's code in the `MULTI_BOUNCE` pipeline constant (the `MB_*` constants of
    /// `shaders/composite.wgsl`).
    fn code(self) -> u32 {
        match self {
            MultiBounce::None => 0,
            MultiBounce::Gtao => 1,
            MultiBounce::ClosedForm => 2,
        }
    }
}

impl std::str::FromStr for MultiBounce {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        Self::ALL
            .into_iter()
            .find(|form| form.name() == s)
            .ok_or_else(|| {
                let known: Vec<&str> = Self::ALL.iter().map(|f| f.name()).collect();
                format!("unknown multi-bounce `{s}` (known: {})", known.join(", "))
            })
    }
}

/// How the composite occludes ambient specular light.
///
/// ```
/// use aokit_scene::composite::{Lighting, SpecularOcclusion};
/// // As `--specular-occlusion` takes it.
/// let mode: SpecularOcclusion = "gtso".parse()?;
/// let lighting = Lighting { specular_occlusion: mode, ..Lighting::default() };
/// assert_eq!(lighting.specular_occlusion.name(), "gtso");
/// assert!("ssr".parse::<SpecularOcclusion>().unwrap_err().contains("frostbite"));
/// # Ok::<(), String>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum SpecularOcclusion {
    /// Not at all: the full ambient reflection everywhere, to see what occlusion removes.
    None,
    /// [`specular_occlusion_gtso`](aokit::occlusion::specular_occlusion_gtso): the visibility
    /// cone around the bent normal intersected with the specular cone. Uses the pipeline's bent
    /// normals; the [`Renderer`](crate::Renderer) turns them on when the method has them
    /// ([`Method::has_bent_normals`](aokit::Method::has_bent_normals)). Other methods fall back
    /// to the G-buffer normal, which keeps the cone sizes but loses the direction of the
    /// openings.
    Gtso,
    /// [`specular_occlusion_frostbite`](aokit::occlusion::specular_occlusion_frostbite): from AO,
    /// N.V and roughness alone. The default: it works with every method and asks nothing more
    /// of the AO pipeline, so the composite's settings never change the work that is timed.
    #[default]
    Frostbite,
}

impl SpecularOcclusion {
    /// Every mode, in the order the CLI lists them.
    pub const ALL: [SpecularOcclusion; 3] = [
        SpecularOcclusion::None,
        SpecularOcclusion::Gtso,
        SpecularOcclusion::Frostbite,
    ];

    /// The name used on the command line.
    ///
    /// ```
    /// use aokit_scene::composite::SpecularOcclusion;
    /// let names: Vec<&str> = SpecularOcclusion::ALL.map(SpecularOcclusion::name).to_vec();
    /// assert_eq!(names.join(", "), "none, gtso, frostbite");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            SpecularOcclusion::None => "none",
            SpecularOcclusion::Gtso => "gtso",
            SpecularOcclusion::Frostbite => "frostbite",
        }
    }

    /// The mode's code in the `SPECULAR_OCCLUSION` pipeline constant (the `SO_*` constants of
    /// `shaders/composite.wgsl`).
    fn code(self) -> u32 {
        match self {
            SpecularOcclusion::None => 0,
            SpecularOcclusion::Gtso => 1,
            SpecularOcclusion::Frostbite => 2,
        }
    }
}

impl std::str::FromStr for SpecularOcclusion {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        Self::ALL
            .into_iter()
            .find(|mode| mode.name() == s)
            .ok_or_else(|| {
                let known: Vec<&str> = Self::ALL.iter().map(|m| m.name()).collect();
                format!(
                    "unknown specular occlusion `{s}` (known: {})",
                    known.join(", ")
                )
            })
    }
}

impl Default for Lighting {
    fn default() -> Self {
        Self {
            // Sun 70 degrees high: it still reaches the floor of Sponza's narrow atrium, and
            // casts short shadows from +X+Z in the built-in scenes.
            sun_direction: Vec3::new(0.3, 1.0, 0.15).normalize(),
            sun_color: Vec3::new(1.0, 0.94, 0.84) * 0.8,
            // Ambient strong enough that AO reads clearly in shade, where it is all the light.
            ambient_color: Vec3::new(0.62, 0.67, 0.78),
            sky_color: Vec3::new(0.42, 0.55, 0.75),
            multi_bounce: MultiBounce::default(),
            specular_occlusion: SpecularOcclusion::default(),
            // Between polished and matte, like painted plaster: the specular occlusion modes
            // differ visibly without the sharp reflections a uniform sky would make look flat.
            roughness: 0.5,
            specular_color: Vec3::splat(0.04),
        }
    }
}

/// Mirrors `CompositeUniforms` in `shaders/composite.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct CompositeUniforms {
    view_from_clip: [[f32; 4]; 4],
    light_clip_from_view: [[f32; 4]; 4],
    sun_direction: [f32; 4],
    sun_color: [f32; 4],
    ambient_color: [f32; 4],
    sky_color: [f32; 4],
    specular_color: [f32; 4],
    far_ndc_depth: f32,
    shadow_normal_offset: f32,
    orthographic: f32,
    roughness: f32,
}

/// Where and how the frame was seen, for the composite. See [`CompositePass::encode`] for a
/// whole frame.
///
/// ```
/// use aokit_scene::composite::{CompositeView, Lighting};
/// use aokit_scene::shadow::SunView;
/// let scene = aokit_scene::Builtin::Room.build();
/// let sun = SunView::new(Lighting::default().sun_direction, &scene.bounds);
/// let projection = aokit::Projection::perspective(1.0, 16.0 / 9.0, 0.1, None);
/// let view = CompositeView {
///     projection: &projection,
///     // The camera at the world's origin, looking down -Z.
///     view_from_world: glam::Mat4::IDENTITY,
///     sun: &sun,
/// };
/// assert!(view.sun.texel_size > 0.0);
/// ```
pub struct CompositeView<'a> {
    /// The camera's projection.
    pub projection: &'a Projection,
    /// The camera's world-to-view transform.
    pub view_from_world: Mat4,
    /// The sun's shadow view.
    pub sun: &'a SunView,
}

/// Writes the lit image from the G-buffer and the AO.
///
/// ```no_run
/// # fn f(device: &wgpu::Device) {
/// use aokit_scene::composite::{CompositePass, LIT_FORMAT};
/// let composite = CompositePass::new(device);
/// // Storage textures cannot be sRGB: the shader encodes, and the texture stores the bytes.
/// let lit = aokit::gpu::create_texture_2d(device, "lit", [1280, 720], LIT_FORMAT,
///     wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC);
/// # }
/// ```
pub struct CompositePass {
    /// One pipeline per combination of lighting modes used so far, compiled on first use (see
    /// [`KernelKey`]).
    kernels: HashMap<KernelKey, ComputeKernel>,
    uniforms: wgpu::Buffer,
    shadow_sampler: wgpu::Sampler,
}

/// The composite's pipeline constants: multi-bounce form, specular occlusion mode and whether
/// bent normals are bound. Constants rather than uniforms because Mesa's lavapipe (22.3)
/// recompiles, at every dispatch, a shader whose branches depend on uniform values alone, and
/// keeps every compile: `aokit render --frames 400` grew by 0.5 MB a frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
struct KernelKey {
    multi_bounce: MultiBounce,
    specular_occlusion: SpecularOcclusion,
    has_bent_normals: bool,
}

impl KernelKey {
    fn compile(self, device: &wgpu::Device) -> ComputeKernel {
        let float = wgpu::TextureSampleType::Float { filterable: false };
        ComputeKernel::with_constants(
            device,
            &shaders::COMPOSITE,
            &[
                bind::uniform(0),
                bind::texture(1, float),
                bind::texture(2, wgpu::TextureSampleType::Uint),
                bind::texture(3, float),
                bind::texture(4, float),
                bind::texture(5, wgpu::TextureSampleType::Depth),
                bind::sampler(6, wgpu::SamplerBindingType::Comparison),
                bind::storage_texture(7, LIT_FORMAT),
                bind::texture(8, float),
            ],
            &[
                ("MULTI_BOUNCE", f64::from(self.multi_bounce.code())),
                (
                    "SPECULAR_OCCLUSION",
                    f64::from(self.specular_occlusion.code()),
                ),
                (
                    "HAS_BENT_NORMALS",
                    f64::from(u32::from(self.has_bent_normals)),
                ),
            ],
        )
    }
}

impl CompositePass {
    /// Compiles the pass.
    ///
    /// ```no_run
    /// let gpu = aokit::GpuContext::headless()?;
    /// // Compiled once (other lighting modes at their first frame); each frame records it.
    /// let composite = aokit_scene::composite::CompositePass::new(&gpu.device);
    /// # Ok::<(), aokit::GpuError>(())
    /// ```
    pub fn new(device: &wgpu::Device) -> Self {
        // The default lighting's pipeline is compiled now; another combination of modes
        // compiles at the first frame that asks for it.
        let lighting = Lighting::default();
        let key = KernelKey {
            multi_bounce: lighting.multi_bounce,
            specular_occlusion: lighting.specular_occlusion,
            has_bent_normals: false,
        };
        let kernels = HashMap::from([(key, key.compile(device))]);
        let shadow_sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("shadow comparison"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            compare: Some(wgpu::CompareFunction::LessEqual),
            ..Default::default()
        });
        let uniforms = create_uniform_buffer::<CompositeUniforms>(device, "composite uniforms");
        Self {
            kernels,
            uniforms,
            shadow_sampler,
        }
    }

    /// Records the composite into `output` (a [`LIT_FORMAT`] storage texture), reading the AO,
    /// the normals the AO used (so that shading shows the normal encoding's precision, or the
    /// reconstruction from depth) and, for [`SpecularOcclusion::Gtso`], the bent normals when
    /// `ao` has them.
    ///
    /// A whole frame, as [`Renderer`](crate::Renderer) records it:
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, scene: &aokit_scene::Scene,
    /// #      camera: &aokit_scene::Camera) -> Result<(), Box<dyn std::error::Error>> {
    /// use aokit::{AoInputs, AoPipeline, AoSettings};
    /// use aokit_scene::composite::{CompositePass, CompositeView, LIT_FORMAT, Lighting};
    /// use aokit_scene::gbuffer::{GBuffer, GBufferCamera, GBufferPass, GpuMesh};
    /// use aokit_scene::shadow::{ShadowPass, SunView};
    /// let (device, queue) = (&gpu.device, &gpu.queue);
    /// let size = [640, 360];
    /// let settings = AoSettings::default();
    /// let lighting = Lighting::default();
    /// let mesh = GpuMesh::new(device, &scene.mesh, &scene.moving_parts);
    /// let (mut gbuffer_pass, shadow_pass) = (GBufferPass::new(device), ShadowPass::new(device));
    /// let mut composite = CompositePass::new(device);
    /// let mut ao = AoPipeline::new(device, queue, &settings)?;
    ///
    /// let projection = camera.projection(size[0] as f32 / size[1] as f32, &scene.bounds);
    /// let view_from_world = camera.view_from_world();
    /// let gbuffer = GBuffer::new(device, size, settings.normals.encoding);
    /// let lit = aokit::gpu::create_texture_2d(device, "lit", size, LIT_FORMAT,
    ///     wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC);
    /// let mut encoder = device.create_command_encoder(&Default::default());
    /// gbuffer_pass.encode(gpu, &mut encoder, &mesh, &GBufferCamera {
    ///     view_from_world,
    ///     projection: &projection,
    ///     previous_clip_from_world: projection.clip_from_view() * view_from_world,
    /// }, &gbuffer);
    /// let outputs = ao.encode(device, queue, &mut encoder, &AoInputs {
    ///     normals: Some((&gbuffer.normals).into()),
    ///     view_from_world,
    ///     ..AoInputs::new(&gbuffer.depth, projection)
    /// })?;
    /// let sun = SunView::new(lighting.sun_direction, &scene.bounds);
    /// shadow_pass.encode(queue, &mut encoder, &mesh, &sun);
    /// let view = CompositeView { projection: &projection, view_from_world, sun: &sun };
    /// composite.encode(device, queue, &mut encoder, &lighting, &view, &gbuffer, &outputs,
    ///                  &shadow_pass.map, &lit);
    /// queue.submit([encoder.finish()]);
    /// let rgba = aokit::gpu::read_texture(device, queue, &lit)?;
    /// # Ok(()) }
    /// ```
    #[allow(clippy::too_many_arguments)]
    pub fn encode(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        lighting: &Lighting,
        view: &CompositeView<'_>,
        gbuffer: &GBuffer,
        ao: &AoOutputs<'_>,
        shadow_map: &wgpu::Texture,
        output: &wgpu::Texture,
    ) {
        let sun = view
            .view_from_world
            .transform_vector3(lighting.sun_direction)
            .normalize();
        let uniforms = CompositeUniforms {
            view_from_clip: view
                .projection
                .clip_from_view()
                .inverse()
                .to_cols_array_2d(),
            light_clip_from_view: (view.sun.light_clip_from_world * view.view_from_world.inverse())
                .to_cols_array_2d(),
            sun_direction: sun.extend(0.0).to_array(),
            sun_color: lighting.sun_color.extend(0.0).to_array(),
            ambient_color: lighting.ambient_color.extend(0.0).to_array(),
            sky_color: lighting.sky_color.extend(0.0).to_array(),
            specular_color: lighting.specular_color.extend(0.0).to_array(),
            far_ndc_depth: view.projection.far_ndc_depth(),
            // Two texels clear the map's quantisation on slopes up to about 60 degrees.
            shadow_normal_offset: 2.0 * view.sun.texel_size,
            orthographic: if view.projection.is_orthographic() {
                1.0
            } else {
                0.0
            },
            roughness: lighting.roughness,
        };
        queue.write_buffer(&self.uniforms, 0, bytemuck::bytes_of(&uniforms));
        let color = |t: &wgpu::Texture| t.create_view(&Default::default());
        let depth_only = |t: &wgpu::Texture| {
            t.create_view(&wgpu::TextureViewDescriptor {
                aspect: wgpu::TextureAspect::DepthOnly,
                ..Default::default()
            })
        };
        let (albedo, depth, shadow, output) = (
            color(&gbuffer.albedo),
            depth_only(&gbuffer.depth),
            depth_only(shadow_map),
            color(output),
        );
        // Without bent normals the AO fills their slot, which takes any unfilterable float
        // texture; `HAS_BENT_NORMALS` = 0 tells the shader not to read it.
        let bent_normals = ao.bent_normals_view.unwrap_or(ao.ao_view);
        let key = KernelKey {
            multi_bounce: lighting.multi_bounce,
            specular_occlusion: lighting.specular_occlusion,
            has_bent_normals: ao.bent_normals_view.is_some(),
        };
        let kernel = self
            .kernels
            .entry(key)
            .or_insert_with(|| key.compile(device));
        kernel.dispatch(
            device,
            encoder,
            &[
                self.uniforms.as_entire_binding(),
                wgpu::BindingResource::TextureView(&albedo),
                wgpu::BindingResource::TextureView(ao.normals_view),
                wgpu::BindingResource::TextureView(&depth),
                wgpu::BindingResource::TextureView(ao.ao_view),
                wgpu::BindingResource::TextureView(&shadow),
                wgpu::BindingResource::Sampler(&self.shadow_sampler),
                wgpu::BindingResource::TextureView(&output),
                wgpu::BindingResource::TextureView(bent_normals),
            ],
            gbuffer.size,
            None,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniforms_match_wgsl() {
        let fields = aokit::field_offsets!(CompositeUniforms {
            view_from_clip,
            light_clip_from_view,
            sun_direction,
            sun_color,
            ambient_color,
            sky_color,
            specular_color,
            far_ndc_depth,
            shadow_normal_offset,
            orthographic,
            roughness,
        });
        aokit::shader::check_layout(
            &shaders::COMPOSITE,
            "CompositeUniforms",
            fields,
            std::mem::size_of::<CompositeUniforms>(),
        )
        .unwrap();
    }

    #[test]
    fn specular_occlusion_names_round_trip() {
        for mode in SpecularOcclusion::ALL {
            assert_eq!(mode.name().parse::<SpecularOcclusion>(), Ok(mode));
        }
        let err = "ssgi".parse::<SpecularOcclusion>().unwrap_err();
        assert!(
            err.contains("ssgi") && err.contains("none, gtso, frostbite"),
            "{err}"
        );
    }

    #[test]
    fn multi_bounce_names_round_trip() {
        for form in MultiBounce::ALL {
            assert_eq!(form.name().parse::<MultiBounce>(), Ok(form));
        }
        let err = "on".parse::<MultiBounce>().unwrap_err();
        assert!(
            err.contains("`on`") && err.contains("none, gtao, closed-form"),
            "{err}"
        );
    }

    /// Checks that composite.wgsl's `u32` constants hold the codes Rust sets its pipeline
    /// constants to.
    fn assert_codes_match_wgsl(codes: &[(u32, &str)]) {
        use wgpu::naga;
        let module = shaders::COMPOSITE.validate().unwrap();
        for &(code, name) in codes {
            let constant = module
                .constants
                .iter()
                .find(|(_, c)| c.name.as_deref() == Some(name))
                .unwrap_or_else(|| panic!("composite.wgsl has no constant {name}"))
                .1;
            let value = &module.global_expressions[constant.init];
            let expected = naga::Expression::Literal(naga::Literal::U32(code));
            assert!(*value == expected, "{name} is {value:?}, Rust says {code}");
        }
    }

    #[test]
    fn specular_occlusion_codes_match_wgsl() {
        assert_codes_match_wgsl(&[
            (SpecularOcclusion::None.code(), "SO_NONE"),
            (SpecularOcclusion::Gtso.code(), "SO_GTSO"),
            (SpecularOcclusion::Frostbite.code(), "SO_FROSTBITE"),
        ]);
    }

    #[test]
    fn multi_bounce_codes_match_wgsl() {
        assert_codes_match_wgsl(&[
            (MultiBounce::None.code(), "MB_NONE"),
            (MultiBounce::Gtao.code(), "MB_GTAO"),
            (MultiBounce::ClosedForm.code(), "MB_CLOSED_FORM"),
        ]);
    }
}
