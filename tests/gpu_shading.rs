//! Parity of the gpu backend's PolarDR shading with the f64 cpu code of `phygap::core::shading`: the
//! Stokes images, the G-buffer gradients and the light's gradient, on random G-buffers under
//! random environment maps (plain and Fresnel-weighted irradiance), with float atomics and with
//! the compare-and-swap path, and on an image shaded in chunks; GridMap's light over two spheres;
//! a light of another kind is shaded by the cpu code. Skips like tests/gpu_parity.rs where no
//! adapter exists.

use glam::DVec3;
use phygap::core::brdf_lut::BrdfLut;
use phygap::core::camera::Camera;
use phygap::core::engine::Backend;
use phygap::core::envmap::{EnvGrad, PreparedEnv};
use phygap::core::light::LightProbe;
use phygap::core::shading::{self, GBufferGrad, ShadingBuffers, StokesImage, StokesImageGrad};
use phygap::gpu::{AtomicsMode, GpuBackend, GpuOptions};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

mod common;
use common::{gpu, random_camera, random_cube, random_env, worst};

/// Random G-buffers of `pixels` pixels: raw normals of any length and direction (some facing
/// away, a few zero), roughness and IoR beyond both ends of the tables' ranges, 10% inactive.
struct Inputs {
    normal: Vec<DVec3>,
    albedo: Vec<DVec3>,
    roughness: Vec<f64>,
    ior: Vec<f64>,
    active: Vec<bool>,
}

impl Inputs {
    fn random(rng: &mut ChaCha8Rng, pixels: usize) -> Self {
        let mut v = |lo: f64, hi: f64| {
            DVec3::new(
                rng.random_range(lo..hi),
                rng.random_range(lo..hi),
                rng.random_range(lo..hi),
            )
        };
        let normal = (0..pixels)
            .map(|p| {
                if p % 97 == 5 {
                    DVec3::ZERO
                } else {
                    v(-2.0, 2.0)
                }
            })
            .collect();
        let albedo = (0..pixels).map(|_| v(0.0, 1.0)).collect();
        Inputs {
            normal,
            albedo,
            roughness: (0..pixels).map(|_| rng.random_range(-0.1..1.1)).collect(),
            ior: (0..pixels).map(|_| rng.random_range(1.2..2.4)).collect(),
            active: (0..pixels).map(|_| rng.random_bool(0.9)).collect(),
        }
    }

    fn buffers(&self) -> ShadingBuffers<'_> {
        ShadingBuffers {
            normal: &self.normal,
            albedo: &self.albedo,
            roughness: &self.roughness,
            ior: &self.ior,
            position: None,
            active: Some(&self.active),
        }
    }
}

fn random_rgb(rng: &mut ChaCha8Rng, pixels: usize) -> Vec<DVec3> {
    (0..pixels)
        .map(|_| {
            DVec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            )
        })
        .collect()
}

fn flat(v: &[DVec3]) -> Vec<f64> {
    v.iter().flat_map(|x| x.to_array()).collect()
}

/// `|gpu − cpu| ≤ tolerance (|cpu| + floor)` over a buffer, with the floor `floor` times the
/// buffer's largest magnitude (an absolute bound where values are near zero: 1e-2 for the images,
/// whose f32 inputs leave values at grazing angles, where the diffuse term ∝ μ vanishes, a few
/// ulps of the image's scale; 1e-3 for the gradients).
fn assert_close(gpu: &[f64], cpu: &[f64], tolerance: f64, floor: f64, what: &str) -> f64 {
    let scale = cpu.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    assert!(scale > 0.0, "{what}: the cpu buffer is all zero");
    let (e, i) = worst(gpu, cpu, floor * scale);
    assert!(
        e <= tolerance,
        "{what}: relative error {e:.2e} at {i} (gpu {}, cpu {}, scale {scale:.3e})",
        gpu[i],
        cpu[i]
    );
    e
}

/// S0, diffuse and specular as [`assert_close`]; S1 and S2 relative to the pixel's S0 (their
/// bound: |S1|, |S2| ≤ S0), since the polarization ratios lose f32 digits to cancellation where
/// the degree of polarization is small, an error that matters only in proportion to S0.
fn assert_images_close(gpu: &StokesImage, cpu: &StokesImage, what: &str) -> f64 {
    let mut e = [
        ("S0", &gpu.s0, &cpu.s0),
        ("diffuse", &gpu.diffuse, &cpu.diffuse),
        ("specular", &gpu.specular, &cpu.specular),
    ]
    .iter()
    .map(|(name, g, c)| assert_close(&flat(g), &flat(c), 1e-4, 1e-2, &format!("{what} {name}")))
    .fold(0.0, f64::max);
    let s0 = flat(&cpu.s0);
    let floor = 1e-3 * s0.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for (name, g, c) in [("S1", &gpu.s1, &cpu.s1), ("S2", &gpu.s2, &cpu.s2)] {
        let (g, c) = (flat(g), flat(c));
        let (worst, i) = g
            .iter()
            .zip(&c)
            .zip(&s0)
            .map(|((g, c), s0)| (g - c).abs() / (s0.abs() + floor))
            .enumerate()
            .fold((0.0, 0), |acc, (i, e)| if e > acc.0 { (e, i) } else { acc });
        assert!(
            worst <= 1e-4,
            "{what} {name}: error {worst:.2e} of S0 at {i} (gpu {}, cpu {}, S0 {})",
            g[i],
            c[i],
            s0[i]
        );
        e = e.max(worst);
    }
    e
}

fn assert_gradients_close(
    gpu: &(GBufferGrad, EnvGrad),
    cpu: &(GBufferGrad, EnvGrad),
    what: &str,
) -> f64 {
    let (g, c) = (&gpu.0, &cpu.0);
    let mut e = [
        assert_close(
            &flat(&g.normal),
            &flat(&c.normal),
            1e-3,
            1e-3,
            &format!("{what} dL/dnormal"),
        ),
        assert_close(
            &flat(&g.albedo),
            &flat(&c.albedo),
            1e-3,
            1e-3,
            &format!("{what} dL/dalbedo"),
        ),
        assert_close(
            &g.roughness,
            &c.roughness,
            1e-3,
            1e-3,
            &format!("{what} dL/droughness"),
        ),
        assert_close(&g.ior, &c.ior, 1e-3, 1e-3, &format!("{what} dL/dior")),
    ]
    .into_iter()
    .fold(0.0, f64::max);
    let (ge, ce) = (&gpu.1, &cpu.1);
    assert_eq!(ge.levels.len(), ce.levels.len());
    assert_eq!(ge.irradiance.len(), ce.irradiance.len());
    for (l, (g, c)) in ge.levels.iter().zip(&ce.levels).enumerate() {
        e = e.max(assert_close(
            g,
            c,
            1e-3,
            1e-3,
            &format!("{what} light level {l}"),
        ));
    }
    for (k, (g, c)) in ge.irradiance.iter().zip(&ce.irradiance).enumerate() {
        // With Fresnel-weighted irradiance a map whose IoR node no pixel is near gets nothing.
        if c.iter().any(|&v| v != 0.0) {
            e = e.max(assert_close(
                g,
                c,
                1e-3,
                1e-3,
                &format!("{what} irradiance map {k}"),
            ));
        }
    }
    e
}

/// Shades one random view with the gpu backend and the cpu code and compares everything.
fn check_view(gpu: &GpuBackend, camera: &Camera, env: &PreparedEnv, lut: &BrdfLut, seed: u64) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let pixels = camera.num_pixels();
    let inputs = Inputs::random(&mut rng, pixels);
    let (s0, s1, s2) = (
        random_rgb(&mut rng, pixels),
        random_rgb(&mut rng, pixels),
        random_rgb(&mut rng, pixels),
    );
    let upstream = StokesImageGrad {
        s0: &s0,
        s1: &s1,
        s2: &s2,
    };
    let buffers = inputs.buffers();
    let what = format!("seed {seed}, {:?}", gpu.atomics());
    let cpu_image = shading::shade_image(camera, &buffers, env, lut).unwrap();
    let gpu_image = gpu.shade(camera, &buffers, env, lut).unwrap();
    let forward = assert_images_close(&gpu_image, &cpu_image, &what);
    for (p, &on) in inputs.active.iter().enumerate() {
        if !on {
            assert_eq!(
                gpu_image.s0[p],
                DVec3::ZERO,
                "{what}: inactive pixel {p} shaded"
            );
        }
    }
    let cpu_grads = shading::shade_image_backward(camera, &buffers, env, lut, &upstream).unwrap();
    let gpu_grads = gpu
        .shade_backward(camera, &buffers, env, lut, &upstream)
        .unwrap();
    let backward = assert_gradients_close(&gpu_grads, &cpu_grads, &what);
    println!("{what}: worst relative error forward {forward:.2e}, backward {backward:.2e}");
}

#[test]
fn shading_matches_cpu_on_random_views() {
    let lut = BrdfLut::compute(24, 64);
    for force_compare_exchange in [false, true] {
        let Some(gpu) = gpu(GpuOptions {
            force_compare_exchange,
            ..GpuOptions::default()
        }) else {
            return;
        };
        if force_compare_exchange {
            assert_eq!(gpu.atomics(), AtomicsMode::CompareExchange);
        }
        for (seed, (fresnel, fine)) in [(false, false), (true, false), (false, true)]
            .into_iter()
            .enumerate()
        {
            let mut rng = ChaCha8Rng::seed_from_u64(seed as u64);
            let env = random_env(&mut rng, fresnel, fine);
            let camera = random_camera(&mut rng, 37, 29);
            check_view(&gpu, &camera, &env, &lut, 10 + seed as u64);
        }
    }
}

/// With the binding limit lowered below the image's Stokes buffer, the image is shaded in chunks
/// of pixels and still matches.
#[test]
fn large_images_are_shaded_in_chunks() {
    let lut = BrdfLut::compute(8, 32);
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let env = random_env(&mut rng, false, false);
    let camera = random_camera(&mut rng, 48, 40);
    let limit = 40_000;
    let light_values = env
        .levels
        .iter()
        .chain(&env.irradiance)
        .map(Vec::len)
        .sum::<usize>()
        + 2 * lut.a.len();
    assert!(light_values * 4 < limit, "the light must still fit");
    assert!(
        camera.num_pixels() * 15 * 4 > 2 * limit,
        "the image must need 3+ chunks"
    );
    let Some(gpu) = gpu(GpuOptions {
        max_binding_bytes: Some(limit as u64),
        ..GpuOptions::default()
    }) else {
        return;
    };
    check_view(&gpu, &camera, &env, &lut, 99);
}

/// A light that only delegates to a global environment but does not say it is one.
struct Local<'a>(&'a PreparedEnv);

impl LightProbe for Local<'_> {
    fn irradiance(&self, position: DVec3, normal: DVec3, ior: f64) -> DVec3 {
        self.0.irradiance(normal, ior) * (1.0 + position.x)
    }
    fn irradiance_backward(
        &self,
        position: DVec3,
        normal: DVec3,
        ior: f64,
        grad_out: DVec3,
        grad: &mut EnvGrad,
    ) -> (DVec3, f64) {
        let scaled = grad_out * (1.0 + position.x);
        self.0.irradiance_backward(normal, ior, scaled, grad)
    }
    fn specular(&self, _position: DVec3, dir: DVec3, roughness: f64) -> DVec3 {
        self.0.specular(dir, roughness)
    }
    fn specular_backward(
        &self,
        _position: DVec3,
        dir: DVec3,
        roughness: f64,
        grad_out: DVec3,
        grad: &mut EnvGrad,
    ) -> (DVec3, f64) {
        self.0.specular_backward(dir, roughness, grad_out, grad)
    }
    fn zero_grad(&self) -> EnvGrad {
        self.0.zero_grad()
    }
}

/// A light of a kind the kernels do not know is shaded by the cpu code: bit for bit its result.
#[test]
fn position_dependent_lights_use_the_cpu_code() {
    let Some(gpu) = gpu(GpuOptions::default()) else {
        return;
    };
    let lut = BrdfLut::compute(8, 32);
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let env = random_env(&mut rng, false, false);
    let camera = random_camera(&mut rng, 9, 7);
    let inputs = Inputs::random(&mut rng, camera.num_pixels());
    let position: Vec<DVec3> = (0..camera.num_pixels())
        .map(|p| DVec3::new(p as f64 * 0.01, 0.0, 0.0))
        .collect();
    let buffers = ShadingBuffers {
        position: Some(&position),
        ..inputs.buffers()
    };
    let light = Local(&env);
    let cpu = shading::shade_image(&camera, &buffers, &light, &lut).unwrap();
    let on_gpu_backend = gpu.shade(&camera, &buffers, &light, &lut).unwrap();
    assert_eq!(on_gpu_backend, cpu);
}

/// Per pixel, the largest error of `gpu` against `cpu` over the images of [`assert_images_close`]
/// (S0, diffuse, specular relative with a floor of 1% of each image's scale; S1, S2 relative to
/// the pixel's S0).
fn pixel_image_errors(gpu: &StokesImage, cpu: &StokesImage) -> Vec<f64> {
    let scale = |v: &[DVec3]| v.iter().fold(0.0f64, |m, x| m.max(x.abs().max_element()));
    let s0_floor = 1e-3 * scale(&cpu.s0);
    (0..cpu.s0.len())
        .map(|p| {
            let rel = |g: &[DVec3], c: &[DVec3], floor: f64| {
                ((g[p] - c[p]).abs() / (c[p].abs() + DVec3::splat(floor))).max_element()
            };
            let s0 = cpu.s0[p].abs() + DVec3::splat(s0_floor);
            [
                rel(&gpu.s0, &cpu.s0, 1e-2 * scale(&cpu.s0)),
                rel(&gpu.diffuse, &cpu.diffuse, 1e-2 * scale(&cpu.diffuse)),
                rel(&gpu.specular, &cpu.specular, 1e-2 * scale(&cpu.specular)),
                ((gpu.s1[p] - cpu.s1[p]).abs() / s0).max_element(),
                ((gpu.s2[p] - cpu.s2[p]).abs() / s0).max_element(),
            ]
            .into_iter()
            .fold(0.0, f64::max)
        })
        .collect()
}

/// Per pixel, the largest relative error of the input gradients (floor: a thousandth of each
/// buffer's scale).
fn pixel_gradient_errors(gpu: &GBufferGrad, cpu: &GBufferGrad) -> Vec<f64> {
    let vec_scale = |v: &[DVec3]| v.iter().fold(0.0f64, |m, x| m.max(x.abs().max_element()));
    let scale = |v: &[f64]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let (sn, sa) = (1e-3 * vec_scale(&cpu.normal), 1e-3 * vec_scale(&cpu.albedo));
    let (sr, si) = (1e-3 * scale(&cpu.roughness), 1e-3 * scale(&cpu.ior));
    (0..cpu.normal.len())
        .map(|p| {
            let v = |g: DVec3, c: DVec3, f: f64| {
                ((g - c).abs() / (c.abs() + DVec3::splat(f))).max_element()
            };
            let s = |g: f64, c: f64, f: f64| (g - c).abs() / (c.abs() + f);
            v(gpu.normal[p], cpu.normal[p], sn)
                .max(v(gpu.albedo[p], cpu.albedo[p], sa))
                .max(s(gpu.roughness[p], cpu.roughness[p], sr))
                .max(s(gpu.ior[p], cpu.ior[p], si))
        })
        .collect()
}

/// ‖a − b‖ / ‖b‖ over every texel of two light gradients.
fn relative_l2(a: &EnvGrad, b: &EnvGrad) -> f64 {
    let pairs = a
        .levels
        .iter()
        .chain(&a.irradiance)
        .flatten()
        .zip(b.levels.iter().chain(&b.irradiance).flatten());
    let (diff, norm) = pairs.fold((0.0, 0.0), |(d, n), (x, y)| {
        (d + (x - y).powi(2), n + y * y)
    });
    (diff / norm).sqrt()
}

/// GridMap over two spheres, seen so that part of sphere A's mirror rays hit sphere B, with the
/// box's anchors and, on smaller spheres, the whole lattice's 64: the device's occlusion test,
/// anchor weights and blended probe lookups against the f64 code. A mirror ray that grazes a
/// triangle edge may be decided differently in f32, so up to 1% of the pixels may differ; every
/// other pixel agrees to the tolerances of the global light, and the light's gradient (escaping
/// rays only) to 1% in norm.
#[test]
fn gridmap_shading_matches_cpu() {
    use phygap::core::gridmap::{AnchorPlacement, GridMap};
    use phygap::core::mesh::bvh::Bvh;
    use phygap::pipeline::reconstruction::prefilter_plan;
    let Some(gpu) = gpu(GpuOptions::default()) else {
        return;
    };
    let lut = BrdfLut::compute(16, 64);
    // The unit spheres with the box's 56 anchors; the small ones with the lattice's 64.
    let scenes = [
        (
            phygap::testing::two_spheres(),
            AnchorPlacement::Box,
            1.5,
            2.0,
        ),
        (
            phygap::testing::spheres_with_a_gap(),
            AnchorPlacement::Lattice,
            1.1,
            1.6,
        ),
    ];
    // The last with two roughness levels per size (three 8² levels in a row).
    for (seed, fresnel, scene, levels_per_size) in
        [(21u64, false, 0, 1), (22, true, 0, 1), (23, true, 1, 2)]
    {
        let ((mesh, surfels), placement, centre_x, distance) = &scenes[scene];
        let (placement, centre_x, distance) = (*placement, *centre_x, *distance);
        let bvh = Bvh::build(mesh);
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let cube = random_cube(&mut rng, 16);
        let env =
            PreparedEnv::new(&cube, prefilter_plan(16, fresnel, levels_per_size).unwrap()).unwrap();
        let grid = GridMap::build(mesh, surfels, &cube, env, placement).unwrap();
        assert_eq!(
            grid.anchors().len(),
            if placement == AnchorPlacement::Box {
                56
            } else {
                64
            }
        );
        let camera = Camera::look_at(
            48,
            40,
            0.9,
            DVec3::new(centre_x, -distance, 0.2),
            DVec3::new(centre_x, 0.0, 0.0),
            DVec3::Z,
        );
        let pixels = camera.num_pixels();
        let mut inputs = Inputs::random(&mut rng, pixels);
        let mut position = vec![DVec3::ZERO; pixels];
        let (mut occluded, mut escaping) = (0, 0);
        for (p, x) in position.iter_mut().enumerate() {
            let (i, j) = ((p % 48) as u32, (p / 48) as u32);
            let dir = camera.pixel_dir(i, j);
            match bvh.intersect(camera.origin(), dir, f64::INFINITY) {
                Some(hit) => {
                    *x = hit.position;
                    let jitter = 0.2 * (inputs.normal[p] / 2.0);
                    inputs.normal[p] = hit.normal + jitter;
                    inputs.roughness[p] = rng.random_range(0.05..0.95);
                    inputs.active[p] = true;
                    let n = inputs.normal[p].normalize();
                    let v = -dir;
                    let mirror = 2.0 * n.dot(v) * n - v;
                    if grid.occluded(hit.position, mirror) {
                        occluded += 1;
                    } else {
                        escaping += 1;
                    }
                }
                None => inputs.active[p] = false,
            }
        }
        let active = occluded + escaping;
        assert!(
            occluded * 20 > active && escaping * 20 > active,
            "the view must test both paths: {occluded} occluded, {escaping} escaping"
        );
        let buffers = ShadingBuffers {
            position: Some(&position),
            ..inputs.buffers()
        };
        let cpu_image = shading::shade_image(&camera, &buffers, &grid, &lut).unwrap();
        let gpu_image = gpu.shade(&camera, &buffers, &grid, &lut).unwrap();
        let (s0, s1, s2) = (
            random_rgb(&mut rng, pixels),
            random_rgb(&mut rng, pixels),
            random_rgb(&mut rng, pixels),
        );
        let upstream = StokesImageGrad {
            s0: &s0,
            s1: &s1,
            s2: &s2,
        };
        let cpu_grads =
            shading::shade_image_backward(&camera, &buffers, &grid, &lut, &upstream).unwrap();
        let gpu_grads = gpu
            .shade_backward(&camera, &buffers, &grid, &lut, &upstream)
            .unwrap();
        let forward = pixel_image_errors(&gpu_image, &cpu_image);
        let backward = pixel_gradient_errors(&gpu_grads.0, &cpu_grads.0);
        let differing: Vec<usize> = (0..pixels)
            .filter(|&p| forward[p] > 1e-4 || backward[p] > 1e-3)
            .collect();
        let light = relative_l2(&gpu_grads.1, &cpu_grads.1);
        println!(
            "seed {seed}, {placement:?}: {occluded} occluded, {escaping} escaping, \
             {} pixels differ {:?}, light gradient {light:.2e}",
            differing.len(),
            &differing[..differing.len().min(8)]
        );
        assert!(
            differing.len() * 100 <= active,
            "{} of {active} pixels differ",
            differing.len()
        );
        assert!(
            light < 1e-2,
            "light gradient differs by {light:.2e} in norm"
        );
    }
}
