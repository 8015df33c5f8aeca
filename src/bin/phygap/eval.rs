//! `phygap eval MODEL CAPTURE [--json]`: metrics of a trained model on the capture's test views.

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;

use phygap::capture;
use phygap::model::Model;
use phygap::reconstruction::Reconstruction;

#[derive(Args, Debug)]
pub struct EvalArgs {
    /// Model folder written by `phygap train`.
    pub model: PathBuf,
    /// The capture (its test split is used).
    pub capture: PathBuf,
    /// Print only the JSON object.
    #[arg(long)]
    pub json: bool,
}

pub fn run(args: &EvalArgs) -> Result<()> {
    let capture = capture::load(&args.capture)?;
    let reconstruction = Reconstruction::new(Model::load(&args.model)?)?;
    let mut report = reconstruction.evaluate(&capture)?;
    report.train_seconds = Some(reconstruction.model.info.train_seconds);
    let json = serde_json::to_string_pretty(&report)?;
    if args.json {
        println!("{json}");
    } else {
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
        println!("surfels         {}", report.num_surfels);
        println!("{json}");
    }
    Ok(())
}
