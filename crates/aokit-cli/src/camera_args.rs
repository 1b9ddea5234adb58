//! Flags that pick or place the camera.

use anyhow::{Result, bail};
use aokit_scene::{Camera, Lens, Scene};
use clap::Args;
use glam::Vec3;

#[derive(Args, Debug, Clone)]
pub struct CameraArgs {
    /// Camera of the scene, by name or index (default: the first, or a framing camera).
    #[arg(long)]
    pub camera: Option<String>,
    /// Place the camera: eye position.
    // Values may start with a minus sign (`--eye -6,1,2`): without `allow_hyphen_values`,
    // clap takes them for an unknown flag.
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_vec3, requires = "target", allow_hyphen_values = true)]
    pub eye: Option<Vec3>,
    /// Place the camera: point looked at.
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_vec3, requires = "eye", allow_hyphen_values = true)]
    pub target: Option<Vec3>,
    /// Up direction (default: +Y for --eye/--target, the scene camera's otherwise).
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_vec3, allow_hyphen_values = true)]
    pub up: Option<Vec3>,
    /// Vertical field of view in degrees for --eye/--target, or to override the scene camera's.
    #[arg(long, value_name = "DEG", allow_negative_numbers = true)]
    pub fov_y: Option<f32>,
    /// Use an orthographic lens this many world units tall.
    #[arg(
        long,
        value_name = "H",
        conflicts_with = "fov_y",
        allow_negative_numbers = true
    )]
    pub ortho_height: Option<f32>,
    /// Near plane distance (default: fitted to the scene).
    #[arg(long, allow_negative_numbers = true)]
    pub near: Option<f32>,
    /// Far plane distance (default: infinite for perspective, fitted for orthographic).
    #[arg(long, allow_negative_numbers = true)]
    pub far: Option<f32>,
    /// Standard depth (near = 0, far = 1) instead of reverse-Z.
    #[arg(long)]
    pub standard_z: bool,
}

pub fn parse_vec3(s: &str) -> Result<Vec3, String> {
    let parts: Vec<f32> = s
        .split(',')
        .map(|p| p.trim().parse::<f32>())
        .collect::<Result<_, _>>()
        .map_err(|e| format!("`{s}` is not X,Y,Z: {e}"))?;
    match parts[..] {
        [x, y, z] if x.is_finite() && y.is_finite() && z.is_finite() => Ok(Vec3::new(x, y, z)),
        _ => Err(format!("`{s}` is not three finite numbers X,Y,Z")),
    }
}

impl CameraArgs {
    /// The camera the flags describe for `scene`.
    pub fn resolve(&self, scene: &Scene) -> Result<Camera> {
        if self.camera.is_some() && self.eye.is_some() {
            bail!("give either --camera or --eye/--target, not both");
        }
        let mut camera = match (self.eye, self.target) {
            (Some(eye), Some(target)) => {
                Camera::perspective("command-line", eye, target, self.fov_y.unwrap_or(60.0))
            }
            _ => scene.camera(self.camera.as_deref())?,
        };
        if let Some(up) = self.up {
            camera.up = up;
        }
        if let Some(fov_y_deg) = self.fov_y {
            camera.lens = Lens::Perspective { fov_y_deg };
        }
        if let Some(height) = self.ortho_height {
            camera.lens = Lens::Orthographic { height };
        }
        camera.near = self.near.or(camera.near);
        camera.far = self.far.or(camera.far);
        camera.reverse_z &= !self.standard_z;
        if let Err(e) = camera.validate() {
            bail!(e);
        }
        Ok(camera)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vectors_parse_and_refuse_garbage() {
        assert_eq!(parse_vec3("1, 2.5,-3").unwrap(), Vec3::new(1.0, 2.5, -3.0));
        assert!(parse_vec3("1,2").is_err());
        assert!(parse_vec3("1,2,x").is_err());
        assert!(parse_vec3("1,2,inf").is_err());
    }
}
