//! The shading model against the Mitsuba ground truth of the shared captures: GT normals,
//! materials and environment fed straight into PolarDR (METHOD.md §4 "measured ceiling"), and the
//! proof that the Stokes sign conventions are the ones the data pins down.

use std::path::Path;

use glam::DMat4;
use phygap::core::brdf_lut::BrdfLut;
use phygap::core::camera::{Camera, CameraConvention, Intrinsics};
use phygap::core::envmap::{CubeMap, MipChainSpec, PrefilterPlan, PreparedEnv, WorldUp};
use phygap::core::shading::{physics_check, GroundTruthView, ShadingCheck};
use phygap::formats::image_io::{read_image, Image};
use phygap::testing::shared_data_dir;

/// One test view read minimally from `transforms_test.json` (the capture loader lives elsewhere).
struct View {
    camera: Camera,
    normal: Image,
    albedo: Image,
    roughness: Image,
    ior: Image,
    mask: Vec<bool>,
    s0: Image,
    s1: Image,
    s2: Image,
}

fn load_view(scene: &Path, index: usize) -> View {
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(scene.join("transforms_test.json")).unwrap())
            .unwrap();
    let frame = &json["frames"][index];
    let num = |v: &serde_json::Value| v.as_f64().unwrap();
    let rows: Vec<Vec<f64>> = serde_json::from_value(frame["transform_matrix"].clone()).unwrap();
    // Row-major nested lists → column-major DMat4.
    let c2w = DMat4::from_cols_array_2d(&std::array::from_fn(|c| {
        std::array::from_fn(|r| rows[r][c])
    }));
    let intrinsics = Intrinsics {
        width: num(&json["w"]) as u32,
        height: num(&json["h"]) as u32,
        fx: num(&json["fl_x"]),
        fy: num(&json["fl_y"]),
        cx: num(&json["cx"]),
        cy: num(&json["cy"]),
    };
    let image = |key: &str| {
        read_image(&scene.join(frame[key].as_str().unwrap()))
            .unwrap()
            .0
    };
    let mask = image("mask_path");
    View {
        camera: Camera::new(intrinsics, c2w, CameraConvention::OpenGL),
        normal: image("normal_path"),
        albedo: image("albedo_path"),
        roughness: image("roughness_path"),
        ior: image("ior_path"),
        mask: (0..mask.num_pixels())
            .map(|p| mask.data[p * mask.channels] > 0.5)
            .collect(),
        s0: image("s0_path"),
        s1: image("s1_path"),
        s2: image("s2_path"),
    }
}

fn check(view: &View, env: &PreparedEnv, s1: &Image, s2: &Image) -> ShadingCheck {
    physics_check(
        &GroundTruthView {
            camera: &view.camera,
            normal: &view.normal,
            albedo: &view.albedo,
            alpha_ggx: &view.roughness,
            ior: &view.ior,
            mask: &view.mask,
            s0: &view.s0,
            s1,
            s2,
        },
        env,
        BrdfLut::shared(),
    )
    .unwrap()
}

fn prepared(scene: &Path, env_name: &str, spec: MipChainSpec) -> PreparedEnv {
    let cube = CubeMap::load_latlong(
        &scene.join("env").join(env_name),
        WorldUp::Z,
        spec.base_size,
    )
    .unwrap();
    PreparedEnv::new(&cube, PrefilterPlan::new(spec).unwrap()).unwrap()
}

fn negated(img: &Image) -> Image {
    Image {
        data: img.data.iter().map(|v| -v).collect(),
        ..img.clone()
    }
}

fn report(name: &str, index: usize, c: &ShadingCheck) {
    println!(
        "{name} view {index}: {} px, S0 PSNR {:.2} dB (peak = GT max: {:.2} dB, bias {:+.1}%), S1 rel L1 {:.3}, S2 rel L1 {:.3}, AoLP within 10° {:.3}, DoLP MAE {:.4}",
        c.pixels,
        c.s0_psnr,
        c.s0_psnr_peak_max,
        100.0 * c.s0_bias,
        c.s1_rel_l1,
        c.s2_rel_l1,
        c.aolp_agreement,
        c.dolp_mae
    );
}

#[test]
fn sphere_polarization_agrees_with_mitsuba_and_wrong_signs_do_not() {
    let Some(root) = shared_data_dir() else {
        return;
    };
    let scene = root.join("sphere");
    let env = prepared(&scene, "sky.exr", MipChainSpec::default());
    // Two roughness levels per resolution resolve the sun highlight (see the S0 note below).
    let fine = prepared(
        &scene,
        "sky.exr",
        MipChainSpec {
            levels_per_size: 2,
            ..MipChainSpec::default()
        },
    );
    for index in 0..3 {
        let view = load_view(&scene, index);
        let c = check(&view, &env, &view.s1, &view.s2);
        report("sphere", index, &c);
        let f = check(&view, &fine, &view.s1, &view.s2);
        report("sphere (levels_per_size 2)", index, &f);
        // At grazing reflection of the sun (view 1) the split-sum's N = V = R lobe is half as bright
        // as the true stretched lobe; PSNR with the peak at the GT maximum stays high.
        assert!(f.s0_psnr_peak_max > 32.0, "S0 PSNR {}", f.s0_psnr_peak_max);
        assert!(c.pixels > 10_000);
        assert!(
            c.aolp_agreement > 0.9,
            "AoLP agreement {}",
            c.aolp_agreement
        );
        // The default D = 64 chain blends its r = 0.08 and r = 0.5 levels for the sphere's
        // r = 0.28, which over-brightens the sun highlight several-fold (≈ 1% of the pixels carry
        // most of the S0 error, so no PSNR floor here); the body of the sphere matches within
        // METHOD.md's +6% diffuse bias.
        assert!(c.s0_bias.abs() < 0.12, "S0 bias {}", c.s0_bias);
        assert!(
            f.s1_rel_l1 < 0.6 && f.s2_rel_l1 < 0.6,
            "S1/S2 {} {}",
            f.s1_rel_l1,
            f.s2_rel_l1
        );
        assert!(c.dolp_mae < 0.03, "DoLP MAE {}", c.dolp_mae);
        // Mirrored angle convention (S2 sign flipped): the agreement collapses.
        let flipped = check(&view, &env, &view.s1, &negated(&view.s2));
        println!(
            "  S2 sign flipped: AoLP agreement {:.3}",
            flipped.aolp_agreement
        );
        assert!(flipped.aolp_agreement < 0.3);
        // Stokes frame turned by 90° (S1, S2 → −S1, −S2): AoLP off by 90° everywhere.
        let turned = check(&view, &env, &negated(&view.s1), &negated(&view.s2));
        println!(
            "  frame turned 90°: AoLP agreement {:.3}",
            turned.aolp_agreement
        );
        assert!(turned.aolp_agreement < 0.1);
    }
}

#[test]
fn knot_figures_are_within_the_known_ceiling() {
    let Some(root) = shared_data_dir() else {
        return;
    };
    let scene = root.join("knot");
    let env = prepared(&scene, "indoor.exr", MipChainSpec::default());
    for index in 0..3 {
        let view = load_view(&scene, index);
        let c = check(&view, &env, &view.s1, &view.s2);
        report("knot", index, &c);
        // Without visibility the knot cannot do better than METHOD.md's ceiling (~0.69), but its
        // signs must still beat chance (0.11 for a 20° window) by far.
        assert!(
            c.aolp_agreement > 0.4,
            "AoLP agreement {}",
            c.aolp_agreement
        );
        assert!(c.s0_psnr > 13.0, "S0 PSNR {}", c.s0_psnr);
        // No Fresnel-weighted irradiance and no inter-reflection: too bright, as METHOD.md's +23%.
        assert!(
            c.s0_bias > 0.05 && c.s0_bias < 0.35,
            "S0 bias {}",
            c.s0_bias
        );
    }
}

/// Figures for other chain resolutions and for Fresnel-weighted irradiance (slow; run with
/// `cargo test --release --test physics_check -- --ignored --nocapture`).
#[test]
#[ignore]
fn figures_for_other_chains() {
    let Some(root) = shared_data_dir() else {
        return;
    };
    for (scene, env_name) in [("sphere", "sky.exr"), ("knot", "indoor.exr")] {
        let scene_dir = root.join(scene);
        for (base, per_size, fresnel) in [
            (64, 1, false),
            (64, 1, true),
            (64, 2, false),
            (64, 3, false),
            (64, 3, true),
            (128, 1, false),
            (128, 2, false),
        ] {
            let spec = MipChainSpec {
                base_size: base,
                levels_per_size: per_size,
                fresnel_irradiance: fresnel,
                ..MipChainSpec::default()
            };
            let start = std::time::Instant::now();
            let env = prepared(&scene_dir, env_name, spec);
            let build = start.elapsed().as_secs_f64();
            let checks: Vec<ShadingCheck> = (0..3)
                .map(|i| {
                    let v = load_view(&scene_dir, i);
                    check(&v, &env, &v.s1, &v.s2)
                })
                .collect();
            let mean = |f: fn(&ShadingCheck) -> f64| checks.iter().map(f).sum::<f64>() / 3.0;
            println!(
                "{scene} D={base} levels_per_size={per_size} fresnel_irradiance={fresnel} (import+plan+prefilter {build:.2} s): S0 PSNR {:.2} dB (peak = GT max {:.2} dB), bias {:+.1}%, S1 {:.3}, S2 {:.3}, AoLP {:.3}, DoLP MAE {:.4}",
                mean(|c| c.s0_psnr),
                mean(|c| c.s0_psnr_peak_max),
                100.0 * mean(|c| c.s0_bias),
                mean(|c| c.s1_rel_l1),
                mean(|c| c.s2_rel_l1),
                mean(|c| c.aolp_agreement),
                mean(|c| c.dolp_mae),
            );
        }
    }
}
