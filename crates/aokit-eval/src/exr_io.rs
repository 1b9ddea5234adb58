//! OpenEXR files: reading one scalar or three normal channels, writing float channels.

use std::path::Path;

use exr::prelude::{
    AnyChannel, AnyChannels, Encoding, FlatSamples, Image, Layer, LayerAttributes, ReadChannels,
    ReadLayers, SmallVec, Text, WritableImage, read,
};

use crate::channel_pick::{Pick, depth_rank, pick_by_rank, pick_normals, scalar_rank};
use crate::error::{EvalError, Result, read_file};
use crate::float_image::{FloatImage, sample_count};

/// One layer (EXR part) of a file, every channel converted to `f32`.
struct ExrLayer {
    name: Option<String>,
    width: u32,
    height: u32,
    channels: Vec<(String, Vec<f32>)>,
}

impl ExrLayer {
    fn names(&self) -> Vec<&str> {
        self.channels
            .iter()
            .map(|(name, _)| name.as_str())
            .collect()
    }

    /// Interleaves the chosen channels into an image.
    fn image(&self, indices: &[usize]) -> FloatImage {
        let count = self.width as usize * self.height as usize;
        let mut data = Vec::with_capacity(count * indices.len());
        for i in 0..count {
            data.extend(indices.iter().map(|&c| self.channels[c].1[i]));
        }
        FloatImage {
            width: self.width,
            height: self.height,
            channels: indices.len() as u32,
            data,
        }
    }
}

fn read_error(path: &Path, error: exr::error::Error) -> EvalError {
    match error {
        exr::error::Error::Io(e) => EvalError::io(path, "read", e),
        other => EvalError::format(path, format!("not a readable OpenEXR file: {other}")),
    }
}

/// The most pixels a layer may have: aokit's budget (`aokit::inputs::MAX_PIXELS`, 8192x8192).
const MAX_PIXELS: u64 = 8192 * 8192;

/// The most bytes of samples a file may claim per byte of its own: zlib, the EXR codec that
/// compresses real passes best, stays under 1032:1. The decoders allocate what the header
/// claims before they find the data missing: a 610-byte file (found by fuzzing) asked for
/// 2.4 GB.
const MAX_EXPANSION: u64 = 2048;

/// Refuses a file whose headers claim more pixels than aokit works on, or far more sample
/// bytes than the file could hold, before the decoders allocate for them.
fn check_claimed_size(path: &Path, bytes: &[u8]) -> Result<()> {
    let meta =
        exr::meta::MetaData::read_from_buffered(bytes, false).map_err(|e| read_error(path, e))?;
    let mut total = 0u64;
    for header in meta.headers.iter() {
        let (width, height) = (
            header.layer_size.width() as u64,
            header.layer_size.height() as u64,
        );
        let pixels = width.saturating_mul(height);
        if pixels > MAX_PIXELS {
            return Err(EvalError::format(
                path,
                format!(
                    "a layer of {width}x{height} is more than the {MAX_PIXELS} pixels (8192x8192) \
                     aokit reads"
                ),
            ));
        }
        let per_pixel: u64 = header
            .channels
            .list
            .iter()
            .map(|c| c.sample_type.bytes_per_sample() as u64)
            .sum();
        total = total.saturating_add(pixels.saturating_mul(per_pixel));
    }
    let limit = MAX_EXPANSION.saturating_mul(bytes.len() as u64);
    if total > limit {
        return Err(EvalError::format(
            path,
            format!(
                "not a readable OpenEXR file: its headers claim {total} bytes of samples, more \
                 than {MAX_EXPANSION} times its {} bytes (truncated or corrupt)",
                bytes.len()
            ),
        ));
    }
    Ok(())
}

/// Every layer's full-resolution channels; deep data and subsampled channels are refused.
/// `bytes` is the file's contents, or `None` to read the file at `path`.
fn read_layers(path: &Path, bytes: Option<&[u8]>) -> Result<Vec<ExrLayer>> {
    let owned;
    let bytes = match bytes {
        Some(bytes) => bytes,
        None => {
            owned = read_file(path)?;
            &owned
        }
    };
    check_claimed_size(path, bytes)?;
    let image = read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .all_layers()
        .all_attributes()
        .from_buffered(std::io::Cursor::new(bytes))
        .map_err(|e| read_error(path, e))?;
    let mut layers = Vec::new();
    for layer in image.layer_data {
        let (width, height) = (layer.size.width() as u64, layer.size.height() as u64);
        let count = sample_count(path, width, height, 1)?;
        let mut channels = Vec::new();
        for channel in layer.channel_data.list {
            let name = channel.name.to_string();
            let samples: Vec<f32> = match channel.sample_data {
                FlatSamples::F16(v) => v.into_iter().map(f32::from).collect(),
                FlatSamples::F32(v) => v,
                FlatSamples::U32(v) => v.into_iter().map(|x| x as f32).collect(),
            };
            if samples.len() != count {
                return Err(EvalError::format(
                    path,
                    format!(
                        "channel {name} has {} samples for {width}x{height} pixels (subsampled channels are not supported)",
                        samples.len()
                    ),
                ));
            }
            channels.push((name, samples));
        }
        layers.push(ExrLayer {
            name: layer.attributes.layer_name.map(|n| n.to_string()),
            width: width as u32,
            height: height as u32,
            channels,
        });
    }
    Ok(layers)
}

/// "R, G, B" or, in multi-part files, "beauty/R, beauty/G, depth/Z".
fn list_channels(layers: &[ExrLayer], only: Option<(usize, &[usize])>) -> String {
    let mut names = Vec::new();
    for (l, layer) in layers.iter().enumerate() {
        for (c, (name, _)) in layer.channels.iter().enumerate() {
            if only.is_some_and(|(ol, oc)| ol != l || !oc.contains(&c)) {
                continue;
            }
            names.push(match &layer.name {
                Some(layer_name) if layers.len() > 1 => format!("{layer_name}/{name}"),
                _ => name.clone(),
            });
        }
    }
    if names.is_empty() {
        "none".to_string()
    } else {
        names.join(", ")
    }
}

/// The first layer with a channel `rank` accepts; else the file's only channel.
fn read_ranked(
    path: &Path,
    bytes: Option<&[u8]>,
    rank: fn(&str) -> u8,
    what: &str,
    wanted: &str,
) -> Result<FloatImage> {
    let layers = read_layers(path, bytes)?;
    for (l, layer) in layers.iter().enumerate() {
        match pick_by_rank(layer.names(), rank) {
            Pick::One(c) => return Ok(layer.image(&[c])),
            Pick::Tie(candidates) => {
                return Err(EvalError::format(
                    path,
                    format!(
                        "several channels could be the {what}: {}",
                        list_channels(&layers, Some((l, &candidates)))
                    ),
                ));
            }
            Pick::None => {}
        }
    }
    let total: usize = layers.iter().map(|l| l.channels.len()).sum();
    if total == 1
        && let Some(layer) = layers.iter().find(|l| !l.channels.is_empty())
    {
        return Ok(layer.image(&[0]));
    }
    Err(EvalError::format(
        path,
        format!(
            "no {what} channel (looked for {wanted}); channels found: {}",
            list_channels(&layers, None)
        ),
    ))
}

/// Reads a one-channel EXR such as the `ao.exr` or `reference.exr` aokit writes: the channel
/// `Y`, else `R`, else the file's only channel.
pub fn read_scalar_exr(path: &Path) -> Result<FloatImage> {
    read_ranked(path, None, scalar_rank, "AO", "Y or R")
}

/// Linear depth from an EXR's bytes (`None`: the file at `path`); see
/// [`read_depth`](crate::read_depth) for the channel rules.
pub(crate) fn read_depth_exr(path: &Path, bytes: Option<&[u8]>) -> Result<FloatImage> {
    read_ranked(
        path,
        bytes,
        depth_rank,
        "depth",
        "Z, depth, V, Y or R, optionally layer-qualified",
    )
}

/// Normals from an EXR's bytes (`None`: the file at `path`): X, Y, Z or R, G, B, optionally
/// layer-qualified.
pub(crate) fn read_normals_exr(path: &Path, bytes: Option<&[u8]>) -> Result<FloatImage> {
    let layers = read_layers(path, bytes)?;
    for (l, layer) in layers.iter().enumerate() {
        match pick_normals(&layer.names()) {
            Pick::One(indices) => return Ok(layer.image(&indices)),
            Pick::Tie(candidates) => {
                return Err(EvalError::format(
                    path,
                    format!(
                        "several channel groups could be the normals: {}",
                        list_channels(&layers, Some((l, &candidates)))
                    ),
                ));
            }
            Pick::None => {}
        }
    }
    Err(EvalError::format(
        path,
        format!(
            "no normal channels (looked for X, Y, Z or R, G, B, optionally layer-qualified); channels found: {}",
            list_channels(&layers, None)
        ),
    ))
}

/// Writes named channels of `size[0] x size[1]` samples each (row-major from the top-left) as
/// one layer of 32-bit floats, ZIP-compressed (lossless).
pub fn write_exr(path: &Path, size: [u32; 2], channels: &[(&str, Vec<f32>)]) -> Result<()> {
    let [width, height] = size;
    let count = sample_count(path, width.into(), height.into(), 1).map_err(|_| {
        EvalError::data(
            path,
            format!("image size {width}x{height} is empty or too large"),
        )
    })?;
    if channels.is_empty() {
        return Err(EvalError::data(path, "no channels to write"));
    }
    let mut list: SmallVec<[AnyChannel<FlatSamples>; 4]> = SmallVec::new();
    for (i, (name, data)) in channels.iter().enumerate() {
        let text = Text::new_or_none(name)
            .filter(|_| !name.is_empty() && !name.contains('\0'))
            .ok_or_else(|| {
                EvalError::data(
                    path,
                    format!("channel name {name:?} is empty or not Latin-1"),
                )
            })?;
        if channels[..i].iter().any(|(other, _)| other == name) {
            return Err(EvalError::data(
                path,
                format!("channel {name} appears twice"),
            ));
        }
        if data.len() != count {
            return Err(EvalError::data(
                path,
                format!(
                    "channel {name} has {} values for {width}x{height} pixels",
                    data.len()
                ),
            ));
        }
        list.push(AnyChannel::new(text, FlatSamples::F32(data.clone())));
    }
    let layer = Layer::new(
        (width as usize, height as usize),
        LayerAttributes::default(),
        Encoding::SMALL_LOSSLESS,
        AnyChannels::sort(list),
    );
    Image::from_layer(layer)
        .write()
        .to_file(path)
        .map_err(|e| match e {
            exr::error::Error::Io(e) => EvalError::io(path, "write", e),
            other => EvalError::data(path, other.to_string()),
        })
}
