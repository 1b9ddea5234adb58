//! The window's GPU: a device on an adapter that can present to the window's surface, the
//! surface's configuration, and reading back what was drawn (for `--screenshot`).

use std::sync::Arc;

use anyhow::{Context, Result};
use aokit::GpuContext;
use winit::window::Window;

/// A device that presents to a window, and the surface it presents to.
pub struct WindowGpu {
    /// The device, queue and adapter, as the scene renderer and the AO pipeline take them.
    pub gpu: GpuContext,
    /// The window's surface.
    pub surface: wgpu::Surface<'static>,
    /// How the surface is configured (size, format).
    pub config: wgpu::SurfaceConfiguration,
}

impl WindowGpu {
    /// Opens a device on an adapter compatible with `window`'s surface, with the features the
    /// headless tools ask for where the adapter has them (timestamps, R16Float storage), and
    /// configures the surface at the window's size.
    pub fn new(window: Arc<Window>) -> Result<Self> {
        let descriptor =
            wgpu::InstanceDescriptor::new_with_display_handle_from_env(Box::new(window.clone()));
        let instance = wgpu::Instance::new(descriptor);
        let surface = instance
            .create_surface(window.clone())
            .context("cannot create a surface for the window")?;
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            force_fallback_adapter: false,
            compatible_surface: Some(&surface),
            ..Default::default()
        }))
        .context("no GPU adapter can present to this window")?;
        let fp16_storage = adapter
            .get_texture_format_features(wgpu::TextureFormat::R16Float)
            .flags
            .contains(wgpu::TextureFormatFeatureFlags::STORAGE_WRITE_ONLY);
        let mut wanted = wgpu::Features::TIMESTAMP_QUERY;
        if fp16_storage {
            wanted |= wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES;
        }
        let adapter_info = adapter.get_info();
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("aokit view"),
            required_features: adapter.features() & wanted,
            required_limits: adapter.limits(),
            ..Default::default()
        }))
        .with_context(|| format!("cannot open a device on {}", adapter_info.name))?;
        let size = window.inner_size();
        let capabilities = surface.get_capabilities(&adapter);
        // egui draws in gamma space into a plain 8-bit target; any the surface has will do.
        let format = capabilities
            .formats
            .iter()
            .copied()
            .find(|f| {
                matches!(
                    f,
                    wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Rgba8Unorm
                )
            })
            .or_else(|| capabilities.formats.first().copied())
            .context("the window's surface offers no format")?;
        let config = wgpu::SurfaceConfiguration {
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            format,
            width: size.width.max(1),
            height: size.height.max(1),
            present_mode: wgpu::PresentMode::AutoVsync,
            desired_maximum_frame_latency: 2,
            alpha_mode: capabilities
                .alpha_modes
                .first()
                .copied()
                .unwrap_or(wgpu::CompositeAlphaMode::Auto),
            view_formats: Vec::new(),
            color_space: Default::default(),
        };
        surface.configure(&device, &config);
        Ok(Self {
            gpu: GpuContext {
                device,
                queue,
                adapter_info,
            },
            surface,
            config,
        })
    }

    /// Configures the surface for a window now `width` x `height` pixels.
    pub fn resize(&mut self, width: u32, height: u32) {
        self.config.width = width.max(1);
        self.config.height = height.max(1);
        self.surface.configure(&self.gpu.device, &self.config);
    }

    /// A texture like the surface's (format and size) that can be read back: the screenshot
    /// draws the same frame into it.
    pub fn capture_target(&self) -> wgpu::Texture {
        self.gpu.device.create_texture(&wgpu::TextureDescriptor {
            label: Some("aokit view screenshot"),
            size: wgpu::Extent3d {
                width: self.config.width,
                height: self.config.height,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: self.config.format,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        })
    }

    /// Reads back `target` (from [`WindowGpu::capture_target`]) as RGBA8, row by row from the
    /// top.
    pub fn read_rgba(&self, target: &wgpu::Texture) -> Result<Vec<u8>> {
        let mut bytes = aokit::gpu::read_texture(&self.gpu.device, &self.gpu.queue, target)?;
        if matches!(
            target.format(),
            wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb
        ) {
            for texel in bytes.chunks_exact_mut(4) {
                texel.swap(0, 2);
            }
        }
        Ok(bytes)
    }
}
