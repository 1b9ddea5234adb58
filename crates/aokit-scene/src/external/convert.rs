//! Passes as another renderer exports them, turned into what [`Passes`](super::Passes) holds:
//! depth-buffer values into linear view depth, world-space normals into view space. The CLI's
//! `aokit ao` and the Python package read files and arrays through these.

use std::str::FromStr;

use aokit::{NormalSpace, Projection};
use glam::{Mat3, Mat4, Vec3};

/// What a depth image holds.
///
/// ```
/// use aokit_scene::external::DepthKind;
/// assert_eq!("ndc".parse::<DepthKind>()?, DepthKind::Ndc);
/// assert_eq!(DepthKind::default().name(), "linear");
/// assert!("z".parse::<DepthKind>().unwrap_err().contains("linear, ndc"));
/// # Ok::<(), String>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DepthKind {
    /// Positive distance along the view axis; 0, negative, NaN or infinite where there is no
    /// surface.
    #[default]
    Linear,
    /// Depth-buffer values in `[0, 1]` in the projection's convention (`reverse_z`, `near`,
    /// `far`); the far-plane value is background.
    Ndc,
}

impl DepthKind {
    /// Every kind, in the order of the docs.
    ///
    /// ```
    /// use aokit_scene::external::DepthKind;
    /// let names: Vec<_> = DepthKind::ALL.iter().map(|k| k.name()).collect();
    /// assert_eq!(names, ["linear", "ndc"]);
    /// ```
    pub const ALL: [DepthKind; 2] = [DepthKind::Linear, DepthKind::Ndc];

    /// The name `--depth-kind` and the Python package take.
    ///
    /// ```
    /// use aokit_scene::external::DepthKind;
    /// assert_eq!(DepthKind::Ndc.name(), "ndc");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            DepthKind::Linear => "linear",
            DepthKind::Ndc => "ndc",
        }
    }
}

impl FromStr for DepthKind {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        DepthKind::ALL
            .into_iter()
            .find(|kind| kind.name() == s)
            .ok_or_else(|| format!("depth kind `{s}` is not one of linear, ndc"))
    }
}

/// Linear view depth from a `width`-wide image of `kind`: linear depth is returned as it is,
/// depth-buffer values are turned with `projection` (background, the far-plane value, becomes
/// 0). A finite NDC value outside `[0, 1]` (linear depth given by mistake) is refused with the
/// count of such pixels and the first one.
///
/// ```
/// use aokit::Projection;
/// use aokit_scene::external::{DepthKind, linear_depth};
/// let projection = Projection::perspective(1.0, 1.0, 0.1, None); // reverse-Z, infinite far
/// let depth = linear_depth(vec![0.05, 0.0], DepthKind::Ndc, &projection, 2)?;
/// assert!((depth[0] - 2.0).abs() < 1e-4);
/// assert_eq!(depth[1], 0.0); // the far plane: background
/// let err = linear_depth(vec![3.5, 0.5], DepthKind::Ndc, &projection, 2).unwrap_err();
/// assert!(err.starts_with("1 of 2 pixels hold depth outside [0, 1] (e.g. 3.5 at x 0, y 0)"));
/// # Ok::<(), String>(())
/// ```
pub fn linear_depth(
    depth: Vec<f32>,
    kind: DepthKind,
    projection: &Projection,
    width: u32,
) -> Result<Vec<f32>, String> {
    match kind {
        DepthKind::Linear => Ok(depth),
        DepthKind::Ndc => {
            // Depth-buffer values lie in [0, 1]; others (linear depth given by mistake) would
            // map to plausible but wrong distances. Non-finite values stay background.
            let outside = |d: &f32| d.is_finite() && !(0.0..=1.0).contains(d);
            let bad = depth.iter().filter(|d| outside(d)).count();
            if let Some((i, example)) = depth.iter().enumerate().find(|(_, d)| outside(d)) {
                let width = width.max(1) as usize;
                return Err(format!(
                    "{bad} of {} pixels hold depth outside [0, 1] (e.g. {example} at x {}, y {}), \
                     which depth kind ndc needs; is it linear depth (depth kind linear)?",
                    depth.len(),
                    i % width,
                    i / width
                ));
            }
            Ok(depth.iter().map(|&d| projection.surface_depth(d)).collect())
        }
    }
}

/// Normals in `space` turned into view space: view-space ones are returned as they are,
/// world-space ones are turned by `view_from_world`'s rotation part, which must not be
/// degenerate (a zero matrix written by hand would turn every normal into zero, which the
/// kernels take for a normal facing the camera).
///
/// ```
/// use aokit::NormalSpace;
/// use aokit_scene::external::view_normals;
/// use glam::{Mat4, Vec3};
/// // A camera turned 90 degrees about +Y: world +X points at it.
/// let view_from_world = Mat4::from_rotation_y(-std::f32::consts::FRAC_PI_2);
/// let view = view_normals(vec![Vec3::X], NormalSpace::World, view_from_world)?;
/// assert!((view[0] - Vec3::Z).length() < 1e-6);
/// let err = view_normals(vec![Vec3::X], NormalSpace::World, Mat4::ZERO).unwrap_err();
/// assert!(err.contains("determinant 0"));
/// # Ok::<(), String>(())
/// ```
pub fn view_normals(
    normals: Vec<Vec3>,
    space: NormalSpace,
    view_from_world: Mat4,
) -> Result<Vec<Vec3>, String> {
    match space {
        NormalSpace::View => Ok(normals),
        NormalSpace::World => {
            let determinant = Mat3::from_mat4(view_from_world).determinant();
            if !(determinant.is_finite() && determinant.abs() > 1e-6) {
                return Err(format!(
                    "view_from_world's 3x3 part has determinant {determinant}, not a rotation; \
                     world-space normals cannot be turned into view space with it"
                ));
            }
            Ok(normals
                .into_iter()
                .map(|n| view_from_world.transform_vector3(n))
                .collect())
        }
    }
}
