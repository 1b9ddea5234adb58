//! The renderer the examples share, standing in for yours: a few boxes, a column and a sphere on
//! a ground plane, drawn by a small headless forward renderer with a depth prepass and a lighting
//! pass. What it does for aokit is what its prepass writes: reverse-Z `Depth32Float` depth with
//! `TEXTURE_BINDING` usage, view-space normals in aokit's oct32 encoding and motion vectors. Each
//! example runs aokit between the two passes and brings the lighting shader that uses the AO.

use std::error::Error;
use std::fmt;
use std::path::{Path, PathBuf};

use aokit::{AoOutputs, GpuContext, Projection};
use glam::{Mat4, Quat, Vec3, Vec4};
use wgpu::util::DeviceExt;

pub type Result<T> = std::result::Result<T, Box<dyn Error>>;

/// Reverse-Z depth (near 1, far 0): a float format keeps precision far away that way.
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
/// View-space normals, oct32: aokit's default `NormalEncoding`, stored in `R32Uint`.
pub const NORMALS_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Uint;
/// Motion vectors in pixels: one of the formats `AoInputs::motion_vectors` takes.
pub const MOTION_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rg16Float;
/// The lit image: sRGB-encoded on write, so the PNG takes its bytes as they are.
pub const COLOR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;
/// Size when the command line names none.
const DEFAULT_SIZE: [u32; 2] = [960, 540];

/// Radiance of the sky (linear): the ambient light AO darkens, and the background.
const SKY: Vec3 = Vec3::new(0.45, 0.56, 0.72);
/// The sun: direction towards it (world space) and radiance.
const SUN_DIRECTION: Vec3 = Vec3::new(0.5, 0.8, 0.35);
const SUN: Vec3 = Vec3::new(0.6, 0.55, 0.48);

/// Where the examples' camera stands (it looks at a point between the boxes and the sphere).
const EYE: Vec3 = Vec3::new(0.6, 2.6, 5.6);
/// The box in front, where the tests look for contact shadow: centre, half extents, yaw.
const FRONT_BOX: (Vec3, Vec3, f32) = (Vec3::new(-1.5, 0.5, 0.2), Vec3::splat(0.5), 0.45);
/// Open ground, farther than the AO radius from everything, for the tests' comparison.
const OPEN_GROUND: Vec3 = Vec3::new(-1.2, 0.0, 2.8);

const SCENE_WGSL: &str = include_str!("scene.wgsl");

/// An example's body: renders a frame of the size given into the PNG path given.
pub type Run = fn(&GpuContext, &Path, [u32; 2]) -> Result<Stats>;

/// An example's `main`: `run` with the output path (first argument, else `NAME.png`) and size
/// (second argument, `WIDTHxHEIGHT`), then its one-line summary.
pub fn main(name: &str, run: Run) -> Result<()> {
    let mut args = std::env::args().skip(1);
    let out = PathBuf::from(args.next().unwrap_or_else(|| format!("{name}.png")));
    let size = match args.next() {
        Some(size) => {
            let (w, h) = size.split_once('x').ok_or("the size is WIDTHxHEIGHT")?;
            [w.parse()?, h.parse()?]
        }
        None => DEFAULT_SIZE,
    };
    println!("{name}: {}", run(&GpuContext::headless()?, &out, size)?);
    Ok(())
}

/// A bind group layout of `count` 2D float textures, bindings `0..count`, that the fragment
/// stage reads with `textureLoad`. Unfilterable: aokit's AO is `R32Float`, which is filterable
/// only with `Features::FLOAT32_FILTERABLE`, and it is read one texel per pixel anyway.
pub fn load_textures_layout(device: &wgpu::Device, count: u32) -> wgpu::BindGroupLayout {
    let entries: Vec<_> = (0..count)
        .map(|binding| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Float { filterable: false },
                view_dimension: wgpu::TextureViewDimension::D2,
                multisampled: false,
            },
            count: None,
        })
        .collect();
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("textures"),
        entries: &entries,
    })
}

/// A bind group of `views`, in order, for a [`load_textures_layout`] layout.
pub fn load_textures_group(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    views: &[&wgpu::TextureView],
) -> wgpu::BindGroup {
    let entries: Vec<_> = (0u32..)
        .zip(views)
        .map(|(binding, view)| wgpu::BindGroupEntry {
            binding,
            resource: wgpu::BindingResource::TextureView(view),
        })
        .collect();
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("textures"),
        layout,
        entries: &entries,
    })
}

/// The camera: what aokit needs to know of it is the view transform and the projection.
pub struct Camera {
    /// World to view space: right-handed, looking down -Z.
    pub view_from_world: Mat4,
    /// Perspective, reverse-Z, infinite far plane: `clip_from_view` gives the matrix.
    pub projection: Projection,
}

impl Camera {
    fn new(size: [u32; 2]) -> Self {
        Self::orbiting(0.0, size)
    }

    /// The examples' view turned by `degrees` (counter-clockwise seen from above) about the
    /// vertical axis through the point it looks at, for an image of `size` pixels.
    pub fn orbiting(degrees: f32, size: [u32; 2]) -> Self {
        let target = Vec3::new(-0.2, 0.5, 0.0);
        let eye = target + Quat::from_rotation_y(degrees.to_radians()) * (EYE - target);
        Self {
            view_from_world: glam::camera::rh::view::look_at_mat4(eye, target, Vec3::Y),
            projection: Projection::perspective(
                50f32.to_radians(),
                size[0] as f32 / size[1] as f32,
                0.1,
                None,
            ),
        }
    }

    pub fn clip_from_world(&self) -> Mat4 {
        self.projection.clip_from_view() * self.view_from_world
    }

    /// The pixel `world` projects to, when it is on screen.
    fn pixel(&self, world: Vec3, size: [u32; 2]) -> Option<[u32; 2]> {
        let clip = self.clip_from_world() * world.extend(1.0);
        let ndc = clip.truncate().truncate() / clip.w;
        let x = (ndc.x * 0.5 + 0.5) * size[0] as f32;
        let y = (0.5 - ndc.y * 0.5) * size[1] as f32;
        let inside = clip.w > 0.0 && (0.0..size[0] as f32).contains(&x);
        (inside && (0.0..size[1] as f32).contains(&y)).then_some([x as u32, y as u32])
    }
}

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct Vertex {
    position: [f32; 3],
    normal: [f32; 3],
    albedo: [f32; 3],
    roughness: f32,
}

/// Linear albedo and perceptual roughness.
#[derive(Clone, Copy)]
struct Material(Vec3, f32);

#[derive(Default)]
struct Mesh {
    vertices: Vec<Vertex>,
    indices: Vec<u32>,
}

impl Mesh {
    fn vertex(
        &mut self,
        position: Vec3,
        normal: Vec3,
        Material(albedo, roughness): Material,
    ) -> u32 {
        self.vertices.push(Vertex {
            position: position.into(),
            normal: normal.into(),
            albedo: albedo.into(),
            roughness,
        });
        self.vertices.len() as u32 - 1
    }

    /// A triangle, wound counter-clockwise seen from the side its vertex normals point to.
    fn triangle(&mut self, [a, b, c]: [u32; 3]) {
        let vertex = |i: u32| self.vertices[i as usize];
        let p = |i: u32| Vec3::from(vertex(i).position);
        let normal: Vec3 = [a, b, c].map(|i| Vec3::from(vertex(i).normal)).iter().sum();
        let front = (p(b) - p(a)).cross(p(c) - p(a)).dot(normal) >= 0.0;
        self.indices
            .extend(if front { [a, b, c] } else { [a, c, b] });
    }

    fn quad(&mut self, corners: [Vec3; 4], normal: Vec3, material: Material) {
        let [a, b, c, d] = corners.map(|p| self.vertex(p, normal, material));
        self.triangle([a, b, c]);
        self.triangle([a, c, d]);
    }

    /// A box of half extents `half` around `center`, turned by `yaw` radians about +Y.
    fn cuboid(&mut self, (center, half, yaw): (Vec3, Vec3, f32), material: Material) {
        let turn = Quat::from_rotation_y(yaw);
        for n in [
            Vec3::X,
            Vec3::NEG_X,
            Vec3::Y,
            Vec3::NEG_Y,
            Vec3::Z,
            Vec3::NEG_Z,
        ] {
            let (u, v) = n.any_orthonormal_pair();
            let corner = |s: f32, t: f32| center + turn * ((n + s * u + t * v) * half);
            let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
            self.quad(corners.map(|(s, t)| corner(s, t)), turn * n, material);
        }
    }

    fn sphere(&mut self, center: Vec3, radius: f32, material: Material) {
        const RINGS: u32 = 24;
        const SEGMENTS: u32 = 48;
        let first = self.vertices.len() as u32;
        for ring in 0..=RINGS {
            for segment in 0..=SEGMENTS {
                let theta = std::f32::consts::PI * ring as f32 / RINGS as f32;
                let phi = std::f32::consts::TAU * segment as f32 / SEGMENTS as f32;
                let n = Vec3::new(
                    theta.sin() * phi.cos(),
                    theta.cos(),
                    theta.sin() * phi.sin(),
                );
                self.vertex(center + radius * n, n, material);
            }
        }
        for ring in 0..RINGS {
            for segment in 0..SEGMENTS {
                let a = first + ring * (SEGMENTS + 1) + segment;
                let b = a + SEGMENTS + 1;
                self.triangle([a, b, a + 1]);
                self.triangle([a + 1, b, b + 1]);
            }
        }
    }

    /// Boxes, one stacked on another, a column and a sphere standing on a ground plane.
    fn scene() -> Self {
        let mut mesh = Self::default();
        let ground = Material(Vec3::splat(0.55), 0.5);
        let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
        let ground_corners = corners.map(|(x, z)| Vec3::new(50.0 * x, 0.0, 50.0 * z));
        mesh.quad(ground_corners, Vec3::Y, ground);
        mesh.cuboid(FRONT_BOX, Material(Vec3::new(0.7, 0.22, 0.15), 0.6));
        let small_box = (Vec3::new(-1.45, 1.25, 0.15), Vec3::splat(0.25), -0.3);
        mesh.cuboid(small_box, Material(Vec3::new(0.8, 0.65, 0.2), 0.4));
        let column = (Vec3::new(1.5, 1.1, -1.0), Vec3::new(0.35, 1.1, 0.35), 0.0);
        mesh.cuboid(column, Material(Vec3::new(0.85, 0.85, 0.8), 0.25));
        mesh.sphere(
            Vec3::new(0.3, 0.55, 1.0),
            0.55,
            Material(Vec3::new(0.15, 0.3, 0.7), 0.2),
        );
        mesh
    }
}

/// Mirrors `Frame` in scene.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct FrameUniforms {
    clip_from_world: Mat4,
    view_from_world: Mat4,
    sun_direction: Vec4,
    sun_color: Vec4,
    sky_color: Vec4,
    previous_clip_from_world: Mat4,
    size: Vec4,
}

impl FrameUniforms {
    /// `previous_clip_from_world`: the camera the last frame was drawn with, `None` on a first
    /// frame or after a cut (no motion then).
    fn new(camera: &Camera, previous_clip_from_world: Option<Mat4>, size: [u32; 2]) -> Self {
        let clip_from_world = camera.clip_from_world();
        Self {
            clip_from_world,
            view_from_world: camera.view_from_world,
            sun_direction: camera
                .view_from_world
                .transform_vector3(SUN_DIRECTION.normalize())
                .extend(0.0),
            sun_color: SUN.extend(1.0),
            sky_color: SKY.extend(1.0),
            previous_clip_from_world: previous_clip_from_world.unwrap_or(clip_from_world),
            size: Vec4::new(size[0] as f32, size[1] as f32, 0.0, 0.0),
        }
    }
}

/// The render targets, all of the window's size: what a resize makes again.
struct Targets {
    depth: wgpu::Texture,
    normals: wgpu::Texture,
    motion: wgpu::Texture,
    color: wgpu::Texture,
}

impl Targets {
    fn new(device: &wgpu::Device, size: [u32; 2]) -> Self {
        let target = |label, format, usage| {
            aokit::gpu::create_texture_2d(device, label, size, format, usage)
        };
        // TEXTURE_BINDING on depth, normals and motion vectors: aokit's compute passes read them.
        let attachment = wgpu::TextureUsages::RENDER_ATTACHMENT;
        let read = attachment | wgpu::TextureUsages::TEXTURE_BINDING;
        Self {
            depth: target("depth", DEPTH_FORMAT, read),
            normals: target("normals", NORMALS_FORMAT, read),
            motion: target("motion", MOTION_FORMAT, read),
            color: target(
                "color",
                COLOR_FORMAT,
                attachment | wgpu::TextureUsages::COPY_SRC,
            ),
        }
    }
}

/// The forward renderer: its targets, geometry and the two passes' pipelines.
pub struct Renderer {
    pub size: [u32; 2],
    pub camera: Camera,
    /// Reverse-Z depth from the prepass, `RENDER_ATTACHMENT | TEXTURE_BINDING`.
    pub depth: wgpu::Texture,
    /// oct32 view-space normals from the prepass, `RENDER_ATTACHMENT | TEXTURE_BINDING`.
    pub normals: wgpu::Texture,
    /// Motion vectors from the prepass (`MOTION_FORMAT`), `RENDER_ATTACHMENT | TEXTURE_BINDING`:
    /// 0 everywhere until [`Renderer::set_camera`] names a previous camera.
    pub motion: wgpu::Texture,
    color: wgpu::Texture,
    #[allow(
        dead_code,
        reason = "written by `set_camera`, which only `frame_loop` calls"
    )]
    uniforms: wgpu::Buffer,
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
    frame: wgpu::BindGroup,
    prepass: wgpu::RenderPipeline,
    lighting: wgpu::RenderPipeline,
}

impl Renderer {
    /// The renderer with the example's lighting shader, `lighting` (WGSL pieces, concatenated,
    /// defining `fs_lighting`), which reads what `lighting_layout` binds as group 1.
    pub fn new(
        device: &wgpu::Device,
        size: [u32; 2],
        lighting: &[&str],
        lighting_layout: &wgpu::BindGroupLayout,
    ) -> Self {
        let camera = Camera::new(size);
        let mesh = Mesh::scene();
        let buffer = |label, contents: &[u8], usage| {
            let descriptor = wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents,
                usage,
            };
            device.create_buffer_init(&descriptor)
        };
        let vertices = buffer(
            "vertices",
            bytemuck::cast_slice(&mesh.vertices),
            wgpu::BufferUsages::VERTEX,
        );
        let indices = buffer(
            "indices",
            bytemuck::cast_slice(&mesh.indices),
            wgpu::BufferUsages::INDEX,
        );
        let uniforms = FrameUniforms::new(&camera, None, size);
        let uniforms = buffer(
            "frame",
            bytemuck::bytes_of(&uniforms),
            wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        );
        let frame_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("frame"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
                count: None,
            }],
        });
        let frame = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("frame"),
            layout: &frame_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: uniforms.as_entire_binding(),
            }],
        });

        // One module for both passes. aokit's `shader::ENCODING` goes first: the prepass
        // writes normals with its `pack_oct32`, exactly as aokit decodes them.
        let source = [&[aokit::shader::ENCODING, SCENE_WGSL], lighting].concat();
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("scene"),
            source: wgpu::ShaderSource::Wgsl(source.join("\n").into()),
        });
        let pipeline = |fragment,
                        layouts: &[Option<&wgpu::BindGroupLayout>],
                        formats: &[wgpu::TextureFormat],
                        compare| {
            let targets: Vec<_> = formats.iter().map(|&f| Some(f.into())).collect();
            let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some(fragment),
                bind_group_layouts: layouts,
                immediate_size: 0,
            });
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(fragment),
                layout: Some(&layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs_main"),
                    compilation_options: Default::default(),
                    buffers: &[Some(wgpu::VertexBufferLayout {
                        array_stride: std::mem::size_of::<Vertex>() as u64,
                        step_mode: wgpu::VertexStepMode::Vertex,
                        attributes: &wgpu::vertex_attr_array![
                            0 => Float32x3, 1 => Float32x3, 2 => Float32x3, 3 => Float32
                        ],
                    })],
                },
                primitive: wgpu::PrimitiveState {
                    cull_mode: Some(wgpu::Face::Back),
                    ..Default::default()
                },
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: DEPTH_FORMAT,
                    // The prepass writes depth; the lighting pass only tests against it.
                    depth_write_enabled: Some(compare == wgpu::CompareFunction::Greater),
                    depth_compare: Some(compare),
                    stencil: Default::default(),
                    bias: Default::default(),
                }),
                multisample: Default::default(),
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some(fragment),
                    compilation_options: Default::default(),
                    targets: &targets,
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        // Reverse-Z: nearer is greater. The lighting pass keeps the fragments the prepass kept.
        let prepass = pipeline(
            "fs_prepass",
            &[Some(&frame_layout)],
            &[NORMALS_FORMAT, MOTION_FORMAT],
            wgpu::CompareFunction::Greater,
        );
        let lighting = pipeline(
            "fs_lighting",
            &[Some(&frame_layout), Some(lighting_layout)],
            &[COLOR_FORMAT],
            wgpu::CompareFunction::GreaterEqual,
        );

        let Targets {
            depth,
            normals,
            motion,
            color,
        } = Targets::new(device, size);
        Self {
            size,
            camera,
            depth,
            normals,
            motion,
            color,
            uniforms,
            vertices,
            indices,
            index_count: mesh.indices.len() as u32,
            frame,
            prepass,
            lighting,
        }
    }

    /// Records the depth prepass: depth, cleared to the far plane (0, reverse-Z), normals and
    /// motion vectors (0 where nothing is drawn).
    pub fn prepass(&self, encoder: &mut wgpu::CommandEncoder) {
        let clear = wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT);
        let groups = [&self.frame];
        self.draw(
            encoder,
            &self.prepass,
            &[&self.normals, &self.motion],
            clear,
            wgpu::LoadOp::Clear(0.0),
            &groups,
        );
    }

    /// Records the lighting pass over the prepass's depth, with `group` as bind group 1.
    pub fn lighting(&self, encoder: &mut wgpu::CommandEncoder, group: &wgpu::BindGroup) {
        let sky = wgpu::Color {
            r: SKY.x.into(),
            g: SKY.y.into(),
            b: SKY.z.into(),
            a: 1.0,
        };
        let clear = wgpu::LoadOp::Clear(sky);
        let groups = [&self.frame, group];
        self.draw(
            encoder,
            &self.lighting,
            &[&self.color],
            clear,
            wgpu::LoadOp::Load,
            &groups,
        );
    }

    fn draw(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        pipeline: &wgpu::RenderPipeline,
        targets: &[&wgpu::Texture],
        load: wgpu::LoadOp<wgpu::Color>,
        depth_load: wgpu::LoadOp<f32>,
        groups: &[&wgpu::BindGroup],
    ) {
        let views: Vec<_> = targets
            .iter()
            .map(|t| t.create_view(&Default::default()))
            .collect();
        let attachments: Vec<_> = views
            .iter()
            .map(|view| {
                Some(wgpu::RenderPassColorAttachment {
                    view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load,
                        store: wgpu::StoreOp::Store,
                    },
                })
            })
            .collect();
        let depth = self.depth.create_view(&Default::default());
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: None,
            color_attachments: &attachments,
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &depth,
                depth_ops: Some(wgpu::Operations {
                    load: depth_load,
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_pipeline(pipeline);
        for (index, group) in (0u32..).zip(groups) {
            pass.set_bind_group(index, *group, &[]);
        }
        pass.set_vertex_buffer(0, self.vertices.slice(..));
        pass.set_index_buffer(self.indices.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(0..self.index_count, 0, 0..1);
    }

    /// Submits the frame, writes the lit image to `path` as PNG and measures it and the AO.
    pub fn finish(
        &self,
        gpu: &GpuContext,
        encoder: wgpu::CommandEncoder,
        ao: &AoOutputs<'_>,
        path: &Path,
    ) -> Result<Stats> {
        let (device, queue) = (&gpu.device, &gpu.queue);
        queue.submit([encoder.finish()]);
        let rgba = aokit::gpu::read_texture(device, queue, &self.color)?;
        let [width, height] = self.size;
        image::save_buffer(path, &rgba, width, height, image::ExtendedColorType::Rgba8)?;
        let values = aokit::gpu::read_texture_f32(device, queue, ao.ao)?;
        // aokit's linear depth is 0 where nothing was drawn.
        let depth = aokit::gpu::read_texture_f32(device, queue, ao.linear_depth)?;
        let covered: Vec<bool> = depth.iter().map(|&d| d > 0.0 && d.is_finite()).collect();
        let rgb = |i: usize| [0, 1, 2].map(|c| rgba[4 * i + c]);
        let sky = SKY.to_array().map(srgb_byte);
        let pixels = 0..covered.len();
        let on_surface = || pixels.clone().filter(|&i| covered[i]);
        let count = on_surface().count();
        // Mean AO and brightness of the surface pixels at and just below `world`.
        let window = |world: Vec3| {
            let [x, y] = self.camera.pixel(world, self.size)?;
            let rows = y..(y + 3).min(height);
            let columns = x.saturating_sub(1)..(x + 2).min(width);
            let at = rows.flat_map(|y| columns.clone().map(move |x| (y * width + x) as usize));
            let at: Vec<usize> = at.filter(|&i| covered[i]).collect();
            let mean =
                |f: &dyn Fn(usize) -> f32| at.iter().map(|&i| f(i)).sum::<f32>() / at.len() as f32;
            let luma = |i: usize| rgb(i).iter().map(|&c| f32::from(c)).sum::<f32>() / 765.0;
            Some((mean(&|i| values[i]), mean(&luma)))
        };
        let nan = (f32::NAN, f32::NAN);
        // On the ground 0.1 in front of the middle of the front box's face towards the camera.
        let (center, half, yaw) = FRONT_BOX;
        let contact = Vec3::new(center.x, 0.0, center.z)
            + Quat::from_rotation_y(yaw) * Vec3::new(0.0, 0.0, half.z + 0.1);
        Ok(Stats {
            size: self.size,
            path: path.to_owned(),
            covered: count,
            mean_ao: on_surface().map(|i| values[i]).sum::<f32>() / count as f32,
            contact: window(contact).unwrap_or(nan),
            open: window(OPEN_GROUND).unwrap_or(nan),
            bad_ao: on_surface()
                .filter(|&i| !(0.0..=1.0).contains(&values[i]))
                .count(),
            black: on_surface().filter(|&i| rgb(i) == [0; 3]).count(),
            sky_changed: pixels
                .filter(|&i| !covered[i])
                .filter(|&i| (0..3).any(|c| rgb(i)[c].abs_diff(sky[c]) > 1))
                .count(),
        })
    }
}

/// What a frame loop adds: a camera per frame, and a window that changes size.
#[allow(
    dead_code,
    reason = "`frame_loop` calls these; the other examples draw one frame of one camera"
)]
impl Renderer {
    /// Makes the targets again at a new window size. The geometry and pipelines stay; the
    /// caller sets a camera of the new aspect ratio next.
    pub fn resize(&mut self, device: &wgpu::Device, size: [u32; 2]) {
        let targets = Targets::new(device, size);
        (self.depth, self.normals) = (targets.depth, targets.normals);
        (self.motion, self.color) = (targets.motion, targets.color);
        self.size = size;
    }

    /// This frame's camera, and the one the previous frame was drawn with (`None` on a first
    /// frame or a cut) for the motion vectors.
    pub fn set_camera(&mut self, queue: &wgpu::Queue, camera: Camera, previous: Option<Mat4>) {
        let uniforms = FrameUniforms::new(&camera, previous, self.size);
        queue.write_buffer(&self.uniforms, 0, bytemuck::bytes_of(&uniforms));
        self.camera = camera;
    }
}

/// A linear value in [0, 1] as its sRGB byte.
fn srgb_byte(linear: f32) -> u8 {
    let encoded = if linear <= 0.003_130_8 {
        12.92 * linear
    } else {
        1.055 * linear.powf(1.0 / 2.4) - 0.055
    };
    (encoded * 255.0).round() as u8
}

/// What a run produced, measured.
#[derive(Debug)]
pub struct Stats {
    pub size: [u32; 2],
    pub path: PathBuf,
    /// Pixels with a surface.
    pub covered: usize,
    /// Mean AO over them.
    pub mean_ao: f32,
    /// Mean AO and brightness (0 to 1) on the ground where the front box stands on it...
    pub contact: (f32, f32),
    /// ...and on open ground.
    pub open: (f32, f32),
    /// Surface pixels with AO outside [0, 1] (NaN included).
    pub bad_ao: usize,
    /// Surface pixels lit pure black, the colour a NaN in the lighting turns into.
    pub black: usize,
    /// Background pixels that are not the sky colour.
    pub sky_changed: usize,
}

impl fmt::Display for Stats {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let [w, h] = self.size;
        write!(
            f,
            "{w}x{h}: mean AO {:.3} over {} covered pixels (at a box's foot {:.3}, open ground \
             {:.3}) -> {}",
            self.mean_ao,
            self.covered,
            self.contact.0,
            self.open.0,
            self.path.display()
        )?;
        if self.bad_ao + self.black + self.sky_changed > 0 {
            write!(
                f,
                "; WRONG: {} pixels with AO outside [0, 1], {} black, {} of the sky changed",
                self.bad_ao, self.black, self.sky_changed
            )?;
        }
        Ok(())
    }
}

/// The test of each example that includes this module (`cargo test` runs the examples' tests:
/// `test = true` in Cargo.toml).
#[cfg(test)]
mod tests {
    use super::*;

    /// The example's `run` at a small size writes a PNG of that size with AO that darkens the
    /// ground at a box's foot, in the AO and in the lit image, and no NaN or changed sky anywhere.
    #[test]
    fn example_renders_contact_shadows() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("example.png");
        let gpu = GpuContext::headless().unwrap();
        let stats = crate::run(&gpu, &path, [160, 90]).unwrap();
        let image = image::open(&path).unwrap();
        assert_eq!([image.width(), image.height()], [160, 90]);
        assert!(stats.covered > 160 * 90 / 2, "{stats:?}");
        assert!(stats.covered < 160 * 90, "no sky: {stats:?}");
        assert_eq!(
            [stats.bad_ao, stats.black, stats.sky_changed],
            [0; 3],
            "{stats:?}"
        );
        assert!(stats.open.0 > 0.9, "{stats:?}");
        assert!(stats.contact.0 < stats.open.0 - 0.15, "{stats:?}");
        // In the lit image too (sRGB brightness; 0.045 to 0.05 lower when measured).
        assert!(stats.contact.1 < stats.open.1 - 0.02, "{stats:?}");
    }
}
