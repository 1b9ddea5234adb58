//! One uniform buffer bound alone at group 0, the shape of every raster pass here.

use std::marker::PhantomData;

use aokit::gpu::create_uniform_buffer;
use bytemuck::Pod;

/// A uniform buffer of `T` with its bind group layout and bind group.
pub(crate) struct UniformBlock<T> {
    buffer: wgpu::Buffer,
    layout: wgpu::BindGroupLayout,
    bind_group: wgpu::BindGroup,
    contents: PhantomData<T>,
}

impl<T: Pod> UniformBlock<T> {
    /// Allocates the buffer, visible to the given stages at binding 0.
    pub fn new(device: &wgpu::Device, label: &str, visibility: wgpu::ShaderStages) -> Self {
        let buffer = create_uniform_buffer::<T>(device, label);
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some(label),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
                count: None,
            }],
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(label),
            layout: &layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: buffer.as_entire_binding(),
            }],
        });
        Self {
            buffer,
            layout,
            bind_group,
            contents: PhantomData,
        }
    }

    /// A pipeline layout with this block as its only bind group.
    pub fn pipeline_layout(&self, device: &wgpu::Device, label: &str) -> wgpu::PipelineLayout {
        device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(label),
            bind_group_layouts: &[Some(&self.layout)],
            immediate_size: 0,
        })
    }

    /// Uploads `value`; it applies to passes submitted afterwards.
    pub fn write(&self, queue: &wgpu::Queue, value: &T) {
        queue.write_buffer(&self.buffer, 0, bytemuck::bytes_of(value));
    }

    /// The bind group, for `set_bind_group(0, ..)`.
    pub fn bind_group(&self) -> &wgpu::BindGroup {
        &self.bind_group
    }
}
