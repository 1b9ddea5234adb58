//! The G-buffer raster pass: depth (D32F), view-space normals in any
//! [`NormalEncoding`], albedo and motion vectors. No MSAA.

use std::collections::HashMap;

use aokit::gpu::create_texture_2d;
use aokit::{GpuContext, NormalEncoding, Projection};
use bytemuck::{Pod, Zeroable};
use glam::{Mat4, Vec3};
use wgpu::util::DeviceExt;

use crate::animation::{Motion, MovingPart};
use crate::mesh::Mesh;
use crate::shaders;
use crate::uniform_block::UniformBlock;

/// Depth format of the G-buffer.
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
/// Albedo, stored sRGB so 8 bits keep dark tones.
pub const ALBEDO_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;
/// Motion vectors, in the convention of [`AoInputs::motion_vectors`](aokit::AoInputs): half
/// floats round an offset by at most 1/2048 of its length, under 0.05 pixels for the 100 a fast
/// camera moves in a frame.
pub const MOTION_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rg16Float;

#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct GpuVertex {
    position: [f32; 3],
    normal: [f32; 3],
    albedo: [f32; 3],
    /// Where this point of the surface was in the previous frame, for motion vectors.
    previous_position: [f32; 3],
}

impl GpuVertex {
    /// Vertex `i` of `mesh`, standing still.
    fn of(mesh: &Mesh, i: usize) -> Self {
        Self {
            position: mesh.positions[i].to_array(),
            normal: mesh.normals[i].to_array(),
            albedo: mesh.albedo[i].to_array(),
            previous_position: mesh.positions[i].to_array(),
        }
    }
}

/// Mirrors `GBufferUniforms` in `shaders/gbuffer.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct GBufferUniforms {
    clip_from_world: [[f32; 4]; 4],
    view_from_world: [[f32; 4]; 4],
    previous_clip_from_world: [[f32; 4]; 4],
    size: [f32; 2],
    orthographic: f32,
    _pad: f32,
}

/// A moving part's vertices at rest, kept to place them again each frame.
struct RestPart {
    first_vertex: u32,
    motion: Motion,
    vertices: Vec<GpuVertex>,
}

/// A mesh uploaded to the GPU, with its moving parts placed at some time of a sequence.
///
/// ```no_run
/// # fn f(device: &wgpu::Device, queue: &wgpu::Queue) -> Result<(), aokit_scene::SceneError> {
/// use aokit_scene::{Scene, gbuffer::GpuMesh};
/// let scene = Scene::open("room")?;
/// let mut mesh = GpuMesh::new(device, &scene.mesh, &scene.moving_parts);
/// // Frame 3 of a 10-frame sequence; motion vectors lead back to frame 2.
/// mesh.place(queue, 3.0 / 9.0, 2.0 / 9.0);
/// # Ok(()) }
/// ```
pub struct GpuMesh {
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
    parts: Vec<RestPart>,
    /// The times the moving parts are placed at: (this frame, previous frame).
    placed: (f32, f32),
}

impl GpuMesh {
    /// Vertex layout of all attributes: position, normal, albedo, previous position.
    fn layout() -> wgpu::VertexBufferLayout<'static> {
        const ATTRIBUTES: [wgpu::VertexAttribute; 4] = wgpu::vertex_attr_array![
            0 => Float32x3, 1 => Float32x3, 2 => Float32x3, 3 => Float32x3
        ];
        wgpu::VertexBufferLayout {
            array_stride: std::mem::size_of::<GpuVertex>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &ATTRIBUTES,
        }
    }

    /// Vertex layout of the position alone, for depth-only passes.
    pub(crate) fn position_layout() -> wgpu::VertexBufferLayout<'static> {
        wgpu::VertexBufferLayout {
            attributes: &Self::layout().attributes[..1],
            ..Self::layout()
        }
    }

    /// Binds the buffers and draws every triangle.
    pub(crate) fn draw(&self, pass: &mut wgpu::RenderPass<'_>) {
        pass.set_vertex_buffer(0, self.vertices.slice(..));
        pass.set_index_buffer(self.indices.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(0..self.index_count, 0, 0..1);
    }

    /// Uploads `mesh` with `moving_parts` (ranges of its vertices) at rest, at time 0.
    ///
    /// ```no_run
    /// use aokit_scene::{Builtin, gbuffer::GpuMesh};
    /// let gpu = aokit::GpuContext::headless()?;
    /// let scene = Builtin::Stairs.build();
    /// let mesh = GpuMesh::new(&gpu.device, &scene.mesh, &scene.moving_parts);
    /// # Ok::<(), aokit::GpuError>(())
    /// ```
    pub fn new(device: &wgpu::Device, mesh: &Mesh, moving_parts: &[MovingPart]) -> Self {
        let vertices: Vec<GpuVertex> = (0..mesh.positions.len())
            .map(|i| GpuVertex::of(mesh, i))
            .collect();
        let parts = moving_parts
            .iter()
            .map(|part| RestPart {
                first_vertex: part.vertices.start,
                motion: part.motion,
                vertices: vertices[part.vertices.start as usize..part.vertices.end as usize]
                    .to_vec(),
            })
            .collect();
        let vertices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("scene vertices"),
            contents: bytemuck::cast_slice(&vertices),
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
        });
        let indices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("scene indices"),
            contents: bytemuck::cast_slice(&wound_to_normals(mesh)),
            usage: wgpu::BufferUsages::INDEX,
        });
        Self {
            vertices,
            indices,
            index_count: mesh.indices.len() as u32,
            parts,
            placed: (0.0, 0.0),
        }
    }

    /// Places the moving parts where they are at `time`, remembering where they were at
    /// `previous_time` for the motion vectors, as [`Scene::mesh_at`](crate::Scene::mesh_at)
    /// places them. Takes effect for passes submitted afterwards.
    ///
    /// ```no_run
    /// # fn f(queue: &wgpu::Queue, mesh: &mut aokit_scene::gbuffer::GpuMesh) {
    /// let frames: u32 = 30;
    /// for frame in 0..frames {
    ///     let time = frame as f32 / (frames - 1) as f32;
    ///     let previous = frame.saturating_sub(1) as f32 / (frames - 1) as f32;
    ///     mesh.place(queue, time, previous);
    ///     // ... record and submit this frame's passes ...
    /// }
    /// # }
    /// ```
    pub fn place(&mut self, queue: &wgpu::Queue, time: f32, previous_time: f32) {
        if self.placed == (time, previous_time) {
            return;
        }
        for part in &self.parts {
            let (now, before) = (
                part.motion.transform_at(time),
                part.motion.transform_at(previous_time),
            );
            let placed: Vec<GpuVertex> = part
                .vertices
                .iter()
                .map(|v| {
                    let position = Vec3::from_array(v.position);
                    GpuVertex {
                        position: now.transform_point3(position).to_array(),
                        // Rigid motions turn normals as they turn directions.
                        normal: now.transform_vector3(Vec3::from_array(v.normal)).to_array(),
                        albedo: v.albedo,
                        previous_position: before.transform_point3(position).to_array(),
                    }
                })
                .collect();
            let offset = u64::from(part.first_vertex) * std::mem::size_of::<GpuVertex>() as u64;
            queue.write_buffer(&self.vertices, offset, bytemuck::cast_slice(&placed));
        }
        self.placed = (time, previous_time);
    }
}

/// The G-buffer textures for one resolution.
///
/// ```no_run
/// # fn f(gpu: &aokit::GpuContext, gbuffer: &aokit_scene::gbuffer::GBuffer)
/// #     -> Result<(), aokit::GpuError> {
/// use aokit::normals::decode_texels;
/// // The normals in their own encoding, decoded on the CPU.
/// let bytes = aokit::gpu::read_texture(&gpu.device, &gpu.queue, &gbuffer.normals)?;
/// let normals = decode_texels(gbuffer.encoding, &bytes);
/// assert_eq!(normals.len(), (gbuffer.size[0] * gbuffer.size[1]) as usize);
/// # Ok(()) }
/// ```
pub struct GBuffer {
    /// Width and height in pixels.
    pub size: [u32; 2],
    /// Hardware depth, as the projection's convention writes it.
    pub depth: wgpu::Texture,
    /// View-space normals, in [`GBuffer::encoding`]'s texture format.
    pub normals: wgpu::Texture,
    /// How [`GBuffer::normals`] is encoded.
    pub encoding: NormalEncoding,
    /// Albedo.
    pub albedo: wgpu::Texture,
    /// Motion vectors ([`MOTION_FORMAT`]): the offset in pixels from each pixel to where its
    /// surface was in the previous frame, moved by the camera and by its part's motion; 0
    /// where nothing was drawn.
    pub motion: wgpu::Texture,
    /// The depth of the nearest back faces ([`DEPTH_FORMAT`]), for
    /// [`AoInputs::back_depth`](aokit::AoInputs::back_depth), when made with
    /// [`GBuffer::with_back_depth`].
    pub back_depth: Option<wgpu::Texture>,
}

impl GBuffer {
    /// Allocates the targets, with normals in `encoding`.
    ///
    /// ```no_run
    /// use aokit::NormalEncoding;
    /// use aokit_scene::gbuffer::GBuffer;
    /// let gpu = aokit::GpuContext::headless()?;
    /// // A slim G-buffer: 16-bit octahedral normals.
    /// let gbuffer = GBuffer::new(&gpu.device, [1920, 1080], NormalEncoding::Oct16);
    /// assert_eq!(gbuffer.normals.format(), NormalEncoding::Oct16.texture_format());
    /// # Ok::<(), aokit::GpuError>(())
    /// ```
    pub fn new(device: &wgpu::Device, size: [u32; 2], encoding: NormalEncoding) -> Self {
        let usage = wgpu::TextureUsages::RENDER_ATTACHMENT
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC;
        let make = |label, format| create_texture_2d(device, label, size, format, usage);
        Self {
            size,
            depth: make("gbuffer depth", DEPTH_FORMAT),
            normals: make("gbuffer normals", encoding.texture_format()),
            encoding,
            albedo: make("gbuffer albedo", ALBEDO_FORMAT),
            motion: make("gbuffer motion", MOTION_FORMAT),
            back_depth: None,
        }
    }

    /// Adds [`GBuffer::back_depth`], which [`GBufferPass::encode`] then draws too.
    ///
    /// ```no_run
    /// use aokit::NormalEncoding;
    /// use aokit_scene::gbuffer::GBuffer;
    /// let gpu = aokit::GpuContext::headless()?;
    /// // For `vbao.back_faces`: one more depth target of the G-buffer's size.
    /// let gbuffer = GBuffer::new(&gpu.device, [1280, 720], NormalEncoding::Oct32)
    ///     .with_back_depth(&gpu.device);
    /// assert_eq!(gbuffer.back_depth.unwrap().size(), gbuffer.depth.size());
    /// # Ok::<(), aokit::GpuError>(())
    /// ```
    pub fn with_back_depth(self, device: &wgpu::Device) -> Self {
        let usage = wgpu::TextureUsages::RENDER_ATTACHMENT
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC;
        Self {
            back_depth: Some(create_texture_2d(
                device,
                "gbuffer back-face depth",
                self.size,
                DEPTH_FORMAT,
                usage,
            )),
            ..self
        }
    }
}

/// The camera a G-buffer is drawn with, and the one of the frame before.
///
/// ```
/// use aokit_scene::{Camera, gbuffer::GBufferCamera};
/// use glam::Vec3;
/// let bounds = aokit_scene::Scene::open("open").unwrap().bounds;
/// let before = Camera::perspective("c", Vec3::new(0.0, 2.0, 6.0), Vec3::ZERO, 60.0);
/// let now = Camera { eye: Vec3::new(0.2, 2.0, 6.0), ..before.clone() };
/// let projection = now.projection(16.0 / 9.0, &bounds);
/// let camera = GBufferCamera {
///     view_from_world: now.view_from_world(),
///     projection: &projection,
///     // The camera moved: motion vectors lead to where each surface was seen before.
///     previous_clip_from_world: before.projection(16.0 / 9.0, &bounds).clip_from_view()
///         * before.view_from_world(),
/// };
/// // A point nearer than the target both cameras look at: the eye moved right, so it moved
/// // left on screen (parallax), and the motion vector points back to the right.
/// let point = Vec3::new(0.0, 0.0, 3.0).extend(1.0);
/// let ndc = |clip: glam::Vec4| clip.truncate() / clip.w;
/// let was = ndc(camera.previous_clip_from_world * point);
/// let is = ndc(projection.clip_from_view() * camera.view_from_world * point);
/// assert!(is.x < was.x - 0.01, "{was} -> {is}");
/// ```
#[derive(Clone, Copy, Debug)]
pub struct GBufferCamera<'a> {
    /// World to view space this frame.
    pub view_from_world: Mat4,
    /// The projection this frame.
    pub projection: &'a Projection,
    /// World to clip space of the previous frame: projection times view. This frame's own
    /// for the first frame of a sequence, which then has no motion.
    pub previous_clip_from_world: Mat4,
}

/// Rasterises a [`GpuMesh`] into a [`GBuffer`].
///
/// ```no_run
/// # fn f(gpu: &aokit::GpuContext, mesh: &aokit_scene::gbuffer::GpuMesh,
/// #      camera: &aokit_scene::Camera, bounds: &aokit_scene::mesh::Bounds) {
/// use aokit::NormalEncoding;
/// use aokit_scene::gbuffer::{GBuffer, GBufferCamera, GBufferPass};
/// let mut pass = GBufferPass::new(&gpu.device);
/// let size = [800, 600];
/// let gbuffer = GBuffer::new(&gpu.device, size, NormalEncoding::Oct32);
/// let projection = camera.projection(800.0 / 600.0, bounds);
/// let view_from_world = camera.view_from_world();
/// let mut encoder = gpu.device.create_command_encoder(&Default::default());
/// pass.encode(gpu, &mut encoder, mesh, &GBufferCamera {
///     view_from_world,
///     projection: &projection,
///     // A still first frame: no motion.
///     previous_clip_from_world: projection.clip_from_view() * view_from_world,
/// }, &gbuffer);
/// gpu.queue.submit([encoder.finish()]);
/// # }
/// ```
pub struct GBufferPass {
    module: wgpu::ShaderModule,
    layout: wgpu::PipelineLayout,
    /// Per normal encoding, pipelines for standard (`[0]`) and reverse-Z (`[1]`) depth tests,
    /// made the first time the encoding is drawn.
    pipelines: HashMap<NormalEncoding, [wgpu::RenderPipeline; 2]>,
    /// Depth-only pipelines of the back faces, standard and reverse-Z, made the first time a
    /// G-buffer has [`GBuffer::back_depth`].
    back_pipelines: Option<[wgpu::RenderPipeline; 2]>,
    uniforms: UniformBlock<GBufferUniforms>,
}

impl GBufferPass {
    /// Compiles the shader; pipelines are made per normal encoding on first use.
    ///
    /// ```no_run
    /// let gpu = aokit::GpuContext::headless()?;
    /// let pass = aokit_scene::gbuffer::GBufferPass::new(&gpu.device);
    /// # Ok::<(), aokit::GpuError>(())
    /// ```
    pub fn new(device: &wgpu::Device) -> Self {
        let uniforms = UniformBlock::new(device, "gbuffer", wgpu::ShaderStages::VERTEX_FRAGMENT);
        Self {
            module: shaders::GBUFFER.create_module(device),
            layout: uniforms.pipeline_layout(device, "gbuffer"),
            pipelines: HashMap::new(),
            back_pipelines: None,
            uniforms,
        }
    }

    fn back_pipelines(&mut self, device: &wgpu::Device) -> &[wgpu::RenderPipeline; 2] {
        let (module, layout) = (&self.module, &self.layout);
        self.back_pipelines.get_or_insert_with(|| {
            // Triangles are wound towards their normals (`wound_to_normals`), so the culled
            // front faces are those whose normals face the eye.
            let raster = Raster {
                label: "gbuffer back faces",
                cull_mode: Some(wgpu::Face::Front),
                fragment: None,
            };
            raster.pipelines(device, module, layout)
        })
    }

    fn pipelines(
        &mut self,
        device: &wgpu::Device,
        encoding: NormalEncoding,
    ) -> &[wgpu::RenderPipeline; 2] {
        let (module, layout) = (&self.module, &self.layout);
        self.pipelines.entry(encoding).or_insert_with(|| {
            let constants = [("ENCODING", f64::from(encoding.shader_code()))];
            let targets = [
                Some(encoding.texture_format().into()),
                Some(ALBEDO_FORMAT.into()),
                Some(MOTION_FORMAT.into()),
            ];
            let raster = Raster {
                label: "gbuffer",
                // Both sides are drawn: scene files hold open sheets and mixed windings.
                cull_mode: None,
                fragment: Some(wgpu::FragmentState {
                    module,
                    entry_point: Some(if encoding.is_uint() {
                        "fs_uint"
                    } else {
                        "fs_float"
                    }),
                    compilation_options: wgpu::PipelineCompilationOptions {
                        constants: &constants,
                        ..Default::default()
                    },
                    targets: &targets,
                }),
            };
            raster.pipelines(device, module, layout)
        })
    }

    /// Records the raster of `mesh` seen by `camera`, clearing `target` first, and when it has
    /// [`GBuffer::back_depth`], the depth of its back faces. Then hand
    /// [`GBuffer::depth`] and [`GBuffer::normals`] to an [`aokit::AoPipeline`]:
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext, pass: &mut aokit_scene::gbuffer::GBufferPass,
    /// #      mesh: &aokit_scene::gbuffer::GpuMesh, gbuffer: &aokit_scene::gbuffer::GBuffer,
    /// #      camera: &aokit_scene::gbuffer::GBufferCamera<'_>,
    /// #      ao: &mut aokit::AoPipeline) -> Result<(), aokit::AoError> {
    /// use aokit::AoInputs;
    /// let mut encoder = gpu.device.create_command_encoder(&Default::default());
    /// pass.encode(gpu, &mut encoder, mesh, camera, gbuffer);
    /// let outputs = ao.encode(&gpu.device, &gpu.queue, &mut encoder, &AoInputs {
    ///     normals: Some((&gbuffer.normals).into()),
    ///     motion_vectors: Some((&gbuffer.motion).into()),
    ///     view_from_world: camera.view_from_world,
    ///     ..AoInputs::new(&gbuffer.depth, *camera.projection)
    /// })?;
    /// gpu.queue.submit([encoder.finish()]);
    /// # Ok(()) }
    /// ```
    pub fn encode(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &GpuMesh,
        camera: &GBufferCamera<'_>,
        target: &GBuffer,
    ) {
        let projection = camera.projection;
        let uniforms = GBufferUniforms {
            clip_from_world: (projection.clip_from_view() * camera.view_from_world)
                .to_cols_array_2d(),
            view_from_world: camera.view_from_world.to_cols_array_2d(),
            previous_clip_from_world: camera.previous_clip_from_world.to_cols_array_2d(),
            size: target.size.map(|side| side as f32),
            orthographic: if projection.is_orthographic() {
                1.0
            } else {
                0.0
            },
            _pad: 0.0,
        };
        self.uniforms.write(&gpu.queue, &uniforms);
        let reverse_z = usize::from(projection.reverse_z);
        let pipeline = self.pipelines(&gpu.device, target.encoding)[reverse_z].clone();
        let back_pipeline = target
            .back_depth
            .as_ref()
            .map(|_| self.back_pipelines(&gpu.device)[reverse_z].clone());
        let normals = target.normals.create_view(&Default::default());
        let albedo = target.albedo.create_view(&Default::default());
        let motion = target.motion.create_view(&Default::default());
        let color = |view| {
            Some(wgpu::RenderPassColorAttachment {
                view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                    store: wgpu::StoreOp::Store,
                },
            })
        };
        let draw = |encoder: &mut wgpu::CommandEncoder,
                    label,
                    pipeline: &wgpu::RenderPipeline,
                    colors: &[Option<wgpu::RenderPassColorAttachment<'_>>],
                    depth: &wgpu::Texture| {
            let depth = depth.create_view(&Default::default());
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some(label),
                color_attachments: colors,
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &depth,
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(projection.far_ndc_depth()),
                        store: wgpu::StoreOp::Store,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, self.uniforms.bind_group(), &[]);
            mesh.draw(&mut pass);
        };
        let colors = [color(&normals), color(&albedo), color(&motion)];
        draw(encoder, "gbuffer", &pipeline, &colors, &target.depth);
        if let (Some(back_depth), Some(pipeline)) = (&target.back_depth, &back_pipeline) {
            draw(encoder, "gbuffer back faces", pipeline, &[], back_depth);
        }
    }
}

/// What a G-buffer raster pipeline draws: the scene's vertices through `vs_main`, writing
/// depth, culling `cull_mode`, and `fragment`'s targets (none: depth alone).
struct Raster<'a> {
    label: &'static str,
    cull_mode: Option<wgpu::Face>,
    fragment: Option<wgpu::FragmentState<'a>>,
}

impl Raster<'_> {
    /// Its pipelines for standard (`[0]`) and reverse-Z (`[1]`) depth tests.
    fn pipelines(
        &self,
        device: &wgpu::Device,
        module: &wgpu::ShaderModule,
        layout: &wgpu::PipelineLayout,
    ) -> [wgpu::RenderPipeline; 2] {
        [wgpu::CompareFunction::Less, wgpu::CompareFunction::Greater].map(|compare| {
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(self.label),
                layout: Some(layout),
                vertex: wgpu::VertexState {
                    module,
                    entry_point: Some("vs_main"),
                    compilation_options: Default::default(),
                    buffers: &[Some(GpuMesh::layout())],
                },
                primitive: wgpu::PrimitiveState {
                    cull_mode: self.cull_mode,
                    ..Default::default()
                },
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: DEPTH_FORMAT,
                    depth_write_enabled: Some(true),
                    depth_compare: Some(compare),
                    stencil: Default::default(),
                    bias: Default::default(),
                }),
                multisample: Default::default(),
                fragment: self.fragment.clone(),
                multiview_mask: None,
                cache: None,
            })
        })
    }
}

/// `mesh`'s indices with every triangle wound so that its front face is the side its vertex
/// normals point to: the G-buffer shader then turns a normal by the rasteriser's facing alone
/// (gbuffer.wgsl, `shading_normal`). Files mix windings, and open sheets are seen from both
/// sides. A triangle whose normals sum to nothing along its face keeps its winding.
fn wound_to_normals(mesh: &Mesh) -> Vec<u32> {
    mesh.indices
        .chunks_exact(3)
        .flat_map(|t| {
            let [a, b, c] = [t[0], t[1], t[2]].map(|i| i as usize);
            let p = &mesh.positions;
            let face = (p[b] - p[a]).cross(p[c] - p[a]);
            let normals = mesh.normals[a] + mesh.normals[b] + mesh.normals[c];
            if face.dot(normals) < 0.0 {
                [t[0], t[2], t[1]]
            } else {
                [t[0], t[1], t[2]]
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangles_are_wound_towards_their_normals() {
        let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y];
        let mesh = |normal: Vec3| Mesh {
            positions: positions.clone(),
            normals: vec![normal; 3],
            albedo: vec![Vec3::ONE; 3],
            indices: vec![0, 1, 2],
        };
        // Counter-clockwise about +Z: kept for normals along +Z, turned for normals along -Z.
        assert_eq!(wound_to_normals(&mesh(Vec3::Z)), [0, 1, 2]);
        assert_eq!(wound_to_normals(&mesh(Vec3::NEG_Z)), [0, 2, 1]);
        // Normals in the triangle's plane say nothing: the file's winding stays.
        assert_eq!(wound_to_normals(&mesh(Vec3::X)), [0, 1, 2]);
    }

    #[test]
    fn uniforms_match_wgsl() {
        let fields = aokit::field_offsets!(GBufferUniforms {
            clip_from_world,
            view_from_world,
            previous_clip_from_world,
            size,
            orthographic,
        });
        aokit::shader::check_layout(
            &shaders::GBUFFER,
            "GBufferUniforms",
            fields,
            std::mem::size_of::<GBufferUniforms>(),
        )
        .unwrap();
    }
}
