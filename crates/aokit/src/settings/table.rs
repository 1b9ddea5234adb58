//! The declaration of every setting, once: its dotted key (as `--set` and settings files name
//! it), what values it takes, and its help. [`AoSettings::validate`], the keys `--set` accepts,
//! `aokit settings` and docs/settings.md are all derived from [`SETTINGS`].

use std::f32::consts::FRAC_PI_2;

use super::spec::{Field, Rule};
use super::*;

const fn integers(min: u32, max: u32, step: u32) -> SettingKind {
    SettingKind::Integer(IntegerRange { min, max, step })
}

/// Samples, slices, directions or steps.
const fn count() -> SettingKind {
    integers(1, MAX_SAMPLE_COUNT, 1)
}

const fn float(
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

const fn above(min: f32, min_inclusive: bool) -> SettingKind {
    SettingKind::Float(FloatRange {
        min,
        min_inclusive,
        max: None,
        max_inclusive: false,
        unit: None,
    })
}

const fn positive() -> SettingKind {
    above(0.0, false)
}

const fn at_least(min: f32) -> SettingKind {
    above(min, true)
}

const fn within(min: f32, max: f32) -> SettingKind {
    float(min, true, Limit::Value(max), true, None)
}

const fn unit() -> SettingKind {
    within(0.0, 1.0)
}

/// From 0 up to another setting's value.
const fn up_to(key: &'static str, unless_zero: bool) -> SettingKind {
    float(0.0, true, Limit::Setting { key, unless_zero }, true, None)
}

const fn names_of<T: Field>(_field: fn(&AoSettings) -> T) -> &'static [&'static str] {
    T::NAMES
}

/// One [`SettingSpec`]: the field's path is its key. `choice` takes the names of the field's
/// enum, `bool` is a bool; other kinds are given.
macro_rules! setting {
    ($head:ident $(. $tail:ident)*, choice, $($rest:tt)*) => {
        setting!(@spec $head $(. $tail)*,
            SettingKind::Choice(names_of(|s: &AoSettings| s.$head $(. $tail)*)), $($rest)*)
    };
    ($head:ident $(. $tail:ident)*, bool, $($rest:tt)*) => {
        setting!(@spec $head $(. $tail)*, SettingKind::Bool, $($rest)*)
    };
    ($head:ident $(. $tail:ident)*, $kind:expr, $($rest:tt)*) => {
        setting!(@spec $head $(. $tail)*, $kind, $($rest)*)
    };
    (@spec $head:ident $(. $tail:ident)*, $kind:expr, $help:expr
        $(, note = $note:expr)? $(, rule = $rule:expr)? $(,)?) => {
        SettingSpec {
            name: concat!(stringify!($head) $(, ".", stringify!($tail))*),
            kind: $kind,
            help: $help,
            default_note: setting!(@option $($note)?),
            get: |s| Field::to_value(s.$head $(. $tail)*),
            set: |s, value| {
                s.$head $(. $tail)* = Field::from_value(value)?;
                Ok(())
            },
            rule: setting!(@option $($rule)?),
        }
    };
    (@option $value:expr) => { Some($value) };
    (@option) => { None };
}

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
pub static SETTINGS: &[SettingSpec] = &[
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
    setting!(
        ssao_crytek.sample_count,
        count(),
        "points in the sphere per pixel"
    ),
    setting!(
        ssao.sample_count,
        count(),
        "points in the hemisphere per pixel"
    ),
    setting!(
        sao.sample_count,
        count(),
        "taps on SAO's spiral per pixel (its turns follow from the count: \
         [methods/sao.md](methods/sao.md))"
    ),
    setting!(
        msvo.sample_count,
        integers(2, MAX_SAMPLE_COUNT, 2),
        "depth samples per texel at each level, in mirrored pairs on a disc of 5 texels of the \
         level; the working level costs this many per pixel, the coarser four together at most a \
         third more ([methods/msvo.md](methods/msvo.md))"
    ),
    setting!(
        msvo.levels,
        integers(1, MSVO_MAX_LEVELS, 1),
        "levels of the depth MIP chain the obscurance is computed at and merged from; the screen \
         radius stops at `5 * 2^(levels - 1)` working texels (80 with all five)"
    ),
    setting!(
        msvo.thickness,
        positive(),
        "Unity's thickness modifier: a sample more than this many sphere chords in front of the \
         sphere is taken for a thin occluder and rejected; larger darkens creases and adds halos \
         around objects",
        note = "Unity's default"
    ),
    setting!(
        ue4_ssao.sample_count,
        count(),
        "sample pairs per pixel, each two depth samples mirrored about the pixel: a pixel reads \
         twice this many depths, so presets give 2, 4, 9 and 27 pairs \
         ([methods/ue4-ssao.md](methods/ue4-ssao.md))"
    ),
    setting!(
        ue4_ssao.use_normals,
        bool,
        "`ue4-ssao`'s normal version, each sample's angle measured from the tangent plane; false: \
         the depth-only version, the angle between the two samples of a pair with the flat-surface \
         `bias`"
    ),
    setting!(
        hbao.direction_count,
        count(),
        "screen directions over the full circle, rotated per pixel (`hbao`, `hbao-plus`; not read \
         by `hbao.variant = separable`, which has four)"
    ),
    setting!(
        hbao.step_count,
        count(),
        "samples per direction (`hbao`, `hbao-plus`)"
    ),
    setting!(
        hbao.variant,
        choice,
        "how `hbao` runs: one kernel per pixel, or two passes over rows and then columns of depth \
         in workgroup memory, after NVIDIA's compute-shader HBAO: four fixed directions (+-x, \
         +-y), `4 * step_count` samples, the screen radius stopped at 128 texels of the working \
         resolution ([methods/hbao.md](methods/hbao.md#separable-hbao-hbaovariant--separable)); \
         `hbao-plus` accepts only `per-pixel`",
        rule = Rule {
            holds: |s| !(s.method == Method::HbaoPlus && s.hbao.variant == HbaoVariant::Separable),
            value: |s| format!("{} with method {}", s.hbao.variant.name(), s.method.name()),
            expected: "per-pixel: the separable passes integrate hbao's horizons, which \
                       hbao-plus does not have",
        }
    ),
    setting!(
        gtao.slice_count,
        count(),
        "slices (screen directions over a half circle) per pixel"
    ),
    setting!(
        gtao.steps_per_side,
        count(),
        "depth samples on each side of the pixel per slice"
    ),
    setting!(
        gtao.normalize_slices,
        bool,
        "divide by the slices' unoccluded integrals (see \
         [gtao.md](methods/gtao.md#slices-normalised-by-their-unoccluded-integrals))"
    ),
    setting!(
        gtao.thickness,
        unit(),
        "the GTAO paper's thickness heuristic: how far the horizon falls back towards a sample \
         below it"
    ),
    setting!(vbao.slice_count, count(), "slices per pixel"),
    setting!(
        vbao.steps_per_side,
        count(),
        "depth samples on each side per slice"
    ),
    setting!(
        vbao.thickness,
        positive(),
        "thickness of every occluder, as a fraction of the radius"
    ),
    setting!(
        vbao.thickness_growth,
        at_least(0.0),
        "extra thickness per unit of the occluder's view depth"
    ),
    setting!(
        vbao.back_faces,
        bool,
        "measure each occluder's thickness from `AoInputs::back_depth` (the depth of the back \
         faces; `aokit ao --back-depth`), `vbao.thickness` then being the least thickness; turning \
         it on in `--set` or a settings file starts from VBAO's presets tuned with back faces \
         (`AoSettings::preset_with_back_faces`, \
         [methods/vbao.md](methods/vbao.md#measured-thickness-vbaoback_faces))"
    ),
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
];
