//! Bind group layouts checked against the `@group(0) @binding(n)` declarations of a program.

use wgpu::naga;

use super::ShaderSource;

/// Checks that `entries`, the bind group layout a pass builds for `source`, declare exactly
/// the program's bindings, all at group 0, each of the kind the WGSL declares: a uniform or
/// storage buffer, a texture of its sample type, dimension and sample count, a storage texture
/// of its format and access, or a sampler. What WGSL does not say (whether a float texture or
/// a sampler filters, a buffer's dynamic offset or minimum size) is not compared.
///
/// ```
/// use aokit::passes::bind;
/// use aokit::shader;
/// // `linear_depth`'s layout for hardware depth: view uniforms, the depth, the linear depth.
/// let float = wgpu::TextureSampleType::Float { filterable: false };
/// let mut entries = vec![
///     bind::uniform(0),
///     bind::texture(1, float),
///     bind::storage_texture(2, wgpu::TextureFormat::R32Float),
/// ];
/// shader::check_bindings(&shader::LINEAR_DEPTH[0], &entries)?;
/// // The multisampled program's binding 1 is a `texture_multisampled_2d<f32>`.
/// let err = shader::check_bindings(&shader::LINEAR_DEPTH[1], &entries).unwrap_err();
/// assert!(err.contains("binding 1 differs"), "{err}");
/// entries.pop();
/// assert!(shader::check_bindings(&shader::LINEAR_DEPTH[0], &entries).is_err());
/// # Ok::<(), String>(())
/// ```
pub fn check_bindings(
    source: &ShaderSource,
    entries: &[wgpu::BindGroupLayoutEntry],
) -> Result<(), String> {
    let module = source.validate()?;
    let mut wgsl = Vec::new();
    for (_, global) in module.global_variables.iter() {
        let Some(naga::ResourceBinding { group, binding }) = global.binding else {
            continue;
        };
        let name = global.name.as_deref().unwrap_or("?");
        if group != 0 {
            return Err(format!("{}: `{name}` is in group {group}", source.name));
        }
        wgsl.push(
            Compared::of_wgsl(&module, binding, global)
                .map_err(|e| format!("{}: `{name}` at binding {binding}: {e}", source.name))?,
        );
    }
    wgsl.sort_by_key(|b| b.binding);
    let mut rust: Vec<Compared> = entries.iter().map(Compared::of_entry).collect();
    rust.sort_by_key(|b| b.binding);
    match wgsl.iter().zip(&rust).find(|(w, r)| w != r) {
        None if wgsl.len() == rust.len() => Ok(()),
        None => Err(format!(
            "{}: WGSL declares {} bindings, the layout {}: WGSL {wgsl:?}, Rust {rust:?}",
            source.name,
            wgsl.len(),
            rust.len()
        )),
        Some((w, r)) => Err(format!(
            "{}: binding {} differs: WGSL {w:?}, Rust {r:?}",
            source.name,
            w.binding.min(r.binding)
        )),
    }
}

/// A binding as compared: wgpu's type with what WGSL does not say set one way, and a storage
/// texture's format by name, since naga and wgpu type it apart but name every one alike
/// (`wgpu-naga-bridge` maps each name to itself).
#[derive(Debug, PartialEq)]
struct Compared {
    binding: u32,
    /// The type, a storage texture's format replaced by [`Compared::FORMAT_BY_NAME`].
    ty: wgpu::BindingType,
    storage_format: Option<String>,
}

impl Compared {
    const FORMAT_BY_NAME: wgpu::TextureFormat = wgpu::TextureFormat::R8Unorm;

    /// The layout entry `entry`.
    fn of_entry(entry: &wgpu::BindGroupLayoutEntry) -> Self {
        let (ty, storage_format) = match entry.ty {
            wgpu::BindingType::Buffer { ty, .. } => (buffer(ty), None),
            wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Float { .. },
                view_dimension,
                multisampled,
            } => (
                wgpu::BindingType::Texture {
                    sample_type: wgpu::TextureSampleType::Float { filterable: false },
                    view_dimension,
                    multisampled,
                },
                None,
            ),
            wgpu::BindingType::Sampler(
                wgpu::SamplerBindingType::Filtering | wgpu::SamplerBindingType::NonFiltering,
            ) => (
                wgpu::BindingType::Sampler(wgpu::SamplerBindingType::NonFiltering),
                None,
            ),
            wgpu::BindingType::StorageTexture {
                access,
                format,
                view_dimension,
            } => (
                wgpu::BindingType::StorageTexture {
                    access,
                    format: Self::FORMAT_BY_NAME,
                    view_dimension,
                },
                Some(format!("{format:?}")),
            ),
            ty => (ty, None),
        };
        Self {
            binding: entry.binding,
            ty,
            storage_format,
        }
    }

    /// The global variable `global` of `module`, declared at `binding`.
    fn of_wgsl(
        module: &naga::Module,
        binding: u32,
        global: &naga::GlobalVariable,
    ) -> Result<Self, String> {
        let mut storage_format = None;
        let ty = match (global.space, &module.types[global.ty].inner) {
            (naga::AddressSpace::Uniform, _) => buffer(wgpu::BufferBindingType::Uniform),
            (naga::AddressSpace::Storage { access }, _) => {
                buffer(wgpu::BufferBindingType::Storage {
                    read_only: !access.contains(naga::StorageAccess::STORE),
                })
            }
            (naga::AddressSpace::Handle, naga::TypeInner::Sampler { comparison }) => {
                wgpu::BindingType::Sampler(if *comparison {
                    wgpu::SamplerBindingType::Comparison
                } else {
                    wgpu::SamplerBindingType::NonFiltering
                })
            }
            (
                naga::AddressSpace::Handle,
                naga::TypeInner::Image {
                    dim,
                    arrayed,
                    class,
                },
            ) => {
                let view_dimension = view_dimension(*dim, *arrayed)?;
                let texture = |sample_type, multisampled| wgpu::BindingType::Texture {
                    sample_type,
                    view_dimension,
                    multisampled,
                };
                match *class {
                    naga::ImageClass::Sampled { kind, multi } => texture(sample_type(kind)?, multi),
                    naga::ImageClass::Depth { multi } => {
                        texture(wgpu::TextureSampleType::Depth, multi)
                    }
                    naga::ImageClass::Storage { format, access } => {
                        storage_format = Some(format!("{format:?}"));
                        wgpu::BindingType::StorageTexture {
                            access: storage_access(access)?,
                            format: Self::FORMAT_BY_NAME,
                            view_dimension,
                        }
                    }
                    naga::ImageClass::External => return Err("an external texture".into()),
                }
            }
            (space, inner) => return Err(format!("no binding of {space:?} {inner:?}")),
        };
        Ok(Self {
            binding,
            ty,
            storage_format,
        })
    }
}

/// A buffer binding of `ty`, with neither a dynamic offset nor a minimum size (WGSL says none).
fn buffer(ty: wgpu::BufferBindingType) -> wgpu::BindingType {
    wgpu::BindingType::Buffer {
        ty,
        has_dynamic_offset: false,
        min_binding_size: None,
    }
}

fn view_dimension(
    dim: naga::ImageDimension,
    arrayed: bool,
) -> Result<wgpu::TextureViewDimension, String> {
    Ok(match (dim, arrayed) {
        (naga::ImageDimension::D1, false) => wgpu::TextureViewDimension::D1,
        (naga::ImageDimension::D2, false) => wgpu::TextureViewDimension::D2,
        (naga::ImageDimension::D2, true) => wgpu::TextureViewDimension::D2Array,
        (naga::ImageDimension::D3, false) => wgpu::TextureViewDimension::D3,
        (naga::ImageDimension::Cube, false) => wgpu::TextureViewDimension::Cube,
        (naga::ImageDimension::Cube, true) => wgpu::TextureViewDimension::CubeArray,
        other => return Err(format!("no view dimension for {other:?}")),
    })
}

/// The sample type of a `texture_2d<kind>`; a float texture's filtering is not WGSL's to say.
fn sample_type(kind: naga::ScalarKind) -> Result<wgpu::TextureSampleType, String> {
    Ok(match kind {
        naga::ScalarKind::Float => wgpu::TextureSampleType::Float { filterable: false },
        naga::ScalarKind::Sint => wgpu::TextureSampleType::Sint,
        naga::ScalarKind::Uint => wgpu::TextureSampleType::Uint,
        other => return Err(format!("no texture of {other:?}")),
    })
}

fn storage_access(access: naga::StorageAccess) -> Result<wgpu::StorageTextureAccess, String> {
    let load = access.contains(naga::StorageAccess::LOAD);
    let store = access.contains(naga::StorageAccess::STORE);
    Ok(match (load, store) {
        (true, true) => wgpu::StorageTextureAccess::ReadWrite,
        (true, false) => wgpu::StorageTextureAccess::ReadOnly,
        (false, true) => wgpu::StorageTextureAccess::WriteOnly,
        (false, false) => return Err(format!("no access in {access:?}")),
    })
}
