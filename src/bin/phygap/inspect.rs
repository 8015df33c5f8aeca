//! `phygap inspect CAPTURE [--json]`: load and validate a capture, then print what it holds.

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;

use phygap::io::capture::{self, CaptureSummary};

/// Arguments of `phygap inspect`.
#[derive(Args, Debug)]
pub struct InspectArgs {
    /// Capture folder (with transforms.json) or a transforms JSON file.
    pub capture: PathBuf,
    /// Print the summary as JSON.
    #[arg(long)]
    pub json: bool,
}

/// Loads the capture and prints its summary. A broken capture prints one error line (every problem
/// found, separated by `;`) on stderr and exits with status 1.
pub fn run(args: &InspectArgs) -> Result<()> {
    let capture = capture::load(&args.capture)?;
    let summary = capture.summary();
    if args.json {
        println!("{}", serde_json::to_string_pretty(&summary)?);
    } else {
        print!("{}", describe(&capture.root, &summary));
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
    for warning in &s.warnings {
        text.push_str(&format!("warning     {warning}\n"));
    }
    text
}
