//! Why a reference cannot be traced.

/// Errors of the reference tracer, each naming what is wrong.
///
/// ```
/// use aokit_reference::{AoOptions, ReferenceError};
/// let options = AoOptions { radius: 0.0, ..Default::default() };
/// assert_eq!(options.validate(), Err(ReferenceError::Radius(0.0)));
/// // The message names the setting, for tools to show as it is.
/// let message = options.validate().unwrap_err().to_string();
/// assert!(message.contains("radius"));
/// ```
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ReferenceError {
    /// The radius is not a positive finite number.
    #[error("reference radius must be positive and finite, got {0}")]
    Radius(f32),
    /// The ray count is zero or absurd.
    #[error("reference rays per pixel must be between 1 and {max}, got {0}", max = crate::MAX_SPP)]
    Spp(u32),
    /// An unknown falloff name.
    #[error("unknown falloff `{0}` (expected none, linear or quadratic)")]
    Falloff(String),
    /// The image has no pixels.
    #[error("reference image size {0}x{1} is empty")]
    Size(u32, u32),
    /// The image has more pixels than [`MAX_PIXELS`](crate::MAX_PIXELS).
    #[error(
        "reference image size {0}x{1} is {pixels} pixels, more than the {max} (8192x8192) aokit \
         works on",
        pixels = u64::from(*.0) * u64::from(*.1),
        max = crate::MAX_PIXELS
    )]
    TooManyPixels(u32, u32),
    /// An index points past the vertex list.
    #[error("triangle {triangle} uses vertex {index}, but there are only {vertices} vertices")]
    Index {
        /// The triangle.
        triangle: usize,
        /// The offending index.
        index: u32,
        /// How many vertices there are.
        vertices: usize,
    },
    /// The index list is not a whole number of triangles.
    #[error("{0} indices do not make whole triangles")]
    PartialTriangle(usize),
    /// A vertex is NaN or infinite.
    #[error("vertex {0} has a non-finite coordinate")]
    NonFinite(usize),
    /// Nothing to trace.
    #[error("the mesh has no triangle with a non-zero area")]
    Empty,
}
