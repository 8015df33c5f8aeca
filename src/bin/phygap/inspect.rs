//! `phygap inspect CAPTURE [--json]`: load and validate a capture, then print what it holds:
//! views, kinds, size, bounds, DoLP statistics, raw-frame and COLMAP details, the conventions
//! found from the data (Stokes angle direction, colour space of 8/16-bit polarizer images) with
//! their evidence, warnings.

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;

use phygap::core::background::{DARK_BACKGROUND_LEVEL, DARK_RIM_PX};
use phygap::core::resolution::Resolution;
use phygap::io::capture::conventions::{self, ConventionsReport};
use phygap::io::capture::{self, CaptureSummary};

/// Arguments of `phygap inspect`.
#[derive(Args, Debug)]
pub struct InspectArgs {
    /// Capture folder (with transforms.json or a COLMAP model) or a transforms JSON file.
    pub capture: PathBuf,
    /// Print the summary as JSON (with per-view DoLP statistics under `frames`).
    #[arg(long)]
    pub json: bool,
}

/// Loads the capture and prints its summary. A broken capture prints one error line (every problem
/// found, separated by `;`) on stderr and exits with status 1.
pub fn run(args: &InspectArgs) -> Result<()> {
    let capture = capture::load(&args.capture)?;
    let summary = capture.summary();
    let report = conventions::check_capture(&args.capture, &capture);
    if args.json {
        let mut value = serde_json::to_value(&summary)?;
        value["conventions"] = serde_json::to_value(&report)?;
        println!("{}", serde_json::to_string_pretty(&value)?);
    } else {
        print!("{}", describe(&capture.root, &summary));
        print!("{}", describe_conventions(&report));
    }
    Ok(())
}

fn describe(root: &std::path::Path, s: &CaptureSummary) -> String {
    let b = &s.bounds;
    let mut text = format!(
        "capture     {}\nviews       {} ({} train, {} test)\nkinds       {}\nresolution  {}×{}\n",
        root.display(),
        s.views,
        s.train_views,
        s.test_views,
        s.kinds.join(", "),
        s.width,
        s.height,
    );
    let working = |budget| {
        let k = Resolution::Auto.factor(s.width.max(1), s.height.max(1), budget);
        match k {
            1 => format!("{}×{}", s.width, s.height),
            k => format!("{}×{} (÷ {k})", s.width / k, s.height / k),
        }
    };
    text.push_str(&format!(
        "training    at {} on the host engines, {} on a GPU (--resolution auto)\n",
        working(Resolution::HOST_PIXEL_BUDGET),
        working(Resolution::DEVICE_PIXEL_BUDGET),
    ));
    if !s.polarizer_groups.is_empty() {
        text.push_str(&format!(
            "polarizer groups  {}\n",
            s.polarizer_groups.join(", ")
        ));
    }
    text.push_str(&format!(
        "world up    [{}, {}, {}]\nbounds      centre [{:.3}, {:.3}, {:.3}], radius {:.3}; box [{:.3}, {:.3}, {:.3}] – [{:.3}, {:.3}, {:.3}]\n",
        s.world_up.x, s.world_up.y, s.world_up.z,
        b.center.x, b.center.y, b.center.z, b.radius,
        b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z,
    ));
    match &s.dolp {
        Some(d) => text.push_str(&format!(
            "DoLP        mean {:.3}, median {:.3}, p90 {:.3} over {} masked pixels of the full-Stokes views\n",
            d.mean, d.median, d.p90, d.pixels
        )),
        None if s.kinds.iter().any(|k| k == "partial" || k == "rgb") => {
            text.push_str("DoLP        – (no full-Stokes view)\n")
        }
        None => {}
    }
    if let Some(share) = s.polarization_above_noise {
        text.push_str(&format!(
            "signal      {:.0} % of the polarized power above the views' noise (the AoLP prior's mean confidence)\n",
            100.0 * share
        ));
    }
    if let Some(level) = s.background_level {
        let meaning = if level == 0.0 {
            " (black, as rendered)".to_owned()
        } else if level <= DARK_BACKGROUND_LEVEL {
            format!(
                " (dark: the training targets keep the images within {DARK_RIM_PX} px of the masks, \
                 where a mask short of the object leaves its rim, and are black farther out)"
            )
        } else {
            " (black in the training targets: the model holds only the object)".to_owned()
        };
        text.push_str(&format!(
            "background  {level:.2} of the object's mean brightness beyond the masks{meaning}\n"
        ));
    }
    if let Some(raw) = &s.raw {
        text.push_str(&format!(
            "raw frames  {} demosaiced ({}){}\n",
            raw.frames.len(),
            format!("{:?}", raw.demosaic).to_lowercase(),
            match (&raw.white_balance, raw.white_balance_gains) {
                (Some(how), Some([r, g, b])) => {
                    format!(", white balance ({how}) R {r:.3}, G {g:.3}, B {b:.3}")
                }
                _ => String::new(),
            }
        ));
    }
    if let Some(colmap) = &s.colmap {
        text.push_str(&format!(
            "COLMAP      {} ({}), {} camera(s), {} view(s) undistorted, {} sparse points\n",
            colmap.model.display(),
            format!("{:?}", colmap.format).to_lowercase(),
            colmap.cameras,
            colmap.undistorted_views,
            s.sparse_points
        ));
    }
    for warning in &s.warnings {
        text.push_str(&format!("warning     {warning}\n"));
    }
    text
}

/// The conventions found from the data, each with its evidence.
fn describe_conventions(report: &ConventionsReport) -> String {
    let mut text = String::new();
    if let Some(s) = &report.stokes {
        let verdict = format!("{:?}", s.verdict).to_lowercase();
        text.push_str(&format!(
            "stokes      {verdict} (stated {}): {}\n",
            s.stated, s.explanation
        ));
    }
    if let Some(c) = &report.color {
        let fits = c.fits.map_or("inconclusive", |e| e.label());
        text.push_str(&format!(
            "colour      {fits} (stated {}): {}\n",
            c.stated, c.explanation
        ));
    }
    text
}
