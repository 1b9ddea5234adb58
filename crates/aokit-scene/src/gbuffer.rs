//! The G-buffer raster pass: depth (D32F), view-space normals in any
//! [`NormalEncoding`] and albedo. No MSAA.

use std::collections::HashMap;

use aokit::gpu::create_texture_2d;
use aokit::{GpuContext, NormalEncoding, Projection};
use bytemuck::{Pod, Zeroable};
use glam::Mat4;
use wgpu::util::DeviceExt;

use crate::mesh::Mesh;
use crate::shaders;
use crate::uniform_block::UniformBlock;

/// Depth format of the G-buffer.
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
/// Albedo, stored sRGB so 8 bits keep dark tones.
pub const ALBEDO_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;

#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct GpuVertex {
    position: [f32; 3],
    normal: [f32; 3],
    albedo: [f32; 3],
}

/// Mirrors `GBufferUniforms` in `shaders/gbuffer.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct GBufferUniforms {
    clip_from_world: [[f32; 4]; 4],
    view_from_world: [[f32; 4]; 4],
    orthographic: f32,
    _pad: [f32; 3],
}

/// A mesh uploaded to the GPU.
pub struct GpuMesh {
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
}

impl GpuMesh {
    /// Vertex layout of all attributes: position, normal, albedo.
    fn layout() -> wgpu::VertexBufferLayout<'static> {
        const ATTRIBUTES: [wgpu::VertexAttribute; 3] =
            wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x3];
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

    /// Uploads `mesh`.
    pub fn new(device: &wgpu::Device, mesh: &Mesh) -> Self {
        let vertices: Vec<GpuVertex> = (0..mesh.positions.len())
            .map(|i| GpuVertex {
                position: mesh.positions[i].to_array(),
                normal: mesh.normals[i].to_array(),
                albedo: mesh.albedo[i].to_array(),
            })
            .collect();
        let vertices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("scene vertices"),
            contents: bytemuck::cast_slice(&vertices),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let indices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("scene indices"),
            contents: bytemuck::cast_slice(&mesh.indices),
            usage: wgpu::BufferUsages::INDEX,
        });
        Self {
            vertices,
            indices,
            index_count: mesh.indices.len() as u32,
        }
    }
}

/// The G-buffer textures for one resolution.
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
}

impl GBuffer {
    /// Allocates the targets, with normals in `encoding`.
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
        }
    }
}

/// Rasterises a [`GpuMesh`] into a [`GBuffer`].
pub struct GBufferPass {
    module: wgpu::ShaderModule,
    layout: wgpu::PipelineLayout,
    /// Per normal encoding, pipelines for standard (`[0]`) and reverse-Z (`[1]`) depth tests,
    /// made the first time the encoding is drawn.
    pipelines: HashMap<NormalEncoding, [wgpu::RenderPipeline; 2]>,
    uniforms: UniformBlock<GBufferUniforms>,
}

impl GBufferPass {
    /// Compiles the shader; pipelines are made per normal encoding on first use.
    pub fn new(device: &wgpu::Device) -> Self {
        let uniforms = UniformBlock::new(device, "gbuffer", wgpu::ShaderStages::VERTEX_FRAGMENT);
        Self {
            module: shaders::GBUFFER.create_module(device),
            layout: uniforms.pipeline_layout(device, "gbuffer"),
            pipelines: HashMap::new(),
            uniforms,
        }
    }

    fn pipelines(
        &mut self,
        device: &wgpu::Device,
        encoding: NormalEncoding,
    ) -> &[wgpu::RenderPipeline; 2] {
        let (module, layout) = (&self.module, &self.layout);
        self.pipelines.entry(encoding).or_insert_with(|| {
            let constants = [("ENCODING", f64::from(encoding.shader_code()))];
            let pipeline = |compare| {
                device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                    label: Some("gbuffer"),
                    layout: Some(layout),
                    vertex: wgpu::VertexState {
                        module,
                        entry_point: Some("vs_main"),
                        compilation_options: Default::default(),
                        buffers: &[Some(GpuMesh::layout())],
                    },
                    primitive: wgpu::PrimitiveState {
                        // Both sides are drawn: scene files hold open sheets and mixed windings.
                        cull_mode: None,
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
                        targets: &[
                            Some(encoding.texture_format().into()),
                            Some(ALBEDO_FORMAT.into()),
                        ],
                    }),
                    multiview_mask: None,
                    cache: None,
                })
            };
            [
                pipeline(wgpu::CompareFunction::Less),
                pipeline(wgpu::CompareFunction::Greater),
            ]
        })
    }

    /// Records the raster of `mesh` seen through `view_from_world` and `projection`.
    pub fn encode(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &GpuMesh,
        view_from_world: Mat4,
        projection: &Projection,
        target: &GBuffer,
    ) {
        let uniforms = GBufferUniforms {
            clip_from_world: (projection.clip_from_view() * view_from_world).to_cols_array_2d(),
            view_from_world: view_from_world.to_cols_array_2d(),
            orthographic: if projection.is_orthographic() {
                1.0
            } else {
                0.0
            },
            _pad: [0.0; 3],
        };
        self.uniforms.write(&gpu.queue, &uniforms);
        let pipeline =
            self.pipelines(&gpu.device, target.encoding)[usize::from(projection.reverse_z)].clone();
        let normals = target.normals.create_view(&Default::default());
        let albedo = target.albedo.create_view(&Default::default());
        let depth = target.depth.create_view(&Default::default());
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
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("gbuffer"),
            color_attachments: &[color(&normals), color(&albedo)],
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
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, self.uniforms.bind_group(), &[]);
        mesh.draw(&mut pass);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniforms_match_wgsl() {
        let fields = aokit::field_offsets!(GBufferUniforms {
            clip_from_world,
            view_from_world,
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
