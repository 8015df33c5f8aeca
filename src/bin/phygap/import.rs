//! `phygap import FOLDER [--out DIR]`: reads a dataset in the IDR/NeuS or LLFF layout (the
//! readers of `io::capture::layouts`), prints what it decided (layout, views, the cameras' frame,
//! which folder holds which angle or Stokes component, masks, colour space, world up), writes the
//! equivalent `transforms.json` into FOLDER (or DIR, with the files it names copied there), and
//! loads the result to check it.
//!
//! `phygap train` and the service read these layouts directly; `import` is for seeing what was
//! decided, editing it, or handing the capture to tools that read `transforms.json`.

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use clap::Args;
use serde_json::Value;

use phygap::io::capture::{self, colmap, layouts};

#[derive(Args, Debug)]
pub struct ImportArgs {
    /// The dataset folder (holding `cameras.npz`, `cameras_sphere.npz`, `cameras_new.npz` or
    /// `poses_bounds.npy`).
    pub folder: PathBuf,
    /// Write `transforms.json` and a copy of the files it names here instead of into FOLDER.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

/// Every `*_path` value of the document's frames.
fn named_files(document: &Value) -> Vec<String> {
    let mut files: Vec<String> = document["frames"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(Value::as_object)
        .flat_map(|frame| {
            frame
                .iter()
                .filter(|(key, _)| key.ends_with("_path"))
                .filter_map(|(_, v)| v.as_str().map(str::to_owned))
        })
        .collect();
    files.sort();
    files.dedup();
    files
}

/// Copies the files `document` names from `root` into `out`, keeping their relative paths.
fn copy_files(root: &Path, out: &Path, document: &Value) -> Result<usize> {
    let files = named_files(document);
    for file in &files {
        let target = out.join(file);
        if let Some(parent) = target.parent() {
            std::fs::create_dir_all(parent)
                .with_context(|| format!("cannot create {}", parent.display()))?;
        }
        std::fs::copy(root.join(file), &target)
            .with_context(|| format!("cannot copy {file} to {}", target.display()))?;
    }
    Ok(files.len())
}

pub fn run(args: &ImportArgs) -> Result<()> {
    let folder = &args.folder;
    let Some(location) = layouts::find_layout(folder) else {
        if folder.join("transforms.json").is_file() {
            bail!(
                "{} already holds a transforms.json: it is a capture as it is (see `phygap inspect`)",
                folder.display()
            );
        }
        if colmap::find_model(folder).is_some() {
            bail!(
                "{} holds a COLMAP model: phygap reads it as it is (see `phygap inspect`)",
                folder.display()
            );
        }
        bail!(
            "no dataset layout found in {}: expected an IDR/NeuS camera file ({}) or LLFF's {}",
            folder.display(),
            layouts::idr::CAMERA_FILES.join(", "),
            layouts::llff::POSES_FILE
        );
    };
    let imported = layouts::import(folder, &location)?;
    print!("{}", imported.report);
    let out = args.out.clone().unwrap_or_else(|| imported.root.clone());
    std::fs::create_dir_all(&out).with_context(|| format!("cannot create {}", out.display()))?;
    let out = out.canonicalize().unwrap_or(out);
    if out != imported.root {
        let copied = copy_files(&imported.root, &out, &imported.document)?;
        println!(
            "copied the {copied} files the views name into {}",
            out.display()
        );
    }
    println!(
        "no file converted: phygap reads the layout's images, .npy arrays and masks as they are"
    );
    let json_path = out.join("transforms.json");
    let text = serde_json::to_string_pretty(&imported.document)?;
    std::fs::write(&json_path, text)
        .with_context(|| format!("cannot write {}", json_path.display()))?;
    println!("wrote {}", json_path.display());
    let loaded = capture::load(&out).with_context(|| {
        format!(
            "{} was written, but the capture it describes does not load",
            json_path.display()
        )
    })?;
    let summary = loaded.summary();
    println!(
        "checked: {} views ({} train, {} test), {}×{}, kinds {}",
        summary.views,
        summary.train_views,
        summary.test_views,
        summary.width,
        summary.height,
        summary.kinds.join(", ")
    );
    for warning in &summary.warnings {
        println!("warning: {warning}");
    }
    Ok(())
}
