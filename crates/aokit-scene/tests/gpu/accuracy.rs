//! Absolute error ceilings: every method at every preset against the ray-traced reference on
//! the built-in views, so that a change that makes every method worse together fails here,
//! where the tests that compare methods with each other would still pass.

use crate::common;

use aokit::{Method, Preset};
use aokit_scene::{Builtin, Renderer};
use common::{gpu, rmse, scene_settings, trace};

/// Small enough for lavapipe, large enough that each preset's sampling shows.
const SIZE: [u32; 2] = [96, 54];
const SPP: u32 = 128;
const VIEWS: [Builtin; 3] = [Builtin::Room, Builtin::Stairs, Builtin::Thin];

/// RMSE over surface pixels measured on lavapipe (Mesa 22.3.6, 2026-11-28) for each method at
/// `low`, `medium`, `high` and `ultra` on room, stairs and thin, as the presets run it: through
/// the spatial filter (`AOKIT_PRINT_ACCURACY=1` prints the table again). A result may rise to 1.2 times its value, plus 0.002 for the
/// noise of a changed sampling pattern, before the test fails.
const MEASURED: [(Method, [[f64; 4]; 3]); 9] = [
    (
        Method::SsaoCrytek,
        [
            [0.2654, 0.3100, 0.3258, 0.3428],
            [0.2482, 0.2981, 0.3041, 0.3268],
            [0.2675, 0.3234, 0.3305, 0.3560],
        ],
    ),
    (
        Method::Ssao,
        [
            [0.0875, 0.0729, 0.0665, 0.0605],
            [0.0934, 0.0758, 0.0688, 0.0595],
            [0.1259, 0.1073, 0.1032, 0.0884],
        ],
    ),
    (
        Method::Hbao,
        [
            [0.0616, 0.0532, 0.0438, 0.0470],
            [0.0761, 0.0666, 0.0619, 0.0708],
            [0.0829, 0.0776, 0.0818, 0.0834],
        ],
    ),
    (
        Method::HbaoPlus,
        [
            [0.0699, 0.0619, 0.0623, 0.0626],
            [0.0877, 0.0771, 0.0761, 0.0761],
            [0.0888, 0.0870, 0.0643, 0.0631],
        ],
    ),
    (
        Method::Gtao,
        [
            [0.0685, 0.0545, 0.0417, 0.0568],
            [0.0810, 0.0729, 0.0618, 0.0880],
            [0.1126, 0.1226, 0.1063, 0.0867],
        ],
    ),
    (
        Method::Vbao,
        [
            [0.0681, 0.0545, 0.0426, 0.0525],
            [0.0812, 0.0702, 0.0632, 0.0733],
            [0.1096, 0.1233, 0.1039, 0.0604],
        ],
    ),
    (
        Method::Sao,
        [
            [0.1006, 0.0984, 0.0988, 0.0987],
            [0.1212, 0.1132, 0.1161, 0.1174],
            [0.0910, 0.0879, 0.0846, 0.0818],
        ],
    ),
    (
        Method::Ue4Ssao,
        [
            [0.1326, 0.1315, 0.1311, 0.1312],
            [0.1614, 0.1584, 0.1581, 0.1579],
            [0.0966, 0.0952, 0.0950, 0.0947],
        ],
    ),
    (
        Method::Msvo,
        [
            [0.0795, 0.0693, 0.0671, 0.0649],
            [0.1055, 0.1049, 0.1010, 0.1064],
            [0.1549, 0.1549, 0.1457, 0.1291],
        ],
    ),
];

#[test]
fn every_method_and_preset_stays_under_its_error_ceiling() {
    let gpu = gpu();
    let print = std::env::var_os("AOKIT_PRINT_ACCURACY").is_some();
    let mut measured = MEASURED.map(|(method, _)| (method, [[0.0; 4]; 3]));
    let mut failures = Vec::new();
    for (v, builtin) in VIEWS.into_iter().enumerate() {
        let scene = builtin.build();
        let camera = &scene.cameras[0];
        let traced = trace(&scene, camera, SIZE, SPP);
        let surface = |i: usize| traced.linear_depth[i] > 0.0;
        let first = scene_settings(&scene, Method::Gtao, Preset::High);
        let mut renderer = Renderer::new(&gpu, &scene, &first).unwrap();
        for (m, (method, ceilings)) in MEASURED.iter().enumerate() {
            for (p, preset) in Preset::ALL.into_iter().enumerate() {
                renderer
                    .set_settings(&gpu, &scene_settings(&scene, *method, preset))
                    .unwrap();
                let frame = renderer.render(&gpu, camera, SIZE, 0).unwrap();
                let error = rmse(&frame.ao, &traced.ao, surface);
                measured[m].1[v][p] = error;
                let ceiling = 1.2 * ceilings[v][p] + 0.002;
                if !print && (error.is_nan() || error > ceiling) {
                    failures.push(format!(
                        "{} {} on {}: RMSE {error:.4}, ceiling {ceiling:.4} (measured {:.4})",
                        method.name(),
                        preset.name(),
                        scene.name,
                        ceilings[v][p]
                    ));
                }
            }
        }
    }
    if print {
        for (method, views) in measured {
            let rows: Vec<String> = views
                .iter()
                .map(|r| format!("[{:.4}, {:.4}, {:.4}, {:.4}]", r[0], r[1], r[2], r[3]))
                .collect();
            eprintln!("    (Method::{method:?}, [{}]),", rows.join(", "));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
