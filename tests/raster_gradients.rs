//! Finite-difference verification of the cpu rasterizer's backward pass, sanity checks of the
//! forward values, and a NaN fuzz test.
//!
//! Loss = Σ upstream · buffer over every G-buffer with random upstream weights. The rasterizer has
//! hard thresholds that make the loss discontinuous: `α < alpha_min` skips a contribution, the
//! transmittance early stop drops the rest of a pixel's list, and an intersection crossing the near
//! plane is skipped; the `alpha_max` clamp and the low-pass `min(ρ_3d, ρ_2d)` switch are only kinks.
//! The "smooth" tests move the discontinuous thresholds away (`alpha_min = 1e-12`, which the
//! exact bounding box honours, and `transmittance_min = 0`) and keep surfels at least 15° from
//! edge-on, so that no ray–plane intersection comes near the camera. One test keeps the default
//! thresholds on scenes whose few surfels cannot reach the early stop.

use glam::{DMat3, DQuat, DVec3};
use phygap::core::camera::Camera;
use phygap::core::gradcheck::{numerical_gradient, worst_mismatch};
use phygap::core::pose::PoseCorrection;
use phygap::core::raster::cpu::CpuBackend;
use phygap::core::raster::{GBufferGrads, GBuffers, RasterError, RasterSettings};
use phygap::core::surfels::{sigmoid, Surfels};
use phygap::testing::random_upstream;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

const W: u32 = 32;
const H: u32 = 24;

fn camera(rng: &mut ChaCha8Rng) -> Camera {
    let dir = DVec3::new(
        rng.random_range(-1.0..1.0),
        rng.random_range(-1.0..1.0),
        rng.random_range(-0.6..0.6),
    )
    .normalize();
    let up = if dir.z.abs() > 0.9 {
        DVec3::X
    } else {
        DVec3::Z
    };
    Camera::look_at(W, H, 0.9, 3.0 * dir, DVec3::ZERO, up)
}

/// Random rotation whose normal is at most `max_tilt` from the direction to the camera (or its
/// opposite: back-facing surfels), as an un-normalized quaternion.
fn rotation_facing(rng: &mut ChaCha8Rng, to_camera: DVec3, max_tilt: f64) -> [f64; 4] {
    let to_camera = to_camera.normalize();
    let helper = if to_camera.x.abs() < 0.9 {
        DVec3::X
    } else {
        DVec3::Y
    };
    let e1 = to_camera.cross(helper).normalize();
    let e2 = to_camera.cross(e1);
    let tilt = rng.random_range(0.0..max_tilt);
    let az = rng.random_range(0.0..std::f64::consts::TAU);
    let mut n = to_camera * tilt.cos() + (e1 * az.cos() + e2 * az.sin()) * tilt.sin();
    if rng.random_bool(0.3) {
        n = -n;
    }
    let h2 = if n.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
    let u0 = n.cross(h2).normalize();
    let v0 = n.cross(u0);
    let spin = rng.random_range(0.0..std::f64::consts::TAU);
    let tu = u0 * spin.cos() + v0 * spin.sin();
    let tv = n.cross(tu);
    let q = DQuat::from_mat3(&DMat3::from_cols(tu, tv, n)).normalize();
    let k = rng.random_range(0.5..2.0);
    [q.w * k, q.x * k, q.y * k, q.z * k]
}

struct SceneOptions {
    count: std::ops::RangeInclusive<usize>,
    log_scale: std::ops::Range<f64>,
    opacity_logit: std::ops::Range<f64>,
    max_tilt_deg: f64,
}

const SMOOTH: SceneOptions = SceneOptions {
    count: 3..=8,
    log_scale: -1.9..-0.9,
    opacity_logit: -1.5..1.5,
    max_tilt_deg: 75.0,
};

/// Random overlapping surfels around the origin; some reach past the image border.
fn scene(rng: &mut ChaCha8Rng, cam: &Camera, opts: &SceneOptions) -> Surfels {
    let n = rng.random_range(opts.count.clone());
    let mut s = Surfels::zeros(n);
    for i in 0..n {
        let spread = if i == 0 { 1.4 } else { 0.45 };
        let p = DVec3::new(
            rng.random_range(-spread..spread),
            rng.random_range(-spread..spread),
            rng.random_range(-spread..spread),
        );
        s.position[i] = p.to_array();
        s.log_scale[i] = [
            rng.random_range(opts.log_scale.clone()),
            rng.random_range(opts.log_scale.clone()),
        ];
        s.rotation[i] = rotation_facing(rng, cam.origin() - p, opts.max_tilt_deg.to_radians());
        s.opacity[i] = rng.random_range(opts.opacity_logit.clone());
        s.albedo[i] = std::array::from_fn(|_| rng.random_range(-2.0..2.0));
        s.roughness[i] = rng.random_range(-2.0..2.0);
        s.ior[i] = rng.random_range(-2.0..2.0);
    }
    s
}

/// Zeroes the upstream gradient of the α-normalized buffers where α ≤ 1e-3 and of the depth
/// normal where any pixel of its 5-point stencil has α ≤ 1e-3. With `alpha_min = 1e-12`, the
/// pixels at the edge of the coverage have α anywhere in (1e-12, 1e-3), and where α crosses the
/// normalization ε (or the depth normal becomes defined) the normalized buffers jump: a 1e-6 step
/// crosses such a jump for some pixel often enough to spoil a test. Masked pixels carry no weight,
/// so the loss is smooth; the α buffer keeps its upstream everywhere.
fn mask_thin_coverage(up: &mut GBufferGrads, gb: &GBuffers) {
    let (w, h) = (gb.width, gb.height);
    let thin = |x: usize, y: usize| gb.alpha[y * w + x] <= 1e-3;
    for y in 0..h {
        for x in 0..w {
            let k = y * w + x;
            if thin(x, y) {
                up.depth[k] = 0.0;
                up.normal[k] = [0.0; 3];
                up.albedo[k] = [0.0; 3];
                up.roughness[k] = 0.0;
                up.ior[k] = 0.0;
                up.depth_sq[k] = 0.0;
            }
            let stencil_thin = x == 0
                || y == 0
                || x + 1 == w
                || y + 1 == h
                || [(x, y), (x - 1, y), (x + 1, y), (x, y - 1), (x, y + 1)]
                    .iter()
                    .any(|&(i, j)| thin(i, j));
            if stencil_thin {
                up.depth_normal[k] = [0.0; 3];
            }
        }
    }
}

fn smooth_settings() -> RasterSettings {
    RasterSettings {
        alpha_min: 1e-12,
        transmittance_min: 0.0,
        ..RasterSettings::default()
    }
}

fn loss(s: &Surfels, cam: &Camera, settings: &RasterSettings, up: &GBufferGrads) -> f64 {
    CpuBackend
        .forward(s, cam, settings)
        .expect("forward")
        .gbuffers
        .dot(up)
}

/// Checks the analytic gradient of every raw parameter group against central differences.
fn check_all_groups(
    what: &str,
    surfels: &Surfels,
    cam: &Camera,
    settings: &RasterSettings,
    up: &GBufferGrads,
) {
    let fwd = CpuBackend.forward(surfels, cam, settings).unwrap();
    assert!(
        fwd.gbuffers.alpha.iter().filter(|&&a| a > 0.05).count() > 20,
        "{what}: the scene should cover some pixels"
    );
    let mut up = up.clone();
    mask_thin_coverage(&mut up, &fwd.gbuffers);
    let up = &up;
    let grads = CpuBackend
        .backward(surfels, cam, settings, &fwd, up)
        .unwrap();
    let analytic_groups = grads.surfels.groups();
    for (g, (name, x)) in surfels.groups().iter().enumerate() {
        let analytic = analytic_groups[g].1;
        let mut f = |v: &[f64]| {
            let mut s = surfels.clone();
            s.groups_mut()[g].1.copy_from_slice(v);
            loss(&s, cam, settings, up)
        };
        let numerical = numerical_gradient(&mut f, x, 1e-6);
        let scale = numerical.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert!(
            scale > 1e-6,
            "{what}/{name}: loss does not depend on the group"
        );
        // Components below 1e-3 of the group's largest are compared in absolute terms.
        let worst = worst_mismatch(analytic, &numerical, 1e-3 * scale);
        assert!(
            worst.relative_error < 1e-3,
            "{what}/{name}: component {} analytic {:e} numerical {:e} (rel {:e}, group scale {scale:e})",
            worst.index,
            worst.analytic,
            worst.numerical,
            worst.relative_error
        );
    }
}

#[test]
fn gradients_match_finite_differences_on_every_group_and_buffer() {
    for seed in 0..6u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let cam = camera(&mut rng);
        let s = scene(&mut rng, &cam, &SMOOTH);
        let up = random_upstream(&mut rng, W as usize, H as usize);
        check_all_groups(&format!("seed {seed}"), &s, &cam, &smooth_settings(), &up);
    }
}

/// One buffer at a time, so a mistake on one buffer cannot hide behind the others.
#[test]
fn gradients_match_for_each_buffer_alone() {
    let mut rng = ChaCha8Rng::seed_from_u64(100);
    let cam = camera(&mut rng);
    let s = scene(&mut rng, &cam, &SMOOTH);
    let mut full = random_upstream(&mut rng, W as usize, H as usize);
    let (w, h) = (W as usize, H as usize);
    let base = CpuBackend.forward(&s, &cam, &smooth_settings()).unwrap();
    mask_thin_coverage(&mut full, &base.gbuffers);
    for buffer in 0..8 {
        let mut up = GBuffers::zeros(w, h);
        match buffer {
            0 => up.alpha = full.alpha.clone(),
            1 => up.depth = full.depth.clone(),
            2 => up.normal = full.normal.clone(),
            3 => up.albedo = full.albedo.clone(),
            4 => up.roughness = full.roughness.clone(),
            5 => up.ior = full.ior.clone(),
            6 => up.depth_sq = full.depth_sq.clone(),
            _ => up.depth_normal = full.depth_normal.clone(),
        }
        let fwd = CpuBackend.forward(&s, &cam, &smooth_settings()).unwrap();
        let grads = CpuBackend
            .backward(&s, &cam, &smooth_settings(), &fwd, &up)
            .unwrap();
        // Position reaches every buffer; check it and the groups each buffer depends on.
        for (g, (name, x)) in s.groups().iter().enumerate() {
            let analytic = grads.surfels.groups()[g].1;
            let mut f = |v: &[f64]| {
                let mut t = s.clone();
                t.groups_mut()[g].1.copy_from_slice(v);
                loss(&t, &cam, &smooth_settings(), &up)
            };
            let numerical = numerical_gradient(&mut f, x, 1e-6);
            let scale = numerical.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            let worst = worst_mismatch(analytic, &numerical, 1e-3 * scale.max(1e-9));
            assert!(
                worst.relative_error < 1e-3,
                "buffer {buffer} group {name}: {worst:?}"
            );
        }
    }
}

#[test]
fn gradients_match_with_default_thresholds() {
    // Few surfels of moderate opacity: T stays far above the early stop; the α cut at 1/255 is a
    // discontinuity that a 1e-6 step crosses with negligible probability (checked seeds).
    let opts = SceneOptions {
        count: 3..=4,
        opacity_logit: -1.0..0.5,
        ..SMOOTH
    };
    for seed in 10..14u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let cam = camera(&mut rng);
        let s = scene(&mut rng, &cam, &opts);
        let up = random_upstream(&mut rng, W as usize, H as usize);
        check_all_groups(
            &format!("default seed {seed}"),
            &s,
            &cam,
            &RasterSettings::default(),
            &up,
        );
    }
}

#[test]
fn gradients_match_when_the_lowpass_filter_dominates_and_alpha_clamps() {
    // Tiny, nearly edge-on or very opaque surfels with a wide screen filter: most pixels take
    // ρ_2d (gradient through the projected centre) and many hit the alpha_max clamp.
    let opts = SceneOptions {
        count: 3..=6,
        log_scale: -2.6..-1.6,
        opacity_logit: 0.0..7.0,
        max_tilt_deg: 75.0,
    };
    let settings = RasterSettings {
        lowpass_sigma_px: 1.5,
        ..smooth_settings()
    };
    for seed in 20..24u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let cam = camera(&mut rng);
        let s = scene(&mut rng, &cam, &opts);
        let up = random_upstream(&mut rng, W as usize, H as usize);
        check_all_groups(&format!("lowpass seed {seed}"), &s, &cam, &settings, &up);
    }
}

#[test]
fn gradients_match_without_lowpass_filter() {
    let settings = RasterSettings {
        lowpass_sigma_px: 0.0,
        ..smooth_settings()
    };
    for seed in 30..33u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let cam = camera(&mut rng);
        let s = scene(&mut rng, &cam, &SMOOTH);
        let up = random_upstream(&mut rng, W as usize, H as usize);
        check_all_groups(&format!("no lowpass seed {seed}"), &s, &cam, &settings, &up);
    }
}

/// `mean2d_grad_norm` is the gradient with respect to a screen translation of the surfel; shifting
/// the principal point translates a one-surfel image the same way.
#[test]
fn mean2d_gradient_is_the_screen_translation_gradient() {
    for seed in 40..44u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let cam = camera(&mut rng);
        let opts = SceneOptions {
            count: 1..=1,
            ..SMOOTH
        };
        let mut s = scene(&mut rng, &cam, &opts);
        s.position[0] = [0.1, -0.1, 0.05];
        let mut up = random_upstream(&mut rng, W as usize, H as usize);
        // The back-projection of the depth map itself depends on (cx, cy).
        up.depth_normal = vec![[0.0; 3]; (W * H) as usize];
        let settings = smooth_settings();
        let fwd = CpuBackend.forward(&s, &cam, &settings).unwrap();
        let grads = CpuBackend.backward(&s, &cam, &settings, &fwd, &up).unwrap();
        let mut f = |c: &[f64]| {
            let mut shifted = cam;
            shifted.cx = c[0];
            shifted.cy = c[1];
            loss(&s, &shifted, &settings, &up)
        };
        let g = numerical_gradient(&mut f, &[cam.cx, cam.cy], 1e-6);
        let expected = (g[0] * g[0] + g[1] * g[1]).sqrt();
        let got = grads.mean2d_grad_norm[0];
        assert!(
            (got - expected).abs() < 1e-4 * expected.max(1e-6),
            "seed {seed}: {got} vs {expected}"
        );
    }
}

fn fronto_parallel_camera() -> Camera {
    // At the origin looking down world −Z; image 64×48.
    Camera::look_at(64, 48, 1.0, DVec3::ZERO, -DVec3::Z, DVec3::Y)
}

fn one_surfel(position: DVec3, sigma: f64, opacity_logit: f64, normal_sign: f64) -> Surfels {
    let mut s = Surfels::zeros(1);
    s.position[0] = position.to_array();
    s.log_scale[0] = [sigma.ln(), sigma.ln()];
    // Identity (normal +Z, toward the camera) or a half turn about X (normal −Z).
    s.rotation[0] = if normal_sign > 0.0 {
        [1.0, 0.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0, 0.0]
    };
    s.opacity[0] = opacity_logit;
    s.albedo[0] = [0.3, -0.2, 1.0];
    s.roughness[0] = -1.0;
    s.ior[0] = 0.5;
    s
}

#[test]
fn fronto_parallel_surfel_has_the_expected_alpha_depth_and_normal() {
    let cam = fronto_parallel_camera();
    for normal_sign in [1.0, -1.0] {
        let (sigma, depth) = (0.2, 4.0);
        let s = one_surfel(DVec3::new(0.05, -0.03, -depth), sigma, 0.8, normal_sign);
        let settings = RasterSettings::default();
        let out = CpuBackend.forward(&s, &cam, &settings).unwrap().gbuffers;
        let o = sigmoid(0.8);
        let (u, v, _) = cam.project(DVec3::new(0.05, -0.03, -depth)).unwrap();
        let (i, j) = (u.floor() as usize, v.floor() as usize);
        for (di, dj) in [(0, 0), (1, 0), (0, 1), (2, -1)] {
            let (pi, pj) = ((i as i64 + di) as usize, (j as i64 + dj) as usize);
            let k = pj * 64 + pi;
            // Pixel offset from the centre in world units on the plane z = −depth.
            let ds = (pi as f64 + 0.5 - u) * depth / cam.fx / sigma;
            let dt = (pj as f64 + 0.5 - v) * depth / cam.fy / sigma;
            let expected = o * (-(ds * ds + dt * dt) / 2.0).exp();
            assert!(
                (out.alpha[k] - expected).abs() < 1e-12,
                "α at ({pi},{pj}): {} vs {expected}",
                out.alpha[k]
            );
            assert!((out.depth[k] - depth).abs() < 1e-12);
            // One surfel: no spread along the ray.
            assert!((out.depth_sq[k] - depth * depth).abs() < 1e-10);
            let n = DVec3::from_array(out.normal[k]);
            assert!(
                n.abs_diff_eq(DVec3::Z, 1e-12),
                "normal faces the camera: {n}"
            );
            let dn = DVec3::from_array(out.depth_normal[k]);
            assert!(dn.abs_diff_eq(DVec3::Z, 1e-9), "depth normal {dn}");
            assert!((out.albedo[k][0] - sigmoid(0.3)).abs() < 1e-12);
            assert!((out.roughness[k] - sigmoid(-1.0)).abs() < 1e-12);
            assert!((out.ior[k] - (1.3 + sigmoid(0.5))).abs() < 1e-12);
        }
        // Far from the surfel nothing is drawn.
        assert_eq!(out.alpha[0], 0.0);
        assert_eq!(out.depth[0], 0.0);
    }
}

#[test]
fn front_surfel_occludes_the_back_one() {
    let cam = fronto_parallel_camera();
    let mut s = one_surfel(DVec3::new(0.0, 0.0, -5.0), 0.3, 1.0, 1.0);
    let front = one_surfel(DVec3::new(0.0, 0.0, -3.0), 0.3, 0.2, 1.0);
    s.extend_from_indices(&[0]);
    s.position[1] = front.position[0];
    s.opacity[1] = front.opacity[0];
    s.albedo[1] = [-1.0, 0.0, 2.0];
    let out = CpuBackend
        .forward(&s, &cam, &RasterSettings::default())
        .unwrap()
        .gbuffers;
    // Pixel (32, 24) is at 0.5 px from the common centre; compute both alphas.
    let k = 24 * 64 + 32;
    let alpha_at = |depth: f64, sigma: f64, logit: f64| {
        let d = 0.5 * depth / cam.fx / sigma;
        sigmoid(logit) * (-(d * d)).exp()
    };
    let a_front = alpha_at(3.0, 0.3, 0.2);
    let a_back = alpha_at(5.0, 0.3, 1.0);
    let alpha = a_front + (1.0 - a_front) * a_back;
    assert!((out.alpha[k] - alpha).abs() < 1e-12);
    let depth = (a_front * 3.0 + (1.0 - a_front) * a_back * 5.0) / alpha;
    assert!((out.depth[k] - depth).abs() < 1e-12);
    // The two weights' spread along the ray: α² (E[z²] − E[z]²) = w_front w_back (5 − 3)².
    let (w_front, w_back) = (a_front, (1.0 - a_front) * a_back);
    let spread = alpha * alpha * (out.depth_sq[k] - out.depth[k] * out.depth[k]);
    assert!((spread - w_front * w_back * 4.0).abs() < 1e-10, "{spread}");
    let red = (a_front * sigmoid(-1.0) + (1.0 - a_front) * a_back * sigmoid(0.3)) / alpha;
    assert!((out.albedo[k][0] - red).abs() < 1e-12);
}

#[test]
fn an_edge_on_surfel_stays_visible_through_the_lowpass_filter() {
    let cam = fronto_parallel_camera();
    // Normal along +X: exactly edge-on to the optical axis.
    let mut s = one_surfel(DVec3::new(0.0, 0.0, -4.0), 0.2, 3.0, 1.0);
    let q = DQuat::from_rotation_y(std::f64::consts::FRAC_PI_2);
    s.rotation[0] = [q.w, q.x, q.y, q.z];
    let with = CpuBackend
        .forward(&s, &cam, &RasterSettings::default())
        .unwrap();
    let without = CpuBackend
        .forward(
            &s,
            &cam,
            &RasterSettings {
                lowpass_sigma_px: 0.0,
                ..RasterSettings::default()
            },
        )
        .unwrap();
    // The centre projects to pixel corner (32, 24); a neighbouring pixel centre is 0.5 px away
    // in x: the filter gives exp(−2·0.5) there.
    let k = 24 * 64 + 32;
    let expected = sigmoid(3.0) * (-2.0f64 * (0.25 + 0.25) / 2.0).exp();
    assert!(
        with.gbuffers.alpha[k] >= expected - 1e-12,
        "{} vs {expected}",
        with.gbuffers.alpha[k]
    );
    let covered = |g: &GBuffers| g.alpha.iter().filter(|&&a| a > 0.1).count();
    assert!(covered(&with.gbuffers) > covered(&without.gbuffers));
}

#[test]
fn backward_rejects_mismatched_inputs() {
    let cam = fronto_parallel_camera();
    let s = one_surfel(DVec3::new(0.0, 0.0, -4.0), 0.2, 0.0, 1.0);
    let settings = RasterSettings::default();
    let fwd = CpuBackend.forward(&s, &cam, &settings).unwrap();
    let small = GBuffers::zeros(3, 3);
    assert!(matches!(
        CpuBackend.backward(&s, &cam, &settings, &fwd, &small),
        Err(RasterError::GradSizeMismatch { .. })
    ));
    let mut two = s.clone();
    two.extend_from_indices(&[0]);
    let up = GBuffers::zeros(64, 48);
    assert!(matches!(
        CpuBackend.backward(&two, &cam, &settings, &fwd, &up),
        Err(RasterError::ForwardMismatch(_))
    ));
    let bad = RasterSettings {
        alpha_max: 1.5,
        ..settings
    };
    assert!(matches!(
        CpuBackend.forward(&s, &cam, &bad),
        Err(RasterError::InvalidSetting(_))
    ));
}

#[test]
fn fuzz_degenerate_scenes_never_produce_nan_or_inf() {
    let backend = CpuBackend;
    for seed in 0..200u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(1000 + seed);
        let mut cam = camera(&mut rng);
        if seed % 5 == 0 {
            // Camera inside the cloud.
            cam = Camera::look_at(W, H, 1.2, DVec3::new(0.05, 0.02, 0.0), DVec3::X, DVec3::Z);
        }
        let n = rng.random_range(1..12);
        let mut s = Surfels::zeros(n);
        for i in 0..n {
            let r = rng.random_range(0.0..1.0f64);
            s.position[i] = std::array::from_fn(|_| rng.random_range(-3.0..3.0));
            s.log_scale[i] = std::array::from_fn(|_| match rng.random_range(0..6) {
                0 => -1000.0,                        // zero size
                1 => rng.random_range(-30.0..-10.0), // sub-pixel
                2 => rng.random_range(3.0..40.0),    // huge
                _ => rng.random_range(-3.0..0.5),
            });
            s.rotation[i] = if r < 0.05 {
                [0.0; 4]
            } else if r < 0.15 {
                // Exactly edge-on to an axis.
                [1.0, 0.0, 1.0, 0.0]
            } else {
                std::array::from_fn(|_| rng.random_range(-1.0..1.0))
            };
            s.opacity[i] = match rng.random_range(0..5) {
                0 => 1000.0,
                1 => -1000.0,
                _ => rng.random_range(-3.0..6.0),
            };
            s.albedo[i] = std::array::from_fn(|_| rng.random_range(-50.0..50.0));
            s.roughness[i] = rng.random_range(-50.0..50.0);
            s.ior[i] = rng.random_range(-50.0..50.0);
        }
        if seed % 7 == 0 {
            // Put one surfel right at the camera and one behind it.
            s.position[0] = cam.origin().to_array();
            let behind = cam.origin() - cam.forward();
            s.position[n - 1] = behind.to_array();
        }
        let settings = if seed % 3 == 0 {
            smooth_settings()
        } else {
            RasterSettings::default()
        };
        let fwd = backend.forward(&s, &cam, &settings).unwrap();
        assert!(fwd.gbuffers.is_finite(), "seed {seed}: non-finite buffers");
        assert!(fwd.gbuffers.alpha.iter().all(|&a| (0.0..=1.0).contains(&a)));
        let up = random_upstream(&mut rng, W as usize, H as usize);
        let g = backend.backward(&s, &cam, &settings, &fwd, &up).unwrap();
        assert!(g.surfels.is_finite(), "seed {seed}: non-finite gradient");
        assert!(g.mean2d_grad_norm.iter().all(|v| v.is_finite()));
    }
}

#[test]
fn output_is_independent_of_tile_size_and_deterministic() {
    let camera = phygap::pipeline::bench::shell_camera(70, 50);
    let s = phygap::pipeline::bench::shell_surfels(3000, 5);
    let base = RasterSettings::default();
    let reference = CpuBackend.forward(&s, &camera, &base).unwrap();
    assert!(
        reference
            .gbuffers
            .alpha
            .iter()
            .filter(|&&a| a > 0.5)
            .count()
            > 500
    );
    for tile_size in [8, 13, 32] {
        let settings = RasterSettings { tile_size, ..base };
        let other = CpuBackend.forward(&s, &camera, &settings).unwrap();
        assert_eq!(
            other.gbuffers, reference.gbuffers,
            "tile size {tile_size} changes the image"
        );
    }
    let mut rng = ChaCha8Rng::seed_from_u64(77);
    let up = random_upstream(&mut rng, 70, 50);
    let g1 = CpuBackend
        .backward(&s, &camera, &base, &reference, &up)
        .unwrap();
    let again = CpuBackend.forward(&s, &camera, &base).unwrap();
    let g2 = CpuBackend
        .backward(&s, &camera, &base, &again, &up)
        .unwrap();
    assert_eq!(g1, g2, "gradients are bitwise reproducible");
    assert!(g1.surfels.is_finite());
}

/// The gradient on a view's pose correction (rotation, then translation, in the camera's axes)
/// against central differences of the rendered G-buffers under the corrected camera. The depth
/// normals follow the camera through their pixel rays too, outside the projection that the pose
/// gradient covers, so their upstream is left out.
#[test]
fn pose_gradient_matches_finite_differences() {
    for seed in 0..6u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(100 + seed);
        let cam = camera(&mut rng);
        let s = scene(&mut rng, &cam, &SMOOTH);
        let settings = smooth_settings();
        let fwd = CpuBackend.forward(&s, &cam, &settings).unwrap();
        let mut up = random_upstream(&mut rng, W as usize, H as usize);
        mask_thin_coverage(&mut up, &fwd.gbuffers);
        up.depth_normal.iter_mut().for_each(|v| *v = [0.0; 3]);
        let analytic = CpuBackend
            .backward(&s, &cam, &settings, &fwd, &up)
            .unwrap()
            .pose
            .expect("the cpu engine computes the pose gradient");
        let mut f = |x: &[f64]| {
            let correction = PoseCorrection::from_array(x.try_into().expect("six values"));
            loss(&s, &correction.apply(&cam), &settings, &up)
        };
        let numerical = numerical_gradient(&mut f, &[0.0; 6], 1e-6);
        let scale = numerical.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert!(
            scale > 1e-6,
            "seed {seed}: loss does not depend on the pose"
        );
        let worst = worst_mismatch(&analytic, &numerical, 1e-3 * scale);
        assert!(
            worst.relative_error < 1e-3,
            "seed {seed}: pose component {} analytic {:e} numerical {:e} (rel {:e})",
            worst.index,
            worst.analytic,
            worst.numerical,
            worst.relative_error
        );
    }
}
