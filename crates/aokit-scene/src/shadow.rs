//! The sun's shadow map for the lit composite: one orthographic depth view fitted to the scene.

use aokit::Projection;
use aokit::gpu::create_texture_2d;
use bytemuck::{Pod, Zeroable};
use glam::{Mat4, Vec3};

use crate::gbuffer::{DEPTH_FORMAT, GpuMesh};
use crate::mesh::Bounds;
use crate::shaders;
use crate::uniform_block::UniformBlock;

/// Texels per side: about 2 cm per texel across Sponza's 37 m atrium.
pub const SHADOW_MAP_SIZE: u32 = 2048;

/// Mirrors `ShadowUniforms` in `shaders/shadow.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct ShadowUniforms {
    light_clip_from_world: [[f32; 4]; 4],
}

/// Where the sun's view sits for a scene.
///
/// ```
/// use aokit_scene::{Scene, shadow::{SHADOW_MAP_SIZE, SunView}};
/// use glam::Vec3;
/// let scene = Scene::open("room").unwrap();
/// let sun = SunView::new(Vec3::new(0.3, 1.0, 0.15), &scene.bounds);
/// // Every point of the scene lands inside the shadow map and its depth range.
/// let corner = sun.light_clip_from_world.project_point3(scene.bounds.max);
/// assert!(corner.x.abs() <= 1.0 && corner.y.abs() <= 1.0 && (0.0..=1.0).contains(&corner.z));
/// // One texel covers the scene's diameter over the map's size.
/// let diameter = 2.0 * scene.bounds.radius();
/// assert!((sun.texel_size * SHADOW_MAP_SIZE as f32 - diameter).abs() < 1e-4);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct SunView {
    /// World to the shadow map's clip space (standard depth, near = 0).
    pub light_clip_from_world: Mat4,
    /// World-space width of one shadow-map texel, for the normal offset against acne.
    pub texel_size: f32,
}

impl SunView {
    /// An orthographic view along `-sun_direction` holding all of `bounds`.
    ///
    /// ```
    /// use aokit_scene::composite::Lighting;
    /// use aokit_scene::shadow::SunView;
    /// let scene = aokit_scene::Builtin::Stairs.build();
    /// // The sun the composite lights with, so shadows fall where the light comes from.
    /// let sun = SunView::new(Lighting::default().sun_direction, &scene.bounds);
    /// assert!(sun.texel_size > 0.0);
    /// ```
    pub fn new(sun_direction: Vec3, bounds: &Bounds) -> Self {
        let radius = bounds.radius().max(1e-3);
        let center = bounds.center();
        let up = if sun_direction.normalize().y.abs() > 0.99 {
            Vec3::Z
        } else {
            Vec3::Y
        };
        let eye = center + sun_direction.normalize() * 2.0 * radius;
        let view = glam::camera::rh::view::look_at_mat4(eye, center, up);
        let projection =
            Projection::orthographic(2.0 * radius, 1.0, radius, 3.0 * radius).with_reverse_z(false);
        Self {
            light_clip_from_world: projection.clip_from_view() * view,
            texel_size: 2.0 * radius / SHADOW_MAP_SIZE as f32,
        }
    }
}

/// Renders the shadow map.
///
/// ```no_run
/// # fn f(gpu: &aokit::GpuContext, scene: &aokit_scene::Scene,
/// #      mesh: &aokit_scene::gbuffer::GpuMesh) {
/// use aokit_scene::shadow::{ShadowPass, SunView};
/// use glam::Vec3;
/// let pass = ShadowPass::new(&gpu.device);
/// let sun = SunView::new(Vec3::new(0.3, 1.0, 0.15), &scene.bounds);
/// let mut encoder = gpu.device.create_command_encoder(&Default::default());
/// pass.encode(&gpu.queue, &mut encoder, mesh, &sun);
/// gpu.queue.submit([encoder.finish()]);
/// // `pass.map` now holds the depth seen from the sun, for the composite to compare against.
/// # }
/// ```
pub struct ShadowPass {
    pipeline: wgpu::RenderPipeline,
    uniforms: UniformBlock<ShadowUniforms>,
    /// The depth map, `SHADOW_MAP_SIZE` square.
    pub map: wgpu::Texture,
}

impl ShadowPass {
    /// Compiles the pass and allocates the map.
    ///
    /// ```no_run
    /// use aokit_scene::shadow::{SHADOW_MAP_SIZE, ShadowPass};
    /// let gpu = aokit::GpuContext::headless()?;
    /// let pass = ShadowPass::new(&gpu.device);
    /// assert_eq!(pass.map.width(), SHADOW_MAP_SIZE);
    /// # Ok::<(), aokit::GpuError>(())
    /// ```
    pub fn new(device: &wgpu::Device) -> Self {
        let uniforms = UniformBlock::new(device, "shadow", wgpu::ShaderStages::VERTEX);
        let pipeline_layout = uniforms.pipeline_layout(device, "shadow");
        let module = shaders::SHADOW.create_module(device);
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("shadow"),
            layout: Some(&pipeline_layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs_main"),
                compilation_options: Default::default(),
                buffers: &[Some(GpuMesh::position_layout())],
            },
            primitive: Default::default(),
            depth_stencil: Some(wgpu::DepthStencilState {
                format: DEPTH_FORMAT,
                depth_write_enabled: Some(true),
                depth_compare: Some(wgpu::CompareFunction::Less),
                stencil: Default::default(),
                // Slope-scaled bias keeps lit surfaces from shadowing themselves at grazing sun.
                bias: wgpu::DepthBiasState {
                    constant: 2,
                    slope_scale: 2.0,
                    clamp: 0.0,
                },
            }),
            multisample: Default::default(),
            fragment: None,
            multiview_mask: None,
            cache: None,
        });
        let map = create_texture_2d(
            device,
            "shadow map",
            [SHADOW_MAP_SIZE; 2],
            DEPTH_FORMAT,
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
        );
        Self {
            pipeline,
            uniforms,
            map,
        }
    }

    /// Records the shadow map of `mesh` seen from `sun`. The sun only needs a new map when it
    /// or the mesh moves:
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, pass: &aokit_scene::shadow::ShadowPass,
    /// #      mesh: &mut aokit_scene::gbuffer::GpuMesh, sun: &aokit_scene::shadow::SunView) {
    /// let mut encoder = gpu.device.create_command_encoder(&Default::default());
    /// mesh.place(&gpu.queue, 0.5, 0.4);
    /// pass.encode(&gpu.queue, &mut encoder, mesh, sun);
    /// gpu.queue.submit([encoder.finish()]);
    /// # }
    /// ```
    pub fn encode(
        &self,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &GpuMesh,
        sun: &SunView,
    ) {
        let uniforms = ShadowUniforms {
            light_clip_from_world: sun.light_clip_from_world.to_cols_array_2d(),
        };
        self.uniforms.write(queue, &uniforms);
        let view = self.map.create_view(&Default::default());
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("shadow"),
            color_attachments: &[],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &view,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(1.0),
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, self.uniforms.bind_group(), &[]);
        mesh.draw(&mut pass);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniforms_match_wgsl() {
        let fields = aokit::field_offsets!(ShadowUniforms {
            light_clip_from_world
        });
        aokit::shader::check_layout(
            &shaders::SHADOW,
            "ShadowUniforms",
            fields,
            std::mem::size_of::<ShadowUniforms>(),
        )
        .unwrap();
    }

    #[test]
    fn the_sun_view_holds_the_whole_scene() {
        let bounds = Bounds {
            min: Vec3::new(-3.0, 0.0, -1.0),
            max: Vec3::new(5.0, 2.0, 4.0),
        };
        let sun = SunView::new(Vec3::new(0.3, 1.0, 0.2), &bounds);
        for i in 0..8 {
            let corner = Vec3::select(
                glam::BVec3::new(i & 1 == 0, i & 2 == 0, i & 4 == 0),
                bounds.min,
                bounds.max,
            );
            let clip = sun.light_clip_from_world * corner.extend(1.0);
            assert!(
                clip.x.abs() <= 1.0 && clip.y.abs() <= 1.0,
                "{corner} -> {clip}"
            );
            assert!((0.0..=1.0).contains(&clip.z), "{corner} -> {clip}");
        }
    }
}
