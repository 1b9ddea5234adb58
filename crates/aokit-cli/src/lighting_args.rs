//! The lit image's lighting flags, shared by `aokit render` and `aokit view`: the sun, the
//! multi-bounce form, specular occlusion and roughness of the composite
//! ([`aokit_scene::composite::Lighting`]).

use anyhow::{Result, bail};
use aokit::Method;
use aokit_scene::composite::{Lighting, MultiBounce, SpecularOcclusion};
use clap::Args;

#[derive(Args, Debug, Default)]
pub struct LightingArgs {
    /// Direction towards the sun for the lit image, in world space (default: 0.3,1,0.15).
    #[arg(long, value_name = "X,Y,Z", value_parser = crate::camera_args::parse_vec3, allow_hyphen_values = true)]
    pub sun: Option<glam::Vec3>,
    /// Multi-bounce AO in the lit image's ambient diffuse light: gtao (Jimenez et al.'s fit, the
    /// default, also what a bare --multi-bounce means), closed-form (k / (1 - albedo (1 - k)))
    /// or none (the raw AO).
    #[arg(
        long,
        value_name = "FORM",
        num_args = 0..=1,
        default_missing_value = "gtao",
        value_parser = parse_multi_bounce,
        overrides_with = "no_multi_bounce"
    )]
    pub multi_bounce: Option<MultiBounce>,
    /// The raw AO in the lit image's ambient diffuse light: --multi-bounce none.
    #[arg(long, overrides_with = "multi_bounce")]
    pub no_multi_bounce: bool,
    /// Specular occlusion in the lit image: none, gtso (bent normals with gtao and vbao) or frostbite
    /// (default: frostbite).
    #[arg(long, value_name = "MODE", value_parser = parse_specular_occlusion)]
    pub specular_occlusion: Option<SpecularOcclusion>,
    /// Roughness of every surface in the lit image, 0 (mirror) to 1 (default: 0.5).
    #[arg(long, value_name = "R", value_parser = parse_roughness, allow_negative_numbers = true)]
    pub roughness: Option<f32>,
}

impl LightingArgs {
    /// Sets what the flags name in `lighting`, noting where specular occlusion by bent normals
    /// meets a `method` without them.
    pub fn apply(&self, lighting: &mut Lighting, method: Method) -> Result<()> {
        if let Some(sun) = self.sun {
            if sun.length() < 1e-6 {
                bail!("--sun {sun} has no direction");
            }
            lighting.sun_direction = sun.normalize();
        }
        // The two flags override each other, so at most one is set: the last given.
        if self.no_multi_bounce {
            lighting.multi_bounce = MultiBounce::None;
        } else if let Some(form) = self.multi_bounce {
            lighting.multi_bounce = form;
        }
        if let Some(mode) = self.specular_occlusion {
            lighting.specular_occlusion = mode;
        }
        if let Some(roughness) = self.roughness {
            lighting.roughness = roughness;
        }
        if lighting.specular_occlusion == SpecularOcclusion::Gtso && !method.has_bent_normals() {
            eprintln!(
                "note: {} has no bent normals: gtso uses the surface normal, keeping the AO's \
                 amount but not the direction of the openings",
                method.name()
            );
        }
        Ok(())
    }
}

fn parse_multi_bounce(s: &str) -> Result<MultiBounce, String> {
    s.parse()
}

fn parse_specular_occlusion(s: &str) -> Result<SpecularOcclusion, String> {
    s.parse()
}

fn parse_roughness(s: &str) -> Result<f32, String> {
    let r: f32 = s
        .trim()
        .parse()
        .map_err(|e| format!("`{s}` is not a number: {e}"))?;
    if !(0.0..=1.0).contains(&r) {
        return Err(format!("`{s}` is outside [0, 1]"));
    }
    Ok(r)
}
