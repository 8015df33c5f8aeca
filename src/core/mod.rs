//! The method's maths (METHOD.md): cameras, surfels, the learnable light (environment map and
//! GridMap), PolarDR shading, losses, the optimizer and density control; the rasterizer interface
//! with its f64 reference engine (what every other engine is tested against) and the fast f32
//! host engine; triangle meshes and metrics. Uses only [`crate::formats`].

pub mod background;
pub mod blur;
pub mod brdf_lut;
pub mod camera;
pub mod config;
pub mod densify;
pub mod engine;
pub mod envmap;
pub mod events;
pub mod filled;
pub mod gradcheck;
pub mod gridmap;
pub mod iterations;
pub mod kdtree;
pub mod light;
pub mod loss;
pub mod mask_band;
pub mod mesh;
pub mod metrics;
pub mod optim;
pub mod polarization_confidence;
pub mod pose;
pub mod raster;
pub mod render;
pub mod resolution;
pub mod setting;
pub mod shading;
pub mod silhouette;
pub mod simd;
pub mod similarity;
pub mod step;
pub mod surfels;
pub mod view_spread;
