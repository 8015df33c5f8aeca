use super::*;
use crate::core::camera::Camera;
use crate::core::gradcheck::assert_gradient;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

const W: usize = 13;
const H: usize = 11;
const C: usize = 3;
const SEEDS: [u64; 3] = [1, 2, 3];

fn random_vec(rng: &mut ChaCha8Rng, n: usize, lo: f64, hi: f64) -> Vec<f64> {
    (0..n).map(|_| rng.random_range(lo..hi)).collect()
}

/// SSIM map by direct 11×11 summation with explicit zero padding: the plain reference for the
/// separable implementation.
fn reference_ssim_map(x: &[f64], y: &[f64], w: usize, h: usize, c: usize) -> Vec<f64> {
    let k = ssim::gaussian_kernel();
    let at = |img: &[f64], px: i64, py: i64, ch: usize| -> f64 {
        if px < 0 || py < 0 || px >= w as i64 || py >= h as i64 {
            0.0
        } else {
            img[(py as usize * w + px as usize) * c + ch]
        }
    };
    let mut map = vec![0.0; x.len()];
    for py in 0..h as i64 {
        for px in 0..w as i64 {
            for ch in 0..c {
                let (mut mx, mut my, mut exx, mut eyy, mut exy) = (0.0, 0.0, 0.0, 0.0, 0.0);
                for dy in -5i64..=5 {
                    for dx in -5i64..=5 {
                        let g = k[(dy + 5) as usize] * k[(dx + 5) as usize];
                        let a = at(x, px + dx, py + dy, ch);
                        let b = at(y, px + dx, py + dy, ch);
                        mx += g * a;
                        my += g * b;
                        exx += g * a * a;
                        eyy += g * b * b;
                        exy += g * a * b;
                    }
                }
                let (vx, vy, cov) = (exx - mx * mx, eyy - my * my, exy - mx * my);
                map[(py as usize * w + px as usize) * c + ch] = (2.0 * mx * my + ssim::SSIM_C1)
                    * (2.0 * cov + ssim::SSIM_C2)
                    / ((mx * mx + my * my + ssim::SSIM_C1) * (vx + vy + ssim::SSIM_C2));
            }
        }
    }
    map
}

#[test]
fn gaussian_kernel_is_normalized_and_symmetric() {
    let k = ssim::gaussian_kernel();
    assert!((k.iter().sum::<f64>() - 1.0).abs() < 1e-15);
    for i in 0..11 {
        assert_eq!(k[i], k[10 - i]);
    }
    // exp(−1/(2·1.5²)) is the ratio of neighbours at the centre.
    assert!((k[6] / k[5] - (-1.0f64 / 4.5).exp()).abs() < 1e-15);
}

#[test]
fn l1_of_known_arrays() {
    let r = l1(&[1.0, 2.0, 3.0, 4.0], &[0.0, 2.0, 5.0, 4.0], None);
    assert_eq!(r.value, 0.75);
    assert_eq!(r.grad, vec![0.25, 0.0, -0.25, 0.0]);
    // Per-pixel weight over 2 channels: pixel 1 is masked out.
    let r = l1(
        &[1.0, 2.0, 3.0, 4.0],
        &[0.0, 0.0, 0.0, 0.0],
        Some(&[1.0, 0.0]),
    );
    assert_eq!(r.value, 3.0 / 4.0);
    assert_eq!(r.grad, vec![0.25, 0.25, 0.0, 0.0]);
    // Per-element weight.
    let r = l1(&[1.0, -2.0], &[0.0, 0.0], Some(&[0.5, 2.0]));
    assert_eq!(r.value, (0.5 + 4.0) / 2.0);
    assert_eq!(r.grad, vec![0.25, -1.0]);
}

#[test]
fn l1_gradient_matches_finite_differences() {
    for seed in SEEDS {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let pred = random_vec(&mut rng, W * H * C, 0.0, 1.0);
        let target = random_vec(&mut rng, W * H * C, 0.0, 1.0);
        let per_pixel = random_vec(&mut rng, W * H, 0.0, 1.0);
        let per_element = random_vec(&mut rng, W * H * C, 0.0, 1.0);
        for weight in [None, Some(&per_pixel[..]), Some(&per_element[..])] {
            let analytic = l1(&pred, &target, weight).grad;
            assert_gradient(
                "l1",
                &mut |p| l1(p, &target, weight).value,
                &pred,
                &analytic,
                1e-6,
                1e-5,
                1e-5,
            );
        }
    }
}

#[test]
fn ssim_matches_direct_window_summation() {
    for seed in SEEDS {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let x = random_vec(&mut rng, W * H * C, 0.0, 1.0);
        let y = random_vec(&mut rng, W * H * C, 0.0, 1.0);
        let fast = ssim_map(&x, &y, W, H, C);
        let reference = reference_ssim_map(&x, &y, W, H, C);
        for (a, b) in fast.iter().zip(&reference) {
            assert!((a - b).abs() < 1e-12, "{a} vs {b}");
        }
        let mean = reference.iter().sum::<f64>() / reference.len() as f64;
        assert!((ssim(&x, &y, W, H, C).value - mean).abs() < 1e-12);
    }
}

#[test]
fn ssim_of_an_image_with_itself_is_one_and_stationary() {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let x = random_vec(&mut rng, W * H * C, 0.0, 1.0);
    let r = ssim(&x, &x, W, H, C);
    assert!((r.value - 1.0).abs() < 1e-12, "{}", r.value);
    assert!(r.grad.iter().all(|g| g.abs() < 1e-12));
}

#[test]
fn ssim_of_constant_images_in_the_interior_is_the_luminance_term() {
    // 21×21: pixels at least 5 from every border see no padding, so σ = 0 there.
    let (a, b) = (0.6, 0.3);
    let map = ssim_map(&vec![a; 21 * 21], &vec![b; 21 * 21], 21, 21, 1);
    let expected = (2.0 * a * b + ssim::SSIM_C1) / (a * a + b * b + ssim::SSIM_C1);
    assert!((map[10 * 21 + 10] - expected).abs() < 1e-12);
    assert!((map[5 * 21 + 15] - expected).abs() < 1e-12);
    // A corner window is mostly padding: its value differs.
    assert!((map[0] - expected).abs() > 1e-3);
}

#[test]
fn ssim_decreases_with_noise() {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let (w, h) = (32, 24);
    let clean: Vec<f64> = (0..w * h * 3)
        .map(|i| 0.5 + 0.3 * ((i / 3 % w) as f64 * 0.3).sin())
        .collect();
    let mut last = 1.0;
    for amplitude in [0.01, 0.05, 0.2] {
        let noisy: Vec<f64> = clean
            .iter()
            .map(|v| v + amplitude * rng.random_range(-1.0..1.0))
            .collect();
        let s = ssim(&noisy, &clean, w, h, 3).value;
        assert!(s < last, "SSIM {s} at noise {amplitude} not below {last}");
        last = s;
    }
    assert!(last < 0.7);
}

#[test]
fn ssim_gradient_matches_finite_differences() {
    for seed in SEEDS {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let x = random_vec(&mut rng, W * H * C, 0.0, 1.0);
        let y = random_vec(&mut rng, W * H * C, 0.0, 1.0);
        let analytic = ssim(&x, &y, W, H, C).grad;
        assert_gradient(
            "ssim",
            &mut |p| ssim(p, &y, W, H, C).value,
            &x,
            &analytic,
            1e-5,
            1e-5,
            1e-8,
        );
    }
}

#[test]
fn photometric_combines_l1_and_ssim_and_its_gradient_matches() {
    for seed in SEEDS {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let x = random_vec(&mut rng, W * H * C, 0.0, 1.0);
        let y = random_vec(&mut rng, W * H * C, 0.0, 1.0);
        let r = photometric(&x, &y, W, H, C, 0.2, LossPrecision::F64);
        let expected = 0.8 * l1(&x, &y, None).value + 0.2 * (1.0 - ssim(&x, &y, W, H, C).value);
        assert!((r.value - expected).abs() < 1e-14);
        assert_gradient(
            "photometric",
            &mut |p| photometric(p, &y, W, H, C, 0.2, LossPrecision::F64).value,
            &x,
            &r.grad,
            1e-6,
            1e-5,
            1e-5,
        );
    }
    let same = vec![0.25; W * H * C];
    assert!(
        photometric(&same, &same, W, H, C, 0.2, LossPrecision::F64)
            .value
            .abs()
            < 1e-14
    );
}

#[test]
fn stokes_l1_sums_both_components_with_their_gradients() {
    let r = stokes_l1(&[0.5, 0.0], &[0.0, 0.0], &[0.0, -1.0], &[0.0, 0.0], None);
    assert_eq!(r.value, 0.25 + 0.5);
    assert_eq!(r.grad_s1, vec![0.5, 0.0]);
    assert_eq!(r.grad_s2, vec![0.0, -0.5]);
    for seed in SEEDS {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let n = W * H * C;
        let (p1, t1) = (
            random_vec(&mut rng, n, -0.3, 0.3),
            random_vec(&mut rng, n, -0.3, 0.3),
        );
        let (p2, t2) = (
            random_vec(&mut rng, n, -0.3, 0.3),
            random_vec(&mut rng, n, -0.3, 0.3),
        );
        let mask = random_vec(&mut rng, W * H, 0.0, 1.0);
        let r = stokes_l1(&p1, &t1, &p2, &t2, Some(&mask));
        assert_gradient(
            "stokes_l1 wrt S1",
            &mut |p| stokes_l1(p, &t1, &p2, &t2, Some(&mask)).value,
            &p1,
            &r.grad_s1,
            1e-6,
            1e-5,
            1e-5,
        );
        assert_gradient(
            "stokes_l1 wrt S2",
            &mut |p| stokes_l1(&p1, &t1, p, &t2, Some(&mask)).value,
            &p2,
            &r.grad_s2,
            1e-6,
            1e-5,
            1e-5,
        );
    }
}

#[test]
fn mask_mse_of_known_values_and_gradient() {
    let r = mask_mse(&[1.0, 0.5, 0.0, 0.25], &[1.0, 0.0, 1.0, 0.25], None);
    assert_eq!(r.value, (0.25 + 1.0) / 4.0);
    assert_eq!(r.grad, vec![0.0, 0.25, -0.5, 0.0]);
    // A weight of 0 leaves the second pixel out; the mean still counts four pixels.
    let weighted = mask_mse(
        &[1.0, 0.5, 0.0, 0.25],
        &[1.0, 0.0, 1.0, 0.25],
        Some(&[1.0, 0.0, 0.5, 1.0]),
    );
    assert_eq!(weighted.value, 0.5 / 4.0);
    assert_eq!(weighted.grad, vec![0.0, 0.0, -0.25, 0.0]);
    for seed in SEEDS {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let alpha = random_vec(&mut rng, W * H, 0.0, 1.0);
        let mask: Vec<f64> = (0..W * H)
            .map(|_| f64::from(rng.random_bool(0.5)))
            .collect();
        let weight: Vec<f32> = (0..W * H).map(|_| rng.random_range(0.0..1.0)).collect();
        for weight in [None, Some(weight.as_slice())] {
            let r = mask_mse(&alpha, &mask, weight);
            assert_gradient(
                "mask_mse",
                &mut |a| mask_mse(a, &mask, weight).value,
                &alpha,
                &r.grad,
                1e-6,
                1e-5,
                1e-5,
            );
        }
    }
}

/// The (weight, depth) of each surfel a pixel composites, front to back.
type Layers = Vec<(f64, f64)>;

/// Per pixel, a few surfels' weights and depths, and the G-buffers they composite to: α = Σ w,
/// depth = Σ w z / α, depth_sq = Σ w z² / α.
fn composited(rng: &mut ChaCha8Rng, pixels: usize) -> (Vec<Layers>, [Vec<f64>; 3]) {
    let layers: Vec<Layers> = (0..pixels)
        .map(|_| {
            let n = rng.random_range(0..4);
            (0..n)
                .map(|_| (rng.random_range(0.0..0.4), rng.random_range(2.0..6.0)))
                .collect()
        })
        .collect();
    let mut buffers = [vec![0.0; pixels], vec![0.0; pixels], vec![0.0; pixels]];
    for (p, l) in layers.iter().enumerate() {
        let a: f64 = l.iter().map(|(w, _)| w).sum();
        buffers[0][p] = a;
        if a > 0.0 {
            buffers[1][p] = l.iter().map(|(w, z)| w * z).sum::<f64>() / a;
            buffers[2][p] = l.iter().map(|(w, z)| w * z * z).sum::<f64>() / a;
        }
    }
    (layers, buffers)
}

#[test]
fn depth_distortion_is_the_pairwise_spread_of_the_weights() {
    for seed in SEEDS {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let (layers, [alpha, depth, depth_sq]) = composited(&mut rng, W * H);
        let scale = 0.7;
        // 2DGS's ordered pairs, Σ_i Σ_{j<i} w_i w_j (z_i − z_j)², in units of the scale.
        let pairwise: f64 = layers
            .iter()
            .map(|l| {
                let mut sum = 0.0;
                for (i, (wi, zi)) in l.iter().enumerate() {
                    for (wj, zj) in &l[..i] {
                        sum += wi * wj * (zi - zj) * (zi - zj);
                    }
                }
                sum
            })
            .sum::<f64>()
            / ((W * H) as f64 * scale * scale);
        let r = depth_distortion(&alpha, &depth, &depth_sq, scale);
        assert!(
            (r.value - pairwise).abs() < 1e-12 * pairwise.max(1.0),
            "{} vs {pairwise}",
            r.value
        );
        assert!(pairwise > 0.0);
    }
    // One surfel, or all at one depth: no distortion.
    let r = depth_distortion(&[0.8, 0.5], &[3.0, 2.0], &[9.0, 4.0], 1.0);
    assert_eq!(r.value, 0.0);
}

#[test]
fn depth_distortion_gradients_match_finite_differences() {
    for seed in SEEDS {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let alpha = random_vec(&mut rng, W * H, 0.0, 1.0);
        let depth = random_vec(&mut rng, W * H, 1.0, 5.0);
        let depth_sq: Vec<f64> = depth
            .iter()
            .map(|z| z * z + rng.random_range(0.0..0.5))
            .collect();
        let scale = rng.random_range(0.5..2.0);
        let r = depth_distortion(&alpha, &depth, &depth_sq, scale);
        assert_gradient(
            "depth_distortion wrt alpha",
            &mut |a| depth_distortion(a, &depth, &depth_sq, scale).value,
            &alpha,
            &r.grad_alpha,
            1e-6,
            1e-5,
            1e-5,
        );
        assert_gradient(
            "depth_distortion wrt depth",
            &mut |d| depth_distortion(&alpha, d, &depth_sq, scale).value,
            &depth,
            &r.grad_depth,
            1e-6,
            1e-5,
            1e-5,
        );
        assert_gradient(
            "depth_distortion wrt depth_sq",
            &mut |q| depth_distortion(&alpha, &depth, q, scale).value,
            &depth_sq,
            &r.grad_depth_sq,
            1e-6,
            1e-5,
            1e-5,
        );
    }
}

/// The bits of each value, so that two computations can be compared exactly.
fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

#[test]
fn the_premultiplied_stokes_loss_equals_stokes_l1_of_the_premultiplied_images() {
    // Larger than one chunk, so the chunked sums are exercised; some targets equal to the
    // prediction (subgradient 0), α of 0 and 1.
    let pixels = CHUNK + 517;
    for seed in SEEDS {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let rgb = |rng: &mut ChaCha8Rng| -> Vec<DVec3> {
            (0..pixels)
                .map(|_| DVec3::from_slice(&random_vec(rng, 3, -0.4, 0.4)))
                .collect()
        };
        let (mut s1, s2) = (rgb(&mut rng), rgb(&mut rng));
        let mut alpha = random_vec(&mut rng, pixels, 0.0, 1.0);
        alpha[0] = 0.0;
        alpha[1] = 1.0;
        let samples = |rng: &mut ChaCha8Rng| -> Vec<f32> {
            (0..3 * pixels)
                .map(|_| rng.random_range(-0.4f32..0.4))
                .collect()
        };
        let (mut t1, t2) = (samples(&mut rng), samples(&mut rng));
        let gains = [1.25f32, 0.75, 1.5];
        t1[3] = 0.0; // pixel 1 (α = 1): prediction equal to the target below
        s1[1].x = f64::from(t1[3] * gains[0]);
        let premul = |v: &[DVec3]| -> Vec<f64> {
            v.iter()
                .zip(&alpha)
                .flat_map(|(x, &a)| (*x * a).to_array())
                .collect()
        };
        let fitted = |t: &[f32]| -> Vec<f64> {
            t.iter()
                .enumerate()
                .map(|(i, &v)| f64::from(v * gains[i % 3]))
                .collect()
        };
        let reference = stokes_l1(&premul(&s1), &fitted(&t1), &premul(&s2), &fitted(&t2), None);
        let fused = stokes_l1_premultiplied((&s1, &s2), &alpha, (&t1, &t2), gains);
        assert_eq!(fused.value.to_bits(), reference.value.to_bits());
        assert_eq!(bits(&fused.grad_s1), bits(&reference.grad_s1));
        assert_eq!(bits(&fused.grad_s2), bits(&reference.grad_s2));
        assert_eq!(fused.grad_s1[3], 0.0);
    }
}

#[test]
fn normal_smoothness_of_a_hand_example() {
    // 2×1 image: one horizontal pair, normals (0,0,1) → (0,1,0), so ‖Δ‖ = √2.
    let normal = [0.0, 0.0, 1.0, 0.0, 1.0, 0.0];
    let edge = (2.0 + NORMAL_SMOOTH_EPS).sqrt() - NORMAL_SMOOTH_EPS.sqrt();
    let flat = normal_smoothness(&normal, &[0.5; 6], 2, 1);
    assert!((flat.value - edge / 2.0).abs() < 1e-15);
    // An image edge of mean height 1 damps the term by e^-1.
    let s0 = [0.0, 0.0, 0.0, 1.0, 2.0, 0.0];
    let damped = normal_smoothness(&normal, &s0, 2, 1);
    assert!((damped.value - edge / 2.0 * (-1.0f64).exp()).abs() < 1e-15);
    // A constant normal map is perfectly smooth.
    let constant: Vec<f64> = [0.0, 0.6, 0.8].repeat(W * H);
    let r = normal_smoothness(&constant, &vec![0.3; W * H * 3], W, H);
    assert_eq!(r.value, 0.0);
    assert!(r.grad.iter().all(|&g| g == 0.0));
}

#[test]
fn normal_smoothness_gradient_matches_finite_differences() {
    for seed in SEEDS {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let normal = random_vec(&mut rng, W * H * 3, -1.0, 1.0);
        let s0 = random_vec(&mut rng, W * H * 3, 0.0, 1.0);
        let r = normal_smoothness(&normal, &s0, W, H);
        assert_gradient(
            "normal_smoothness",
            &mut |n| normal_smoothness(n, &s0, W, H).value,
            &normal,
            &r.grad,
            1e-6,
            1e-5,
            1e-5,
        );
    }
}

#[test]
fn depth_normal_consistency_of_a_hand_example() {
    // Pixel 0 aligned (rendered normal not unit: normalization matters), pixel 1 orthogonal,
    // pixel 2 background (zero rendered normal): excluded from the mean.
    let normal = [0.0, 0.0, 2.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0];
    let depth = [0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0];
    let r = depth_normal_consistency(&normal, &depth, None);
    assert!((r.value - 0.5).abs() < 1e-15);
    assert!(r.grad_normal[6..].iter().all(|&g| g == 0.0));
    assert!(r.grad_depth_normal[6..].iter().all(|&g| g == 0.0));
    // Pixel 1 (orthogonal): ∂/∂N_x = −(1 − 0)/(2·1) = −0.5; ∂/∂N_d,z = −N̂_z/2 = −0.5.
    assert_eq!(r.grad_normal[3], -0.5);
    assert_eq!(r.grad_depth_normal[5], -0.5);
    let weighted = depth_normal_consistency(&normal, &depth, Some(&[1.0, 0.5, 1.0]));
    assert!((weighted.value - 0.25).abs() < 1e-15);
    let none = depth_normal_consistency(&[0.0; 3], &[0.0, 0.0, 1.0], None);
    assert_eq!(none.value, 0.0);
}

#[test]
fn depth_normal_consistency_gradients_match_finite_differences() {
    for seed in SEEDS {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let normal = random_vec(&mut rng, W * H * 3, -1.0, 1.0);
        let depth_normal = random_vec(&mut rng, W * H * 3, -1.0, 1.0);
        let weight = random_vec(&mut rng, W * H, 0.0, 1.0);
        for w in [None, Some(&weight[..])] {
            let r = depth_normal_consistency(&normal, &depth_normal, w);
            assert_gradient(
                "depth_normal_consistency wrt normal",
                &mut |n| depth_normal_consistency(n, &depth_normal, w).value,
                &normal,
                &r.grad_normal,
                1e-6,
                1e-5,
                1e-4,
            );
            assert_gradient(
                "depth_normal_consistency wrt depth normal",
                &mut |d| depth_normal_consistency(&normal, d, w).value,
                &depth_normal,
                &r.grad_depth_normal,
                1e-6,
                1e-5,
                1e-4,
            );
        }
    }
}

#[test]
fn loss_weights_come_from_the_config() {
    let config = TrainConfig {
        lambda_stokes: 4.0,
        ..TrainConfig::default()
    };
    let w = LossWeights::from(&config);
    assert_eq!(
        w,
        LossWeights {
            lambda_ssim: 0.2,
            lambda_stokes: 4.0,
            lambda_mask: 0.4,
            lambda_normal_smooth: 0.2,
            lambda_depth_normal: 0.1,
            lambda_distortion: config.lambda_distortion,
            lambda_aolp: config.lambda_aolp,
            distortion_scale: 1.0,
        }
    );
    let object = LossWeights::for_object(&config, 2.5);
    assert_eq!(object.distortion_scale, 2.5);
    assert_eq!(object.lambda_stokes, 4.0);
    assert_eq!(
        LossWeights::for_object(&config, f64::NAN).distortion_scale,
        1.0
    );
}

/// Timing of SSIM forward + backward at 256×256×3 (run with `--ignored --nocapture`).
#[test]
#[ignore]
fn ssim_timing_256() {
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let n = 256 * 256 * 3;
    let x = random_vec(&mut rng, n, 0.0, 1.0);
    let y = random_vec(&mut rng, n, 0.0, 1.0);
    let _ = ssim(&x, &y, 256, 256, 3);
    let runs = 20;
    let start = std::time::Instant::now();
    for _ in 0..runs {
        std::hint::black_box(ssim(&x, &y, 256, 256, 3));
    }
    let per = start.elapsed().as_secs_f64() / runs as f64;
    println!("ssim 256x256x3 forward+backward: {:.2} ms", per * 1e3);
}

/// `f` on a rayon pool of `threads` threads.
fn on_threads<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
        .install(f)
}

#[test]
fn chunked_losses_match_their_serial_definitions_for_any_thread_count() {
    let mut rng = ChaCha8Rng::seed_from_u64(9);
    // Several chunks and a ragged last one.
    let n = 3 * CHUNK + 123;
    let pred = random_vec(&mut rng, n, -1.0, 2.0);
    let target = random_vec(&mut rng, n, 0.0, 1.0);
    let l = l1(&pred, &target, None);
    let serial = pred
        .iter()
        .zip(&target)
        .map(|(p, t)| (p - t).abs())
        .sum::<f64>()
        / n as f64;
    assert!((l.value - serial).abs() < 1e-12);
    for ((g, p), t) in l.grad.iter().zip(&pred).zip(&target) {
        assert_eq!(*g, (p - t).signum() / n as f64);
    }
    let mask = mask_mse(&pred, &target, None);
    let serial = pred
        .iter()
        .zip(&target)
        .map(|(p, t)| (p - t) * (p - t))
        .sum::<f64>()
        / n as f64;
    assert!((mask.value - serial).abs() < 1e-12);
    // Depth–normal consistency with a third of the pixels empty (excluded from the mean).
    let pixels = 2 * CHUNK + 77;
    let mut normal = random_vec(&mut rng, pixels * 3, -1.0, 1.0);
    let depth_normal = random_vec(&mut rng, pixels * 3, -1.0, 1.0);
    normal.chunks_exact_mut(9).for_each(|c| c[..3].fill(0.0));
    let dn = depth_normal_consistency(&normal, &depth_normal, None);
    let terms: Vec<f64> = normal
        .chunks_exact(3)
        .zip(depth_normal.chunks_exact(3))
        .filter(|(n, _)| n.iter().any(|&v| v != 0.0))
        .map(|(n, d)| {
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            1.0 - (n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / len
        })
        .collect();
    let serial = terms.iter().sum::<f64>() / terms.len() as f64;
    assert!((dn.value - serial).abs() < 1e-12);
    let alpha = random_vec(&mut rng, pixels, 0.0, 1.0);
    let depth = random_vec(&mut rng, pixels, 1.0, 5.0);
    let depth_sq: Vec<f64> = depth.iter().map(|z| z * z + 0.1).collect();
    let distortion = depth_distortion(&alpha, &depth, &depth_sq, 1.0);
    let serial = alpha
        .iter()
        .zip(&depth)
        .zip(&depth_sq)
        .map(|((a, z), q)| a * a * (q - z * z))
        .sum::<f64>()
        / pixels as f64;
    assert!((distortion.value - serial).abs() < 1e-12);
    // Bit for bit the same on one thread and on three.
    let run = || {
        (
            l1(&pred, &target, None),
            mask_mse(&pred, &target, None),
            depth_normal_consistency(&normal, &depth_normal, None),
            depth_distortion(&alpha, &depth, &depth_sq, 1.0),
        )
    };
    assert_eq!(on_threads(1, run), on_threads(3, run));
}

/// A camera of W × H pixels looking at the origin.
fn aolp_camera() -> Camera {
    Camera::look_at(
        W as u32,
        H as u32,
        0.8,
        DVec3::new(0.4, -3.0, 1.2),
        DVec3::ZERO,
        DVec3::Z,
    )
}

/// Random measured polarization, a fifth of the pixels off the object.
fn random_polarization(rng: &mut ChaCha8Rng, pixels: usize) -> Vec<[f64; 2]> {
    (0..pixels)
        .map(|_| {
            if rng.random_bool(0.2) {
                [0.0, 0.0]
            } else {
                let (dolp, psi) = (rng.random_range(0.0..1.0), rng.random_range(0.0..3.2f64));
                [dolp * (2.0 * psi).cos(), dolp * (2.0 * psi).sin()]
            }
        })
        .collect()
}

#[test]
fn aolp_normal_vanishes_on_the_normal_azimuth_and_across_it() {
    let camera = aolp_camera();
    let pixels = camera.num_pixels();
    let mut rng = ChaCha8Rng::seed_from_u64(4);
    // Each pixel's normal at a random azimuth φ in its Stokes frame, tilted towards the camera
    // and of random length; the AoLP along it (diffuse), across it (specular), at 30° from it, or
    // nothing measured.
    let mut normal = Vec::new();
    let mut polarization = Vec::new();
    let mut expected = 0.0;
    for p in 0..pixels {
        let d = camera.pixel_dir((p % W) as u32, (p / W) as u32);
        let (x, y) = camera.stokes_frame(d);
        let phi: f64 = rng.random_range(0.0..6.3);
        let n = (x * phi.cos() + y * phi.sin() - d * 0.7) * rng.random_range(0.2..2.0);
        normal.extend(n.to_array());
        let dolp = 0.6;
        let psi = phi + [0.0, 90f64.to_radians(), 30f64.to_radians(), 0.0][p % 4];
        polarization.push(if p % 4 == 3 {
            [0.0, 0.0]
        } else {
            [dolp * (2.0 * psi).cos(), dolp * (2.0 * psi).sin()]
        });
        if p % 4 == 2 {
            expected += (dolp * 60f64.to_radians().sin()).powi(2);
        }
    }
    let r = aolp_normal(&normal, &camera, &polarization);
    expected /= pixels as f64;
    assert!(
        (r.value - expected).abs() < 1e-12 * expected,
        "{} vs {expected}",
        r.value
    );
    for (p, g) in r.grad.chunks(3).enumerate() {
        let g = DVec3::from_slice(g);
        match p % 4 {
            0 | 1 => assert!(g.length() < 1e-12, "pixel {p}: {g}"),
            2 => assert!(g.length() > 1e-4, "pixel {p}: {g}"),
            _ => assert_eq!(g, DVec3::ZERO),
        }
    }
}

#[test]
fn aolp_normal_gradient_matches_finite_differences() {
    let camera = aolp_camera();
    for seed in SEEDS {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let normal = random_vec(&mut rng, 3 * W * H, -1.0, 1.0);
        let polarization = random_polarization(&mut rng, W * H);
        let r = aolp_normal(&normal, &camera, &polarization);
        assert!(r.value > 0.0);
        assert_gradient(
            "aolp_normal wrt normal",
            &mut |n| aolp_normal(n, &camera, &polarization).value,
            &normal,
            &r.grad,
            1e-6,
            1e-5,
            1e-5,
        );
    }
}

#[test]
fn measured_polarization_is_the_channel_mean_stokes_ratio_on_the_object() {
    // Pixel 0: DoLP 0.5 at ψ = 30°; 1: off the object; 2: S1 > S0 (clamped to DoLP 1); 3: black.
    let (c, s) = (
        0.5 * 60f64.to_radians().cos(),
        0.5 * 60f64.to_radians().sin(),
    );
    let s0 = [0.2, 0.4, 0.6, 1.0, 1.0, 1.0, 0.1, 0.1, 0.1, 0.0, 0.0, 0.0];
    let s1 = [
        0.4 * c as f32,
        0.4 * c as f32,
        0.4 * c as f32,
        0.3,
        0.3,
        0.3,
        0.3,
        0.3,
        0.3,
        1e-5,
        0.0,
        0.0,
    ];
    let s2 = [
        0.4 * s as f32,
        0.4 * s as f32,
        0.4 * s as f32,
        0.3,
        0.3,
        0.3,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ];
    let mask = [1.0, 0.2, 1.0, 1.0];
    let m = measured_polarization(&s0, &s1, &s2, &mask, 1.0, None);
    assert!(
        (m[0][0] - c).abs() < 1e-6 && (m[0][1] - s).abs() < 1e-6,
        "{:?}",
        m[0]
    );
    assert_eq!(m[1], [0.0, 0.0]);
    assert!(
        (m[2][0] - 1.0).abs() < 1e-12 && m[2][1] == 0.0,
        "{:?}",
        m[2]
    );
    assert!(
        (m[3][0] - 1e-5 / 3.0 / POLARIZATION_MIN_S0).abs() < 1e-9,
        "{:?}",
        m[3]
    );
    // A pixel's confidence scales its measured polarization.
    let confidence = [0.25, 1.0, 0.0, 1.0];
    let weighted = measured_polarization(&s0, &s1, &s2, &mask, 1.0, Some(&confidence));
    assert_eq!(weighted[0], m[0].map(|v| 0.25 * v));
    assert_eq!(weighted[2], [0.0, 0.0]);
    assert_eq!(weighted[3], m[3]);
}
