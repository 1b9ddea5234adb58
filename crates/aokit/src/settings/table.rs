//! The declaration of every setting, once: its dotted key (as `--set` and settings files name
//! it), what values it takes, and its help. [`AoSettings::validate`], the keys `--set` accepts,
//! `aokit settings` and docs/settings.md are all derived from [`SETTINGS`].

use std::f32::consts::FRAC_PI_2;

use super::spec::{Field, Rule};
use super::*;
use crate::methods::REGISTRY;

pub(crate) const fn integers(min: u32, max: u32, step: u32) -> SettingKind {
    SettingKind::Integer(IntegerRange { min, max, step })
}

/// Samples, slices, directions or steps.
pub(crate) const fn count() -> SettingKind {
    integers(1, MAX_SAMPLE_COUNT, 1)
}

pub(crate) const fn float(
    min: f32,
    min_inclusive: bool,
    max: Limit,
    max_inclusive: bool,
    unit: Option<&'static str>,
) -> SettingKind {
    SettingKind::Float(FloatRange {
        min,
        min_inclusive,
        max: Some(max),
        max_inclusive,
        unit,
    })
}

pub(crate) const fn above(min: f32, min_inclusive: bool) -> SettingKind {
    SettingKind::Float(FloatRange {
        min,
        min_inclusive,
        max: None,
        max_inclusive: false,
        unit: None,
    })
}

pub(crate) const fn positive() -> SettingKind {
    above(0.0, false)
}

pub(crate) const fn at_least(min: f32) -> SettingKind {
    above(min, true)
}

pub(crate) const fn within(min: f32, max: f32) -> SettingKind {
    float(min, true, Limit::Value(max), true, None)
}

pub(crate) const fn unit() -> SettingKind {
    within(0.0, 1.0)
}

/// From 0 up to another setting's value.
pub(crate) const fn up_to(key: &'static str, unless_zero: bool) -> SettingKind {
    float(0.0, true, Limit::Setting { key, unless_zero }, true, None)
}

pub(crate) const fn names_of<T: Field>(_field: fn(&AoSettings) -> T) -> &'static [&'static str] {
    T::NAMES
}

/// One [`SettingSpec`]: the field's path is its key. `choice` takes the names of the field's
/// enum, `bool` is a bool; other kinds are given.
macro_rules! setting {
    ($head:ident $(. $tail:ident)*, choice, $($rest:tt)*) => {
        $crate::settings::setting!(@spec $head $(. $tail)*,
            $crate::settings::SettingKind::Choice($crate::settings::names_of(
                |s: &$crate::settings::AoSettings| s.$head $(. $tail)*
            )), $($rest)*)
    };
    ($head:ident $(. $tail:ident)*, bool, $($rest:tt)*) => {
        $crate::settings::setting!(@spec $head $(. $tail)*, $crate::settings::SettingKind::Bool, $($rest)*)
    };
    ($head:ident $(. $tail:ident)*, $kind:expr, $($rest:tt)*) => {
        $crate::settings::setting!(@spec $head $(. $tail)*, $kind, $($rest)*)
    };
    (@spec $head:ident $(. $tail:ident)*, $kind:expr, $help:expr
        $(, note = $note:expr)? $(, rule = $rule:expr)? $(,)?) => {
        $crate::settings::SettingSpec {
            name: concat!(stringify!($head) $(, ".", stringify!($tail))*),
            kind: $kind,
            help: $help,
            default_note: $crate::settings::setting!(@option $($note)?),
            get: |s| $crate::settings::Field::to_value(s.$head $(. $tail)*),
            set: |s, value| {
                s.$head $(. $tail)* = $crate::settings::Field::from_value(value)?;
                Ok(())
            },
            rule: $crate::settings::setting!(@option $($rule)?),
        }
    };
    (@option $value:expr) => { Some($value) };
    (@option) => { None };
}
pub(crate) use setting;

/// The settings before the methods' own.
const BEFORE_METHODS: &[SettingSpec] = &[
    setting!(method, choice, "the AO method ([methods.md](methods.md))"),
    setting!(
        radius,
        positive(),
        "world-space radius of the occlusion hemisphere",
        note = "`aokit`: the scene's suggested radius, where it has one"
    ),
    setting!(
        radius_multiplier,
        float(0.0, false, Limit::Value(4.0), true, None),
        "the kernel's radius over `radius`: screen-space methods under-occlude at the true radius, \
         and sampling a little farther brings them closer to the reference traced at `radius`; 1 \
         samples at `radius`"
    ),
    setting!(
        falloff,
        unit(),
        "fraction of the radius, at its outer end, over which a sample's influence fades to zero; \
         0 cuts off hard, as the reference does (used by `gtao`, by the range checks of `ssao` and \
         `ssao-crytek`, and by `ue4-ssao`'s weight, which fades with how far a sample rises \
         towards the eye: its preset's 1 is Unreal Engine 4's linear fade over the whole radius; \
         `sao` has its own in its estimator)"
    ),
    setting!(
        intensity,
        at_least(0.0),
        "`ao = 1 - intensity * (1 - visibility)`, before `power`"
    ),
    setting!(
        power,
        positive(),
        "exponent applied last; above 1 darkens and adds contrast"
    ),
    setting!(
        max_radius_px,
        at_least(1.0),
        "largest screen radius in pixels of the input, at any `resolution` (Max Radius Pixels of \
         the Unity Asset Store package \"Horizon Based Ambient Occlusion\"): nearer surfaces get a \
         world radius that covers this many pixels; `msvo` stops sooner, at its coarsest level's \
         disc"
    ),
    setting!(
        min_radius_px,
        up_to("max_radius_px", false),
        "smallest screen radius in pixels of the input: farther surfaces get a world radius \
         widened to cover this many pixels, so distant geometry keeps a contact shadow (a look \
         control: it departs from the world radius and the reference); 0 keeps the world radius, \
         and AO stops where it covers under one pixel"
    ),
    setting!(
        bias,
        unit(),
        "self-occlusion bias of `ssao`, `ssao-crytek` and `sao` (the paper's beta, subtracted from \
         `v . n`), and `ue4-ssao`'s flat-surface bias in its depth-only version (a pair occludes \
         only where its two samples together rise this far towards the eye above the pixel), as a \
         fraction of the radius; `sao`'s preset is the paper's, `ue4-ssao`'s Unreal's 5 units at \
         its 200-unit radius"
    ),
    setting!(
        angle_bias,
        float(
            0.0,
            true,
            Limit::Named(FRAC_PI_2, "pi/2"),
            false,
            Some("radians")
        ),
        "angle bias of `hbao` (added to the tangent angle) and `hbao-plus` (its sine is the N.V \
         bias), radians"
    ),
    setting!(
        step_power,
        within(0.25, 4.0),
        "step spacing of the marching methods, `1 + t^step_power * (R_px - 1)` pixels: 1 even, 2 \
         crowded near the pixel"
    ),
    setting!(
        max_distance,
        at_least(0.0),
        "view depth beyond which there is no AO; 0: no limit (Max Distance of the Unity Asset \
         Store package \"Horizon Based Ambient Occlusion\")"
    ),
    setting!(
        distance_falloff,
        up_to("max_distance", true),
        "distance before `max_distance` over which AO fades out"
    ),
    setting!(
        bent_normals,
        bool,
        "also output bent normals (`gtao` and `vbao` only)",
        rule = Rule {
            holds: |s| !s.bent_normals || s.method.has_bent_normals(),
            value: |s| format!("true with method {}", s.method.name()),
            expected: "false, or a method with slices (gtao, vbao)",
        }
    ),
];

/// The settings after the methods' own.
const AFTER_METHODS: &[SettingSpec] = &[
    setting!(
        normals.encoding,
        choice,
        "how the normal texture is encoded: what the pipeline decodes from the input normals \
         (their texture format must match), what the scene renderer's G-buffer and `aokit ao` \
         upload store ([normals.md](normals.md))"
    ),
    setting!(
        normals.space,
        choice,
        "the space of the input normals; world-space ones are turned into view space with \
         `AoInputs::view_from_world` by the decode pass, which then runs for oct32 too (0.026 ms \
         at 1080p on an H100, the decode pass's cost in [performance.md](performance.md))"
    ),
    setting!(
        normals.source,
        choice,
        "where the AO's normals come from: the normal texture (without one, `depth-5tap`, the best \
         reconstruction), or reconstructed from depth by the named method \
         ([normals.md](normals.md#normals-from-depth))"
    ),
    setting!(
        noise.kind,
        choice,
        "per-pixel noise that rotates and jitters every method's samples ([noise.md](noise.md))"
    ),
    setting!(
        noise.blue_size,
        integers(64, 128, 64),
        "side of the blue-noise tile, in texels"
    ),
    setting!(
        noise.temporal,
        choice,
        "how the tiled kinds (`blue`, `bayer`, `white`, `hilbert-r2`) move each frame: both values \
         by the golden ratio's fraction, or by R2's step"
    ),
    setting!(
        spatial.enabled,
        bool,
        "run the spatial filter, an edge-aware blur of the AO ([denoise.md](denoise.md)); on by \
         default, `false` gives the raw estimate"
    ),
    setting!(
        spatial.kind,
        choice,
        "which filter: the separable bilateral blur (the keys `radius` to `normal_power` below), \
         He, Sun and Tang's guided filter with log depth as the guide (`guided_radius`, \
         `guided_epsilon`; [denoise.md](denoise.md#guided-filter)), or one pass over each pixel's \
         3x3 neighbourhood with the bilateral weights (`sigma` to `normal_power`; \
         [denoise.md](denoise.md#edges-kind))"
    ),
    setting!(
        spatial.radius,
        integers(1, MAX_SPATIAL_RADIUS, 1),
        "bilateral kernel radius in pixels: each of the two passes averages `2 * radius + 1` pixels"
    ),
    setting!(
        spatial.sigma,
        positive(),
        "standard deviation of the Gaussian spatial weight, in pixels"
    ),
    setting!(
        spatial.depth_weight,
        choice,
        "how a neighbour's depth difference weighs it: a Gaussian, or all or nothing"
    ),
    setting!(
        spatial.depth_sigma,
        positive(),
        "relative depth difference `|d - d0| / d0` that scales the depth weight: the Gaussian's \
         standard deviation, or the threshold above which a neighbour is rejected"
    ),
    setting!(
        spatial.normal_power,
        at_least(0.0),
        "exponent of the normal weight `max(0, n . n0)^normal_power`; 0 turns it off"
    ),
    setting!(
        spatial.packed_input,
        bool,
        "the edges kind reads the AO and depth that the method's kernel packs into one texel \
         (four gathers a pixel instead of eight; AO to 1/1023), where it filters a per-pixel \
         kernel's output at its resolution"
    ),
    setting!(
        spatial.guided_radius,
        integers(1, MAX_SPATIAL_RADIUS, 1),
        "guided filter window radius in pixels: AO is fitted against depth in windows of `(2 * \
         guided_radius + 1)^2` pixels, and each pixel averages the fits of the windows that hold \
         it"
    ),
    setting!(
        spatial.guided_epsilon,
        positive(),
        "the guided filter's regularisation: the variance of log depth in a window below which its \
         AO is smoothed flat rather than fitted against depth; `sqrt` of it is a relative depth \
         spread (1e-6: 0.1%)"
    ),
    setting!(
        temporal.enabled,
        bool,
        "blend each frame's AO with its reprojected history ([denoise.md](denoise.md)); off for \
         single frames, on where frames follow each other (`render --frames N`, `view`)"
    ),
    setting!(
        temporal.blend,
        float(0.0, true, Limit::Value(1.0), false, None),
        "weight of the history; the noise averages over about `1 / (1 - blend)` frames"
    ),
    setting!(
        temporal.variance_gamma,
        positive(),
        "history clipped to the 3x3 same-surface mean +- this many standard deviations"
    ),
    setting!(
        temporal.depth_threshold,
        positive(),
        "relative depth difference above which reprojected history shows another surface and is \
         rejected"
    ),
    setting!(
        temporal.filter_current,
        bool,
        "blend the 3x3 same-surface mean of the current frame instead of the pixel's own value \
         (the filtered current value of [ybniaobu's Unity \
         YPipeline](https://github.com/ybniaobu/Unity_YPipeline); blurs contact shadows)"
    ),
    setting!(
        resolution,
        choice,
        "resolution the AO kernel runs at: every pixel, or one texel per 2x2 or 4x4 pixels \
         upsampled back ([denoise.md](denoise.md#resolution)); full so that the published tables \
         stand"
    ),
    setting!(
        downsample,
        choice,
        "which pixel of each block gives a working texel its depth, normal and motion: a fixed \
         one, the nearest, the farthest, or nearest and farthest alternating in a checkerboard"
    ),
    setting!(
        upsample,
        choice,
        "how each pixel combines the 2x2 working texels around it: those on its surface equally or \
         bilinearly weighted, or bilinearly where all four are on its surface and else the one of \
         nearest depth"
    ),
    setting!(
        upsample_threshold,
        positive(),
        "relative depth difference `|d - d0| / d0` below which a working texel shows the pixel's \
         surface in the upsample"
    ),
    setting!(
        filter_resolution,
        choice,
        "below full resolution, where the spatial and temporal filters run: before the upsample, \
         on the working texels, or after it, on every pixel"
    ),
    setting!(
        depth_mips,
        choice,
        "whether `gtao`, `vbao`, `hbao`, `hbao-plus`, `ssao` and `ssao-crytek` read far samples \
         from a depth MIP chain, and its precision ([depth-mips.md](depth-mips.md)); `fp16` needs \
         R16Float storage on the device"
    ),
    setting!(
        depth_mip_offset,
        float(0.0, true, Limit::Value(16.0), true, Some("log2 pixels")),
        "with `depth_mips` on, a sample `d` pixels out reads level `floor(log2(d) - \
         depth_mip_offset)`, clamped to the chain's levels"
    ),
    setting!(
        sample_depth,
        choice,
        "how `gtao`, `vbao`, `hbao` and `hbao-plus` read the depth where a sample lands: the texel \
         it lands in, moved onto the view ray through the sample at the same height above the \
         tangent plane (one load), or 1 / depth interpolated over its 2x2 texels (exact on planes; \
         slightly lower error for 1.06 to 1.32 times the frame's time on an H100: \
         [methods.md](methods.md#sample-depth))"
    ),
    setting!(
        slice_march,
        choice,
        "how `gtao`, `vbao`, `hbao` and `hbao-plus` march their slices with the `nearest` read: \
         each side set up once, with the counts and the step power compiled into the kernel, or \
         every sample placed from scratch; the same AO to rounding, at different cost \
         ([gtao.md](methods/gtao.md#the-lean-march))"
    ),
    setting!(
        offscreen_samples,
        choice,
        "what `gtao`, `vbao`, `hbao` and `hbao-plus` take for a sample off screen: the surface at \
         the screen's edge continued (the plane of the last texel on screen along the slice), \
         nothing, as if the scene were open beyond the edge, or the last texel on screen (what a \
         clamping sampler reads) at its height above the pixel's tangent plane; against \
         `unoccluded`, `clamp` (the default) lowers the error within 12 px of the edges by 8 to \
         21% at about no cost, `extend` by 11 to 20% for 1.22 to 1.26 times GTAO `high`'s frame \
         time on lavapipe \
         ([quality.md](quality.md#off-screen-samples-and-silhouettes))"
    ),
];

/// Every setting of [`AoSettings`], in the order docs/settings.md lists them and
/// [`AoSettings::validate`] checks them.
///
/// ```
/// use aokit::settings::{SETTINGS, SettingKind};
/// // The keys a `--set` completion offers, with their ranges.
/// for spec in SETTINGS {
///     println!("{} {}", spec.name, spec.kind.range_text());
/// }
/// let counts = SETTINGS.iter().filter(|s| matches!(s.kind, SettingKind::Integer(_))).count();
/// assert!(counts > 10);
/// ```
pub static SETTINGS: &[SettingSpec] = &ALL;

/// How many settings there are: the general ones and every registered method's.
const LEN: usize = {
    let mut len = BEFORE_METHODS.len() + AFTER_METHODS.len();
    let mut i = 0;
    while i < REGISTRY.len() {
        len += REGISTRY[i].settings.len();
        i += 1;
    }
    len
};

/// [`SETTINGS`]' rows: the general ones, then each method's in the registry's order, then the
/// stages'.
static ALL: [SettingSpec; LEN] = {
    let mut all = [BEFORE_METHODS[0]; LEN];
    let mut at = append(&mut all, 0, BEFORE_METHODS);
    let mut i = 0;
    while i < REGISTRY.len() {
        at = append(&mut all, at, REGISTRY[i].settings);
        i += 1;
    }
    assert!(append(&mut all, at, AFTER_METHODS) == LEN);
    all
};

/// Copies `rows` into `all` from `at`, returning where they end.
const fn append(all: &mut [SettingSpec], mut at: usize, rows: &[SettingSpec]) -> usize {
    let mut i = 0;
    while i < rows.len() {
        all[at] = rows[i];
        at += 1;
        i += 1;
    }
    at
}
