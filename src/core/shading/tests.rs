use std::sync::Arc;

use glam::DVec3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use super::*;
use crate::core::camera::stokes_frame;
use crate::core::envmap::{CubeMap, MipChainSpec, PrefilterPlan, PreparedEnv};
use crate::core::gradcheck::assert_gradient;
use crate::testing::random_unit;

fn tiny_plan(fresnel: bool) -> Arc<PrefilterPlan> {
    PrefilterPlan::new(MipChainSpec {
        base_size: 8,
        min_size: 2,
        fresnel_irradiance: fresnel,
        ..MipChainSpec::default()
    })
    .unwrap()
}

fn random_cube(rng: &mut ChaCha8Rng) -> CubeMap {
    let raw = (0..CubeMap::num_values(8))
        .map(|_| rng.random_range(-2.0..2.0))
        .collect();
    CubeMap::from_raw(8, raw).unwrap()
}

/// A random pixel whose normal faces the viewer at a random angle (or, with `flipped`, whose raw
/// normal points away and must be flipped).
fn random_input(rng: &mut ChaCha8Rng, flipped: bool) -> PixelInput {
    let view = random_unit(rng);
    let up = random_unit(rng);
    let (stokes_x, stokes_y) = stokes_frame(-view, up);
    let normal = loop {
        let n = random_unit(rng);
        if n.dot(view) > 0.15 {
            break n;
        }
    };
    let scale = rng.random_range(0.5..2.0) * if flipped { -1.0 } else { 1.0 };
    PixelInput {
        position: DVec3::ZERO,
        normal: normal * scale,
        view,
        stokes_x,
        stokes_y,
        albedo: DVec3::new(rng.random(), rng.random(), rng.random()),
        roughness: rng.random_range(0.1..0.95),
        ior: rng.random_range(1.35..2.25),
    }
}

fn random_upstream(rng: &mut ChaCha8Rng) -> PixelStokesGrad {
    let mut v = || {
        DVec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        )
    };
    PixelStokesGrad {
        s0: v(),
        s1: v(),
        s2: v(),
    }
}

fn loss(s: &PixelStokes, g: &PixelStokesGrad) -> f64 {
    s.s0.dot(g.s0) + s.s1.dot(g.s1) + s.s2.dot(g.s2)
}

fn pack(i: &PixelInput) -> Vec<f64> {
    vec![
        i.normal.x,
        i.normal.y,
        i.normal.z,
        i.albedo.x,
        i.albedo.y,
        i.albedo.z,
        i.roughness,
        i.ior,
    ]
}

fn unpack(base: &PixelInput, x: &[f64]) -> PixelInput {
    PixelInput {
        normal: DVec3::new(x[0], x[1], x[2]),
        albedo: DVec3::new(x[3], x[4], x[5]),
        roughness: x[6],
        ior: x[7],
        ..*base
    }
}

/// Checks [`shade_backward`]'s input gradient of one pixel under `light` against finite
/// differences of [`shade`] (in the order of [`pack`]).
fn assert_shade_gradient(
    name: &str,
    input: &PixelInput,
    light: &dyn LightProbe,
    lut: &BrdfLut,
    up: &PixelStokesGrad,
) {
    let mut scratch = light.zero_grad();
    let g = shade_backward(input, light, lut, up, &mut scratch);
    let analytic = [
        g.normal.x,
        g.normal.y,
        g.normal.z,
        g.albedo.x,
        g.albedo.y,
        g.albedo.z,
        g.roughness,
        g.ior,
    ];
    let mut f = |x: &[f64]| loss(&shade(&unpack(input, x), light, lut), up);
    assert_gradient(name, &mut f, &pack(input), &analytic, 1e-6, 1e-4, 1e-6);
}

#[test]
fn fresnel_ratios_have_the_physical_signs_and_values() {
    for eta in [1.3, 1.5, 2.2] {
        let brewster = (1.0f64 / (1.0 + eta * eta)).sqrt(); // cos of atan(η)
        let (rho_s, _) = polarization_ratios(brewster, eta);
        assert!(
            (rho_s.v - 1.0).abs() < 1e-9,
            "fully polarized at Brewster's angle"
        );
        let (rho_s, rho_d) = polarization_ratios(1.0, eta);
        assert!(
            rho_s.v.abs() < 1e-12 && rho_d.v.abs() < 1e-12,
            "unpolarized head-on"
        );
        for k in 1..20 {
            let mu = k as f64 / 20.0;
            let (rho_s, rho_d) = polarization_ratios(mu, eta);
            assert!(rho_s.v > 0.0 && rho_s.v <= 1.0 + 1e-12);
            assert!(rho_d.v < 0.0);
            // The textbook diffuse DoLP (Atkinson & Hancock 2006).
            let s2 = 1.0 - mu * mu;
            let n = eta;
            let expected = (n - 1.0 / n).powi(2) * s2
                / (2.0 + 2.0 * n * n - (n + 1.0 / n).powi(2) * s2 + 4.0 * mu * (n * n - s2).sqrt());
            assert!(
                (-rho_d.v - expected).abs() < 1e-12,
                "μ {mu}: {} vs {expected}",
                -rho_d.v
            );
        }
    }
    // Derivatives of the ratios.
    let mut rng = ChaCha8Rng::seed_from_u64(4);
    for _ in 0..20 {
        let x = [rng.random_range(0.05..0.99), rng.random_range(1.3..2.3)];
        let (s, d) = polarization_ratios(x[0], x[1]);
        let mut fs = |x: &[f64]| polarization_ratios(x[0], x[1]).0.v;
        assert_gradient("rho_s", &mut fs, &x, &[s.dmu, s.deta], 1e-7, 1e-6, 1e-6);
        let mut fd = |x: &[f64]| polarization_ratios(x[0], x[1]).1.v;
        assert_gradient("rho_d", &mut fd, &x, &[d.dmu, d.deta], 1e-7, 1e-6, 1e-6);
    }
}

#[test]
fn specular_aolp_is_perpendicular_and_diffuse_parallel_to_the_normal_azimuth() {
    let env =
        PreparedEnv::new(&CubeMap::constant(8, DVec3::ONE).unwrap(), tiny_plan(false)).unwrap();
    let lut = BrdfLut::compute(64, 64);
    let view = DVec3::Z;
    let (stokes_x, stokes_y) = stokes_frame(-view, DVec3::Y);
    for azimuth in [0.0f64, 0.4, 1.1, 2.0, -0.7] {
        let tilt: f64 = 0.9;
        let normal = DVec3::new(
            tilt.sin() * (azimuth.cos() * stokes_x.x + azimuth.sin() * stokes_y.x),
            tilt.sin() * (azimuth.cos() * stokes_x.y + azimuth.sin() * stokes_y.y),
            tilt.cos(),
        );
        let base = PixelInput {
            position: DVec3::ZERO,
            normal,
            view,
            stokes_x,
            stokes_y,
            albedo: DVec3::ZERO,
            roughness: 0.3,
            ior: 1.5,
        };
        let spec = shade(&base, &env, &lut);
        let psi = aolp(spec.s1.x, spec.s2.x);
        assert!(
            aolp_difference(psi, azimuth + std::f64::consts::FRAC_PI_2) < 1e-9,
            "specular: ψ = φ + 90°"
        );
        // A bright diffuse surface with a weak specular part: ψ = φ.
        let diffuse = shade(
            &PixelInput {
                albedo: DVec3::splat(1.0),
                ior: 1.3,
                roughness: 0.9,
                normal: normal * 0.5 + view * 0.0,
                ..base
            },
            &env,
            &lut,
        );
        let diffuse_part = diffuse.diffuse.x * polarization_ratios(normal.dot(view), 1.3).1.v.abs();
        let specular_part = diffuse.specular.x * polarization_ratios(normal.dot(view), 1.3).0.v;
        assert!(diffuse_part > specular_part);
        assert!(
            aolp_difference(aolp(diffuse.s1.x, diffuse.s2.x), azimuth) < 1e-9,
            "diffuse: ψ = φ"
        );
    }
}

#[test]
fn shade_gradients_match_finite_differences() {
    let lut = BrdfLut::compute(32, 64);
    for (seed, fresnel) in [(1u64, false), (2, false), (3, true), (4, false), (5, true)] {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let env = PreparedEnv::new(&random_cube(&mut rng), tiny_plan(fresnel)).unwrap();
        for k in 0..12 {
            let input = random_input(&mut rng, k % 3 == 2);
            let up = random_upstream(&mut rng);
            assert_shade_gradient(
                &format!("shade inputs (seed {seed}, pixel {k})"),
                &input,
                &env,
                &lut,
                &up,
            );
        }
    }
}

/// Under GridMap the forward keeps its lookups' Jacobians and the backward applies them
/// ([`SavedLookup`]) instead of asking the light again: the inputs' gradients still match finite
/// differences, on pixels whose mirror rays are blocked (the probes' blend) and escape (the
/// global map, which also takes the gradient).
#[test]
fn shade_gradients_under_gridmap_match_finite_differences() {
    use crate::core::gridmap::{AnchorPlacement, GridMap};
    use crate::testing::two_spheres;

    let lut = BrdfLut::compute(32, 64);
    let (mesh, surfels) = two_spheres();
    let (mut blocked, mut escaping) = (0, 0);
    for (seed, fresnel) in [(21u64, false), (22, true)] {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let cube = random_cube(&mut rng);
        let global = PreparedEnv::new(&cube, tiny_plan(fresnel)).unwrap();
        let grid = GridMap::build(&mesh, &surfels, &cube, global, AnchorPlacement::Box).unwrap();
        for k in 0..12 {
            // A point of sphere A facing sphere B (centre (3, 0, 0)).
            let towards_b = DVec3::new(
                1.0,
                rng.random_range(-0.4..0.4),
                rng.random_range(-0.4..0.4),
            );
            let mut input = random_input(&mut rng, k % 3 == 2);
            input.position = towards_b.normalize();
            // Normal near the sphere's, viewed from near it: mirror rays toward B or the sky.
            let normal = (input.position + 0.2 * random_unit(&mut rng)).normalize();
            input.view = loop {
                let v = (normal + 0.8 * random_unit(&mut rng)).normalize();
                if v.dot(normal) > 0.15 {
                    break v;
                }
            };
            (input.stokes_x, input.stokes_y) = stokes_frame(-input.view, random_unit(&mut rng));
            input.normal = normal * input.normal.length() * if k % 3 == 2 { -1.0 } else { 1.0 };
            let unit = input.normal.normalize() * input.normal.dot(input.view).signum();
            let mirror = 2.0 * unit.dot(input.view) * unit - input.view;
            if grid.occluded(input.position, mirror) {
                blocked += 1;
            } else {
                escaping += 1;
            }
            let up = random_upstream(&mut rng);
            assert_shade_gradient(
                &format!("shade inputs under GridMap (seed {seed}, pixel {k})"),
                &input,
                &grid,
                &lut,
                &up,
            );
        }
    }
    assert!(
        blocked >= 3 && escaping >= 3,
        "{blocked} blocked, {escaping} escaping"
    );
}

#[test]
fn shade_gradient_reaches_the_env_texels() {
    let lut = BrdfLut::compute(32, 64);
    for (seed, fresnel) in [(10u64, false), (11, true)] {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let plan = tiny_plan(fresnel);
        let cube = random_cube(&mut rng);
        let pixels: Vec<(PixelInput, PixelStokesGrad)> = (0..5)
            .map(|_| (random_input(&mut rng, false), random_upstream(&mut rng)))
            .collect();
        let env = PreparedEnv::new(&cube, plan.clone()).unwrap();
        let mut grad = env.zero_grad();
        for (input, up) in &pixels {
            shade_backward(input, &env, &lut, up, &mut grad);
        }
        let analytic = env.backward(&grad);
        let mut f = |x: &[f64]| {
            let env =
                PreparedEnv::new(&CubeMap::from_raw(8, x.to_vec()).unwrap(), plan.clone()).unwrap();
            pixels
                .iter()
                .map(|(i, up)| loss(&shade(i, &env, &lut), up))
                .sum()
        };
        assert_gradient(
            "env texels through shade",
            &mut f,
            &cube.raw,
            &analytic,
            1e-6,
            1e-4,
            1e-6,
        );
    }
}

#[test]
fn polarizer_intensity_and_its_gradient() {
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    for _ in 0..10 {
        let mut v = || {
            DVec3::new(
                rng.random(),
                rng.random_range(-0.5..0.5),
                rng.random_range(-0.5..0.5),
            )
        };
        let s = PixelStokes {
            s0: v() + DVec3::ONE,
            s1: v(),
            s2: v(),
            ..Default::default()
        };
        use std::f64::consts::FRAC_PI_4;
        let i = |k: f64| polarizer_intensity(&s, k * FRAC_PI_4);
        assert!((i(0.0) + i(2.0)).abs_diff_eq(s.s0, 1e-12));
        assert!((i(0.0) - i(2.0)).abs_diff_eq(s.s1, 1e-12));
        assert!((i(1.0) - i(3.0)).abs_diff_eq(s.s2, 1e-12));
        let theta = rng.random_range(0.0..std::f64::consts::PI);
        let g = DVec3::new(rng.random(), rng.random(), rng.random());
        let (gs, gt) = polarizer_intensity_backward(&s, theta, g);
        let x: Vec<f64> = [s.s0, s.s1, s.s2]
            .iter()
            .flat_map(|v| v.to_array())
            .chain([theta])
            .collect();
        let analytic: Vec<f64> = [gs.s0, gs.s1, gs.s2]
            .iter()
            .flat_map(|v| v.to_array())
            .chain([gt])
            .collect();
        let mut f = |x: &[f64]| {
            let s = PixelStokes {
                s0: DVec3::from_slice(&x[0..3]),
                s1: DVec3::from_slice(&x[3..6]),
                s2: DVec3::from_slice(&x[6..9]),
                ..Default::default()
            };
            polarizer_intensity(&s, x[9]).dot(g)
        };
        assert_gradient("polarizer", &mut f, &x, &analytic, 1e-6, 1e-7, 1e-8);
    }
}

#[test]
fn degenerate_pixels_stay_finite() {
    let lut = BrdfLut::compute(32, 32);
    let mut rng = ChaCha8Rng::seed_from_u64(21);
    let env = PreparedEnv::new(&random_cube(&mut rng), tiny_plan(true)).unwrap();
    let view = DVec3::Z;
    let (stokes_x, stokes_y) = stokes_frame(-view, DVec3::Y);
    let up = random_upstream(&mut rng);
    for normal in [
        DVec3::X,
        DVec3::new(1.0, 0.0, -1e-9),
        DVec3::Z,
        -DVec3::Z,
        DVec3::ZERO,
        DVec3::new(0.0, 1e-30, 1e-30),
    ] {
        for (roughness, ior) in [(0.0, 1.0), (1.0, 2.3), (0.5, 1.5)] {
            let input = PixelInput {
                position: DVec3::ZERO,
                normal,
                view,
                stokes_x,
                stokes_y,
                albedo: DVec3::ONE,
                roughness,
                ior,
            };
            let s = shade(&input, &env, &lut);
            let mut g = env.zero_grad();
            let d = shade_backward(&input, &env, &lut, &up, &mut g);
            let all = [
                s.s0,
                s.s1,
                s.s2,
                d.normal,
                d.albedo,
                DVec3::new(d.roughness, d.ior, 0.0),
            ];
            assert!(
                all.iter().all(|v| v.is_finite()),
                "{normal} r {roughness} η {ior}: {s:?} {d:?}"
            );
            assert!(g
                .levels
                .iter()
                .chain(&g.irradiance)
                .flatten()
                .all(|v| v.is_finite()));
        }
    }
}

#[test]
fn image_batch_matches_per_pixel_shading() {
    let lut = BrdfLut::compute(32, 64);
    let mut rng = ChaCha8Rng::seed_from_u64(31);
    let env = PreparedEnv::new(&random_cube(&mut rng), tiny_plan(false)).unwrap();
    let camera = Camera::look_at(
        13,
        9,
        0.9,
        DVec3::new(0.5, -3.0, 1.0),
        DVec3::ZERO,
        DVec3::Z,
    );
    let n = camera.num_pixels();
    let normal: Vec<DVec3> = (0..n).map(|_| random_unit(&mut rng)).collect();
    let albedo: Vec<DVec3> = (0..n)
        .map(|_| DVec3::new(rng.random(), rng.random(), rng.random()))
        .collect();
    let roughness: Vec<f64> = (0..n).map(|_| rng.random_range(0.05..1.0)).collect();
    let ior: Vec<f64> = (0..n).map(|_| rng.random_range(1.3..2.3)).collect();
    let active: Vec<bool> = (0..n).map(|p| p % 7 != 3).collect();
    let buffers = ShadingBuffers {
        normal: &normal,
        albedo: &albedo,
        roughness: &roughness,
        ior: &ior,
        position: None,
        active: Some(&active),
    };
    let img = shade_image(&camera, &buffers, &env, &lut).unwrap();
    let ups: Vec<PixelStokesGrad> = (0..n).map(|_| random_upstream(&mut rng)).collect();
    let (s0, s1, s2): (Vec<DVec3>, Vec<DVec3>, Vec<DVec3>) = (
        ups.iter().map(|u| u.s0).collect(),
        ups.iter().map(|u| u.s1).collect(),
        ups.iter().map(|u| u.s2).collect(),
    );
    let (gbuf, env_grad) = shade_image_backward(
        &camera,
        &buffers,
        &env,
        &lut,
        &StokesImageGrad {
            s0: &s0,
            s1: &s1,
            s2: &s2,
        },
    )
    .unwrap();
    // The training step's path keeps the forward intermediates: the same numbers, bit for bit.
    let (img_saved, saved) = shade_image_saved(&camera, &buffers, &env, &lut).unwrap();
    assert_eq!(img_saved, img);
    let (gbuf_saved, env_saved) = shade_image_backward_saved(
        &camera,
        &buffers,
        &env,
        &lut,
        &saved,
        &StokesImageGrad {
            s0: &s0,
            s1: &s1,
            s2: &s2,
        },
    )
    .unwrap();
    assert_eq!(gbuf_saved, gbuf);
    assert_eq!(env_saved.levels, env_grad.levels);
    assert_eq!(env_saved.irradiance, env_grad.irradiance);
    let mut expected_env = env.zero_grad();
    for p in 0..n {
        if !active[p] {
            for plane in [&img.s0, &img.s1, &img.s2, &img.diffuse, &img.specular] {
                assert_eq!(plane[p], DVec3::ZERO);
            }
            assert_eq!(gbuf.normal[p], DVec3::ZERO);
            continue;
        }
        let input = buffers.pixel_input(&camera, p);
        let s = shade(&input, &env, &lut);
        let planes = (
            img.s0[p],
            img.s1[p],
            img.s2[p],
            img.diffuse[p],
            img.specular[p],
        );
        assert_eq!(planes, (s.s0, s.s1, s.s2, s.diffuse, s.specular));
        let g = shade_backward(&input, &env, &lut, &ups[p], &mut expected_env);
        assert_eq!(gbuf.normal[p], g.normal);
        assert_eq!(gbuf.ior[p], g.ior);
    }
    for (a, b) in env_grad
        .levels
        .iter()
        .flatten()
        .zip(expected_env.levels.iter().flatten())
    {
        assert!((a - b).abs() <= 1e-12 * (1.0 + b.abs()));
    }
    let short = ShadingBuffers {
        ior: &ior[1..],
        ..buffers
    };
    let err = shade_image(&camera, &short, &env, &lut)
        .unwrap_err()
        .to_string();
    assert!(err.contains("ior"), "{err}");
}
