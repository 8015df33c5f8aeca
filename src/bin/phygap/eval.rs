//! `phygap eval MODEL CAPTURE [--json] [--relight-envmap FILE] [--gt-mesh FILE] [--resolution
//! working|full]`: metrics of a trained model on the capture's test views (at the resolution it
//! was trained at, or the capture's own); with a relighting map, the relit S0 against the
//! views' `relight_s0` ground truth; with a ground-truth mesh, the Chamfer-L1 of the model's mesh.
//! Both are taken from the capture folder (`scene.json`'s relighting map, `mesh.ply`) unless given.

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;

use phygap::core::resolution::Resolution;
use phygap::io::capture;
use phygap::io::model::Model;
use phygap::pipeline::evaluate::EvalReport;
use phygap::pipeline::scorecard::{self, GroundTruth};

#[derive(Args, Debug)]
pub struct EvalArgs {
    /// Model folder written by `phygap train`.
    pub model: PathBuf,
    /// The capture (its test split is used).
    pub capture: PathBuf,
    /// Print only the JSON object.
    #[arg(long)]
    pub json: bool,
    /// Lat-long map (.exr/.hdr) the capture's `relight_s0` ground truth is lit by: adds
    /// `relight_psnr` and `relight_ssim` (default: the map the capture's `scene.json` names for
    /// relighting, where it has one).
    #[arg(long)]
    pub relight_envmap: Option<PathBuf>,
    /// Ground-truth mesh (PLY): adds `chamfer` (the model's mesh at the default resolution;
    /// default: the capture's `mesh.ply`, where it has one).
    #[arg(long)]
    pub gt_mesh: Option<PathBuf>,
    #[arg(long, help = crate::GRIDMAP_OVERRIDE_HELP)]
    pub gridmap: Option<crate::Switch>,
    /// Evaluate at the resolution the model was trained at (`working`: the capture's views
    /// shrunk as they were for training, or, for views of another size such as a raw capture's
    /// full-Stokes reference, to the working size's longest side) or at the capture's own
    /// (`full`).
    #[arg(long, value_enum, default_value = "working")]
    pub resolution: EvalResolution,
}

/// The resolution `phygap eval` renders and compares at.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum EvalResolution {
    Working,
    Full,
}

pub fn run(args: &EvalArgs) -> Result<()> {
    let mut model = Model::load(&args.model)?;
    let resolution = match args.resolution {
        EvalResolution::Working => crate::working_resolution(&model, &args.capture)?,
        EvalResolution::Full => Resolution::Full,
    };
    let options = capture::LoadOptions {
        resolution,
        ..capture::LoadOptions::default()
    };
    let capture = capture::load_with(&args.capture, &options)?;
    crate::override_gridmap(&mut model, args.gridmap);
    let truth = GroundTruth::discover_or(
        &args.capture,
        args.relight_envmap.clone(),
        args.gt_mesh.clone(),
    );
    let report = scorecard::score(&model, &capture, &truth)?;
    if !args.json {
        print_table(&report);
    }
    println!("{}", serde_json::to_string_pretty(&report)?);
    Ok(())
}

/// The report as aligned lines for a person (the JSON follows it).
pub fn print_table(report: &EvalReport) {
    let fmt = |v: Option<f64>| v.map_or("n/a".to_owned(), |v| format!("{v:.4}"));
    println!("test views      {}", report.test_views);
    println!("S0 PSNR (dB)    {}", fmt(report.psnr));
    println!("S0 SSIM         {}", fmt(report.ssim));
    println!("normal MAE (°)  {}", fmt(report.normal_mae_deg));
    println!("AoLP MAE (°)    {}", fmt(report.aolp_mae_deg));
    println!("DoLP MAE        {}", fmt(report.dolp_mae));
    println!("albedo MAE      {}", fmt(report.albedo_mae));
    println!("roughness MAE   {}", fmt(report.roughness_mae));
    println!("IoR MAE         {}", fmt(report.ior_mae));
    println!("relit PSNR (dB) {}", fmt(report.relight_psnr));
    println!("relit SSIM      {}", fmt(report.relight_ssim));
    println!("Chamfer-L1      {}", fmt(report.chamfer));
    println!("pose error (°)  {}", fmt(report.pose_error_deg));
    println!("pose error (r)  {}", fmt(report.pose_error_radius));
    println!("pose error (px) {}", fmt(report.pose_error_px));
    println!("surfels         {}", report.num_surfels);
}
