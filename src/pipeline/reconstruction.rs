//! A trained model made ready to render: its prefiltered environment, GridMap when the model was
//! trained with it (mesh extracted from the training cameras, probes under the environment), the
//! BRDF table and a backend. Rendering novel views to files (`phygap render`), evaluation
//! (`phygap eval`) and relighting (a replaced environment map, which rebuilds the probes) all go
//! through it.

use std::path::{Path, PathBuf};

use glam::DVec3;
use thiserror::Error;

use crate::core::brdf_lut::BrdfLut;
use crate::core::camera::Camera;
use crate::core::config::TrainConfig;
use crate::core::envmap::{CubeMap, EnvMapError, MipChainSpec, PrefilterPlan, PreparedEnv};
use crate::core::gridmap::GridMap;
use crate::core::light::LightProbe;
use crate::core::mesh::{DepthPixels, TriangleMesh};
use crate::core::render::{RenderError, RenderedView, Scene};
use crate::formats::image_io::{self, Image, ImageError};
use crate::io::capture::Capture;
use crate::io::model::Model;
use crate::pipeline::backend::{self, BackendError, Engine};
use crate::pipeline::evaluate::{self, EvalError, EvalReport};
use crate::pipeline::mesh_extraction::{self, GRIDMAP_MESH_RESOLUTION};
use crate::pipeline::previews;

#[derive(Debug, Error)]
pub enum ReconstructionError {
    #[error(transparent)]
    EnvMap(#[from] EnvMapError),
    #[error(transparent)]
    Backend(#[from] BackendError),
    #[error(transparent)]
    Render(#[from] RenderError),
    #[error(transparent)]
    Eval(#[from] EvalError),
    #[error(transparent)]
    Image(#[from] ImageError),
    #[error("{path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
}

/// A model with everything needed to render it.
pub struct Reconstruction {
    pub model: Model,
    env: PreparedEnv,
    /// The mesh GridMap traces against (models trained with GridMap only).
    mesh: Option<TriangleMesh>,
    gridmap: Option<GridMap>,
    backend: Engine,
    lut: &'static BrdfLut,
}

/// The environment-map prefilter plan for a learned map of face size `size`.
pub fn prefilter_plan(
    size: usize,
    fresnel_irradiance: bool,
    levels_per_size: usize,
) -> Result<std::sync::Arc<PrefilterPlan>, EnvMapError> {
    PrefilterPlan::new(MipChainSpec {
        base_size: size,
        min_size: (size / 4).max(2),
        fresnel_irradiance,
        levels_per_size,
        ..MipChainSpec::default()
    })
}

/// The prefilter plan a run with `config` trains with, for a learned map of face size `size`
/// (its model's map, whose size is the config's `envmap_resolution`): the one place that reads
/// which settings shape the chain, so a model renders with the chain it was trained with.
pub fn run_prefilter_plan(
    config: &TrainConfig,
    size: usize,
) -> Result<std::sync::Arc<PrefilterPlan>, EnvMapError> {
    prefilter_plan(
        size,
        config.fresnel_irradiance,
        config.mip_levels_per_size as usize,
    )
}

impl Reconstruction {
    pub fn new(model: Model) -> Result<Self, ReconstructionError> {
        let mut reconstruction = Self::without_gridmap(model)?;
        if reconstruction.trained_with_gridmap() {
            let model = &reconstruction.model;
            reconstruction.mesh = mesh_extraction::mesh_from_surfels(
                &model.surfels,
                &mesh_extraction::model_cameras(model),
                &*reconstruction.backend,
                &model.raster_settings(),
                GRIDMAP_MESH_RESOLUTION,
                DepthPixels::All,
            )
            .inspect_err(|e| {
                tracing::warn!("GridMap mesh extraction failed, rendering without GridMap: {e}")
            })
            .ok();
            reconstruction.rebuild_gridmap();
        }
        Ok(reconstruction)
    }

    /// The same model under another environment map (already in the model's frame and face
    /// size): the prefilters and GridMap's probes are rebuilt under it, GridMap's mesh (which
    /// depends on the surfels alone) is reused.
    pub fn relit(&self, envmap: CubeMap) -> Result<Self, ReconstructionError> {
        let mut model = self.model.clone();
        model.envmap = envmap;
        let mut relit = Self::without_gridmap(model)?;
        relit.mesh = self.mesh.clone();
        relit.rebuild_gridmap();
        Ok(relit)
    }

    /// The model with its prefiltered environment and a backend, GridMap not built.
    fn without_gridmap(model: Model) -> Result<Self, ReconstructionError> {
        let plan = run_prefilter_plan(&model.config, model.envmap.size)?;
        let env = PreparedEnv::new(&model.envmap, plan)?;
        let backend = backend::select(model.config.backend)?;
        Ok(Reconstruction {
            model,
            env,
            mesh: None,
            gridmap: None,
            backend,
            lut: BrdfLut::shared(),
        })
    }

    /// Whether the model's PolarDR stage ran with GridMap (then it renders with it too).
    fn trained_with_gridmap(&self) -> bool {
        let config = &self.model.config;
        config.gridmap && config.polar_stage_start() < self.model.info.iterations
    }

    fn rebuild_gridmap(&mut self) {
        self.gridmap = self.mesh.as_ref().and_then(|mesh| {
            GridMap::build(
                mesh,
                &self.model.surfels,
                &self.model.envmap,
                self.env.clone(),
                self.model.config.gridmap_anchors,
            )
            .inspect_err(|e| tracing::warn!("GridMap build failed, rendering without it: {e}"))
            .ok()
        });
    }

    /// The model it renders.
    pub fn model(&self) -> &Model {
        &self.model
    }

    /// The mesh GridMap traces against, when the model renders with GridMap.
    pub fn mesh(&self) -> Option<&TriangleMesh> {
        self.mesh.as_ref()
    }

    /// GridMap, when the model renders with it.
    pub fn gridmap(&self) -> Option<&GridMap> {
        self.gridmap.as_ref()
    }

    /// The model's environment, prefiltered with the chain it was trained with.
    pub fn environment(&self) -> &PreparedEnv {
        &self.env
    }

    /// The light the model is shaded with: GridMap over the environment, or the environment.
    pub fn light(&self) -> &dyn LightProbe {
        match &self.gridmap {
            Some(grid) => grid,
            None => &self.env,
        }
    }

    pub fn scene(&self) -> Scene<'_> {
        Scene {
            surfels: &self.model.surfels,
            light: self.light(),
            lut: self.lut,
            backend: &*self.backend,
            settings: self.model.raster_settings(),
        }
    }

    /// Metrics on the capture's test views.
    pub fn evaluate(&self, capture: &Capture) -> Result<EvalReport, ReconstructionError> {
        Ok(evaluate::evaluate(
            &self.scene(),
            capture,
            &self.model.polarizer_angles(),
        )?)
    }

    /// Renders every camera and writes `DIR/<kind>/<name>.exr` and `.png` for each kind of
    /// [`OUTPUT_KINDS`] in `kinds`. Returns the files written.
    pub fn render_to_dir(
        &self,
        cameras: &[(String, Camera)],
        out: &Path,
        kinds: &[&str],
    ) -> Result<Vec<PathBuf>, ReconstructionError> {
        let _span = tracing::info_span!("render_to_dir", views = cameras.len()).entered();
        for kind in kinds {
            let dir = out.join(kind);
            std::fs::create_dir_all(&dir)
                .map_err(|source| ReconstructionError::Io { path: dir, source })?;
        }
        let scene = self.scene();
        let mut written = Vec::new();
        for (index, (_, camera)) in cameras.iter().enumerate() {
            let rendered = scene.render(camera)?;
            let images = output_images(&rendered);
            for (kind, (linear, preview)) in images {
                if !kinds.contains(&kind) {
                    continue;
                }
                let exr = out.join(kind).join(format!("{index:03}.exr"));
                let png = exr.with_extension("png");
                image_io::write_exr(&exr, &linear)?;
                image_io::write_png(&png, &preview.0, preview.1)?;
                written.extend([exr, png]);
            }
        }
        Ok(written)
    }
}

/// Every image `phygap render` can write.
pub const OUTPUT_KINDS: [&str; 12] = [
    "s0",
    "s1",
    "s2",
    "dolp",
    "aolp",
    "normal",
    "albedo",
    "roughness",
    "ior",
    "diffuse",
    "specular",
    "alpha",
];

/// A preview image and whether it is to be sRGB-encoded.
type Preview = (Image, bool);

fn image(width: usize, height: usize, channels: usize, values: &[f64]) -> Image {
    Image {
        width,
        height,
        channels,
        data: values.iter().map(|&v| v as f32).collect(),
    }
}

/// The linear image and the 8-bit preview of each output kind of a rendered view.
fn output_images(view: &RenderedView) -> Vec<(&'static str, (Image, Preview))> {
    let g = view.gbuffers();
    let (w, h) = (g.width, g.height);
    let s = &view.shaded;
    let rgb = |values: Vec<f64>| image(w, h, 3, &values);
    let grey = |values: Vec<f64>| image(w, h, 1, &values);
    let mapped = |img: &Image, f: &dyn Fn(f32) -> f32| Image {
        data: img.data.iter().map(|&v| f(v)).collect(),
        ..img.clone()
    };
    let s0 = rgb(view.premultiplied(&s.s0));
    let s1 = rgb(view.premultiplied(&s.s1));
    let s2 = rgb(view.premultiplied(&s.s2));
    let sums = |stokes: &[DVec3]| -> Vec<f64> { stokes.iter().map(|v| v.element_sum()).collect() };
    let (dolp, aolp) = previews::dolp_aolp(&sums(&s.s0), &sums(&s.s1), &sums(&s.s2));
    let dolp = grey(dolp);
    let aolp = grey(aolp);
    let normal: Vec<f64> = g
        .normal
        .iter()
        .flat_map(|n| DVec3::from_array(*n).normalize_or_zero().to_array())
        .collect();
    let normal = rgb(normal);
    let diffuse = rgb(view.premultiplied(&s.diffuse));
    let specular = rgb(view.premultiplied(&s.specular));
    let signed = |v: f32| 0.5 + 0.5 * v;
    vec![
        ("s0", (s0.clone(), (s0, true))),
        ("s1", (s1.clone(), (mapped(&s1, &signed), false))),
        ("s2", (s2.clone(), (mapped(&s2, &signed), false))),
        ("dolp", (dolp.clone(), (dolp, false))),
        (
            "aolp",
            (
                aolp.clone(),
                (mapped(&aolp, &previews::aolp_preview), false),
            ),
        ),
        (
            "normal",
            (normal.clone(), (mapped(&normal, &signed), false)),
        ),
        ("albedo", {
            let a = rgb(g.albedo.as_flattened().to_vec());
            (a.clone(), (a, true))
        }),
        ("roughness", {
            let r = grey(g.roughness.clone());
            (r.clone(), (r, false))
        }),
        ("ior", {
            let i = grey(g.ior.clone());
            (i.clone(), (mapped(&i, &|v| v - 1.3), false))
        }),
        ("diffuse", (diffuse.clone(), (diffuse, true))),
        ("specular", (specular.clone(), (specular, true))),
        ("alpha", {
            let a = grey(g.alpha.clone());
            (a.clone(), (a, false))
        }),
    ]
}
