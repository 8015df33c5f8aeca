//! `phygap check-shading CAPTURE --envmap FILE [--view N] [--json]`: feed a test view's ground-truth
//! normals, albedo, roughness and IoR with the ground-truth environment straight into PolarDR (no
//! rasterizer) and compare with the captured Stokes images: the model's measured ceiling.

use std::path::{Path, PathBuf};

use anyhow::{anyhow, Context, Result};
use clap::Args;

use phygap::core::brdf_lut::BrdfLut;
use phygap::core::envmap::{CubeMap, PreparedEnv, WorldUp};
use phygap::core::shading::check::{physics_check, GroundTruthView};
use phygap::formats::image_io::{read_image, Image};
use phygap::io::capture::{self, Measurement};
use phygap::pipeline::reconstruction::prefilter_plan;

#[derive(Args, Debug)]
pub struct CheckShadingArgs {
    /// Capture with ground-truth buffers (normal_path, albedo_path, roughness_path, ior_path).
    pub capture: PathBuf,
    /// The ground-truth lat-long environment map of the capture (named in its scene.json).
    #[arg(long)]
    pub envmap: PathBuf,
    /// Index among the capture's test views.
    #[arg(long, default_value_t = 0)]
    pub view: usize,
    /// Cube-map face size of the environment.
    #[arg(long, default_value_t = 64)]
    pub envmap_resolution: usize,
    /// Weight the irradiance by the Fresnel transmission of the incoming light.
    #[arg(long)]
    pub fresnel_irradiance: bool,
    /// Roughness levels per resolution of the specular mip chain (1: METHOD.md's chain).
    #[arg(long, default_value_t = 1)]
    pub mip_levels_per_size: usize,
    /// Print the figures as JSON.
    #[arg(long)]
    pub json: bool,
}

fn ground_truth(path: Option<&PathBuf>, what: &str) -> Result<Image> {
    let path = path.ok_or_else(|| anyhow!("the view has no `{what}_path` ground truth"))?;
    Ok(read_image(path)?.0)
}

pub fn run(args: &CheckShadingArgs) -> Result<()> {
    let capture = capture::load(&args.capture)?;
    let tests: Vec<_> = capture.test_views().collect();
    let view = tests.get(args.view).ok_or_else(|| {
        anyhow!(
            "--view {}: the capture has {} test views",
            args.view,
            tests.len()
        )
    })?;
    let gt = &view.ground_truth;
    let normal = ground_truth(gt.normal.as_ref(), "normal")?.to_rgb();
    let albedo = ground_truth(gt.albedo.as_ref(), "albedo")?.to_rgb();
    let alpha_ggx = ground_truth(gt.roughness.as_ref(), "roughness")?.channel(0);
    let ior = ground_truth(gt.ior.as_ref(), "ior")?.channel(0);
    let (s0, s1, s2) = match &view.measurement {
        Measurement::Stokes { s0, s1, s2 } => (s0.clone(), s1.clone(), s2.clone()),
        _ => (
            ground_truth(gt.s0.as_ref(), "s0")?,
            ground_truth(gt.s1.as_ref(), "s1")?,
            ground_truth(gt.s2.as_ref(), "s2")?,
        ),
    };
    let mask: Vec<bool> = view.mask.data.iter().map(|&m| m > 0.5).collect();
    let up = WorldUp::from_vector(capture.world_up.to_array())?;
    let env = load_env(
        &args.envmap,
        up,
        args.envmap_resolution,
        args.fresnel_irradiance,
        args.mip_levels_per_size,
    )?;
    let check = physics_check(
        &GroundTruthView {
            camera: &view.camera,
            normal: &normal,
            albedo: &albedo,
            alpha_ggx: &alpha_ggx,
            ior: &ior,
            mask: &mask,
            s0: &s0,
            s1: &s1,
            s2: &s2,
        },
        &env,
        BrdfLut::shared(),
    )?;
    if args.json {
        println!("{}", serde_json::to_string_pretty(&check)?);
    } else {
        println!(
            "view            {} ({} pixels in the mask)",
            view.name, check.pixels
        );
        println!(
            "S0 PSNR         {:.2} dB (peak 1), {:.2} dB (peak = GT max)",
            check.s0_psnr, check.s0_psnr_peak_max
        );
        println!("S0 bias         {:+.1}%", 100.0 * check.s0_bias);
        println!("S1 rel. L1      {:.3}", check.s1_rel_l1);
        println!("S2 rel. L1      {:.3}", check.s2_rel_l1);
        println!(
            "AoLP within 10° {:.3} (pixels with GT DoLP > 0.05)",
            check.aolp_agreement
        );
        println!("DoLP MAE        {:.4}", check.dolp_mae);
        println!(
            "best fit        {:.3} × specular + {:.3} × diffuse (least squares over S0, S1, S2)",
            check.part_scales.specular, check.part_scales.diffuse
        );
    }
    Ok(())
}

fn load_env(
    path: &Path,
    up: WorldUp,
    size: usize,
    fresnel: bool,
    levels_per_size: usize,
) -> Result<PreparedEnv> {
    let cube = CubeMap::load_latlong(path, up, size)
        .with_context(|| format!("environment map {}", path.display()))?;
    Ok(PreparedEnv::new(
        &cube,
        prefilter_plan(size, fresnel, levels_per_size)?,
    )?)
}
