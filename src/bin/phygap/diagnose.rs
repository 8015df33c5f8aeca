//! `phygap diagnose MODEL CAPTURE [--json]`: the loss budget of a trained model — its test
//! views rendered with each learned component (geometry, albedo, roughness, IoR, light) in turn
//! replaced by the capture's ground truth, the S0 and relit PSNR of each, and the distribution of
//! its normals' errors (mean, median, 90th and 99th percentiles, by distance to the silhouette).
//! The lighting and relighting maps come from the capture's `scene.json`. `--images DIR`
//! also writes each test view's normal error as an image (false colour PNG, degrees in EXR).
//! The views are compared at the size the model was trained at (a capture of another size, such
//! as a raw capture's full-Stokes reference, shrunk to it).

use std::path::PathBuf;

use anyhow::{Context, Result};
use clap::Args;

use phygap::formats::image_io::{write_exr, write_png};
use phygap::io::capture::{self, LoadOptions};
use phygap::io::model::Model;
use phygap::pipeline::diagnose::{diagnose, DiagnoseTruth, Diagnosis, DEPTH_JUMP, FAR_OFFSET};
use phygap::pipeline::reconstruction::Reconstruction;

#[derive(Args, Debug)]
pub struct DiagnoseArgs {
    /// Model folder written by `phygap train`.
    pub model: PathBuf,
    /// The capture it was trained on, with ground-truth G-buffers (normal, depth, albedo,
    /// roughness, ior) on its test views.
    pub capture: PathBuf,
    /// Print only the JSON object.
    #[arg(long)]
    pub json: bool,
    /// Also write each test view's normal error to this folder: `normal_error_NNN.png` (false
    /// colour: dark blue 0°, blue 5°, green 15°, yellow 30°, red from 45°; black off the object)
    /// and `normal_error_NNN.exr` (degrees; NaN off the object), NNN the view's frame index.
    #[arg(long, value_name = "DIR")]
    pub images: Option<PathBuf>,
}

pub fn run(args: &DiagnoseArgs) -> Result<()> {
    let model = Model::load(&args.model)?;
    let options = LoadOptions {
        resolution: crate::working_resolution(&model, &args.capture)?,
        ..LoadOptions::default()
    };
    let capture = capture::load_with(&args.capture, &options)?;
    let truth = DiagnoseTruth::discover(&capture.root);
    let reconstruction = Reconstruction::new(model)?;
    let report = diagnose(&reconstruction, &capture, &truth)?;
    if !args.json {
        print!("{}", describe(&report));
    }
    if let Some(dir) = &args.images {
        std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
        for map in &report.normal_error_maps {
            let stem = dir.join(format!("normal_error_{:03}", map.frame_index));
            write_png(&stem.with_extension("png"), &map.colored(), false)?;
            write_exr(&stem.with_extension("exr"), &map.degrees)?;
            if !args.json {
                println!("{}: {}.png, .exr", map.view, stem.display());
            }
        }
    }
    println!("{}", serde_json::to_string_pretty(&report)?);
    Ok(())
}

/// The budget as a table for people: each variant's PSNR and what the replacement gains.
fn describe(report: &Diagnosis) -> String {
    let learned = report.variants.first();
    let gain = |value: f64, base: Option<f64>| match base {
        Some(base) => format!("{:+.2}", value - base),
        None => "–".to_owned(),
    };
    // The first column as wide as its longest name ("materials+light").
    let width = report
        .variants
        .iter()
        .map(|v| v.name.chars().count())
        .chain(["replaced".len()])
        .max()
        .unwrap_or(0);
    let mut text = format!(
        "loss budget over {} test views (S0 PSNR dB; relit PSNR dB; the gain of each ground truth)\n\
         {:<width$} {:>8} {:>8} {:>8} {:>8}\n",
        report.test_views, "replaced", "S0", "gain", "relit", "gain"
    );
    for v in &report.variants {
        let relit = v.relit_psnr.map_or("–".to_owned(), |r| format!("{r:.2}"));
        let relit_gain = match (v.relit_psnr, learned.and_then(|l| l.relit_psnr)) {
            (Some(r), Some(base)) => format!("{:+.2}", r - base),
            _ => "–".to_owned(),
        };
        text.push_str(&format!(
            "{:<width$} {:>8.2} {:>8} {:>8} {:>8}\n",
            v.name,
            v.s0_psnr,
            gain(v.s0_psnr, learned.map(|l| l.s0_psnr)),
            relit,
            relit_gain
        ));
    }
    let n = &report.normals;
    text.push_str(&format!(
        "normals over {} pixels: MAE {:.2}°, median {:.2}°, p90 {:.2}°, p99 {:.2}°, cosine distance {:.4}\n",
        n.pixels, n.mae_degrees, n.median_degrees, n.p90_degrees, n.p99_degrees, n.cosine_distance
    ));
    for band in &n.by_silhouette_distance {
        text.push_str(&format!(
            "  {:>4.1}–{:<4} px from the silhouette: {:>7} pixels, MAE {:.2}°\n",
            band.from,
            if band.to.is_finite() {
                format!("{:.1}", band.to)
            } else {
                "∞".to_owned()
            },
            band.pixels,
            band.mae_degrees
        ));
    }
    let c = &n.contours;
    text.push_str(&format!(
        "  within 1 px of a contour (the silhouette or a jump of the true depth by more than {:.0}%): \
         {:.1}% of the pixels, {:.1}% of the cosine distance; the others' cosine distance {:.4}\n",
        100.0 * DEPTH_JUMP,
        100.0 * c.pixel_share,
        100.0 * c.cosine_distance_share,
        c.cosine_distance_elsewhere
    ));
    let d = &report.depths;
    let percent = |share: f64| 100.0 * share;
    let far = FAR_OFFSET;
    text.push_str(&format!(
        "depths over {} pixels (object radii): median offset {:+.4}, median |offset| {:.4}; \
         {:.2}% more than {far} behind the surface (normal MAE there {:.1}°), {:.2}% more than {far} in front\n",
        d.pixels,
        d.median_offset,
        d.median_abs_offset,
        percent(d.far_behind_share),
        d.far_behind_normal_mae_degrees,
        percent(d.far_in_front_share)
    ));
    text
}
