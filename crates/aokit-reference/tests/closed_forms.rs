//! The tracer against integrals with closed forms (derived in docs/reference.md).
//!
//! Tolerances come from the sample count: each estimate averages `n` ray results in `[0, 1]`,
//! so its standard error is at most `sqrt(p (1 - p) / n)` for independent rays; the tests allow
//! four of those. The stratified sequence does better than independent rays, never worse, so a
//! failure means a biased integrator, not bad luck.

use aokit_reference::{AoOptions, Falloff, Lens, PixelCamera, PixelSampler, Tracer};
use glam::Vec3;

/// Points averaged per estimate, each with its own scrambling, so that the test sees the
/// estimator's mean rather than one pixel's pattern.
const POINTS: u64 = 64;
const SPP: u32 = 1024;

/// A square of half-size `half` in the plane `axis = offset`, as two triangles.
fn square(positions: &mut Vec<Vec3>, indices: &mut Vec<u32>, axis: usize, offset: f32, half: f32) {
    let base = positions.len() as u32;
    for (a, b) in [(-half, -half), (half, -half), (half, half), (-half, half)] {
        let mut p = Vec3::ZERO;
        p[axis] = offset;
        p[(axis + 1) % 3] = a;
        p[(axis + 2) % 3] = b;
        positions.push(p);
    }
    indices.extend([0, 1, 2, 0, 2, 3].map(|i| base + i));
}

fn mean_ao(tracer: &Tracer, point: Vec3, normal: Vec3, options: &AoOptions) -> f64 {
    (0..POINTS)
        .map(|i| {
            let sampler = PixelSampler::new(options.seed, i);
            f64::from(tracer.ambient_occlusion(point, normal, options, &sampler))
        })
        .sum::<f64>()
        / POINTS as f64
}

fn tolerance(expected: f64) -> f64 {
    let n = (POINTS * u64::from(SPP)) as f64;
    // Never below the standard error of p = 1/2, so the bound stays honest where p is near 0/1.
    4.0 * (expected * (1.0 - expected)).max(0.25).sqrt() / n.sqrt()
}

fn options(radius: f32, falloff: Falloff) -> AoOptions {
    AoOptions {
        radius,
        spp: SPP,
        seed: 11,
        falloff,
    }
}

#[test]
fn a_lone_plane_is_unoccluded() {
    let (mut p, mut i) = (Vec::new(), Vec::new());
    square(&mut p, &mut i, 1, 0.0, 100.0);
    let tracer = Tracer::new(&p, &i).unwrap();
    for falloff in Falloff::ALL {
        for point in [
            Vec3::ZERO,
            Vec3::new(37.5, 0.0, -80.25),
            Vec3::new(99.0, 0.0, 99.0),
        ] {
            let ao = mean_ao(&tracer, point, Vec3::Y, &options(5.0, falloff));
            assert_eq!(ao, 1.0, "{falloff} at {point}");
        }
    }
}

#[test]
fn the_foot_of_an_infinite_wall_is_half_occluded() {
    // Floor y = 0 and wall x = 0 rising from it, both 10^4 wide: from a point 10^-3 off the
    // wall, the directions that miss the wall's finite extent are a negligible sliver.
    let (mut p, mut i) = (Vec::new(), Vec::new());
    square(&mut p, &mut i, 1, 0.0, 1e4);
    square(&mut p, &mut i, 0, 0.0, 1e4);
    let tracer = Tracer::new(&p, &i).unwrap();
    let ao = mean_ao(
        &tracer,
        Vec3::new(1e-3, 0.0, 0.0),
        Vec3::Y,
        &options(1e6, Falloff::None),
    );
    assert!((ao - 0.5).abs() < tolerance(0.5), "AO {ao}, expected 0.5");
}

/// AO on a plane under a parallel plane `a = h / R` radii away.
fn between_planes(a: f64, falloff: Falloff) -> f64 {
    if a >= 1.0 {
        return 1.0;
    }
    match falloff {
        Falloff::None => a * a,
        Falloff::Linear => 1.0 - (1.0 - a) * (1.0 - a),
        Falloff::Quadratic => a * a * (1.0 - 2.0 * a.ln()),
    }
}

#[test]
fn between_two_planes_ao_matches_the_closed_form() {
    let radius = 2.0f32;
    for h in [0.1f32, 0.5, 1.0, 1.6, 2.5] {
        let (mut p, mut i) = (Vec::new(), Vec::new());
        square(&mut p, &mut i, 1, 0.0, 1e4);
        square(&mut p, &mut i, 1, h, 1e4);
        let tracer = Tracer::new(&p, &i).unwrap();
        for falloff in Falloff::ALL {
            let expected = between_planes(f64::from(h / radius), falloff);
            let ao = mean_ao(
                &tracer,
                Vec3::new(0.3, 0.0, -0.7),
                Vec3::Y,
                &options(radius, falloff),
            );
            assert!(
                (ao - expected).abs() < tolerance(expected),
                "h = {h}, R = {radius}, {falloff}: AO {ao}, closed form {expected}"
            );
        }
    }
}

#[test]
fn the_same_seed_gives_the_same_estimate_and_another_seed_another() {
    let (mut p, mut i) = (Vec::new(), Vec::new());
    square(&mut p, &mut i, 1, 0.0, 10.0);
    square(&mut p, &mut i, 0, 0.0, 10.0);
    let tracer = Tracer::new(&p, &i).unwrap();
    let at = |seed| {
        let o = AoOptions {
            spp: 64,
            ..options(3.0, Falloff::None)
        };
        tracer.ambient_occlusion(
            Vec3::new(0.5, 0.0, 0.0),
            Vec3::Y,
            &o,
            &PixelSampler::new(seed, 9),
        )
    };
    assert_eq!(at(1), at(1));
    assert_ne!(at(1), at(2));
}

#[test]
fn whole_images_between_two_planes_match_the_closed_form_at_every_pixel() {
    // Primary hits go through the same path as any scene's: a camera between a floor and a
    // ceiling 10^4 wide (two triangles each, so hit points must be exact far from the vertices)
    // looks down at the floor. Every floor pixel has AO = (h / R)^2.
    let (h, radius) = (1.0f32, 2.0f32);
    let (mut p, mut i) = (Vec::new(), Vec::new());
    square(&mut p, &mut i, 1, 0.0, 1e4);
    square(&mut p, &mut i, 1, h, 1e4);
    let tracer = Tracer::new(&p, &i).unwrap();
    let camera = PixelCamera {
        size: [24, 16],
        lens: Lens::Perspective {
            fov_y: 100f32.to_radians(),
        },
        view_from_world: glam::camera::rh::view::look_at_mat4(
            Vec3::new(3.0, 0.5, -7.0),
            Vec3::new(4.0, 0.0, -6.0),
            Vec3::Y,
        ),
        near: 0.01,
        far: None,
    };
    let options = AoOptions {
        spp: 4096,
        ..options(radius, Falloff::None)
    };
    let image = tracer.render(&camera, &options, &|_| {}).unwrap();
    let expected = between_planes(f64::from(h / radius), Falloff::None);
    let per_pixel = 4.0 * (expected * (1.0 - expected) / 4096.0).sqrt();
    let mut floor_pixels = 0;
    for (k, (&ao, &depth)) in image.ao.iter().zip(&image.linear_depth).enumerate() {
        assert!(depth > 0.0, "pixel {k} sees nothing");
        // The upper part of the view sees the ceiling, also (h / R)^2 by symmetry.
        assert!(
            (f64::from(ao) - expected).abs() < per_pixel,
            "pixel {k}: AO {ao}, closed form {expected}"
        );
        floor_pixels += usize::from(image.normals[k].y.abs() > 0.0);
    }
    assert_eq!(floor_pixels, image.ao.len());
}
