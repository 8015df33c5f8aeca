//! PhyGaP: relightable reconstruction of glossy objects from polarization captures.
//!
//! 2D Gaussian surfels are rasterized into G-buffers, shaded by a polarimetric deferred renderer
//! (PolarDR) into Stokes images, and fitted to captured polarization. The science is in
//! `shared/docs/METHOD.md`; each module is named after the concept it computes.

pub mod allocator;
pub mod backend;
pub mod bench;
pub mod brdf_lut;
pub mod bvh;
pub mod camera;
pub mod capture;
pub mod checkpoint;
pub mod config;
pub mod densify;
pub mod envmap;
pub mod evaluate;
pub mod events;
pub mod export;
pub mod gpu;
pub mod gradcheck;
pub mod gridmap;
pub mod image_io;
pub mod kdtree;
pub mod loss;
pub mod mesh;
pub mod meshing;
pub mod metrics;
pub mod model;
pub mod optim;
pub mod ply;
pub mod raster;
pub mod reconstruction;
pub mod relight;
pub mod render;
pub mod scorecard;
pub mod shading;
pub mod surfels;
pub mod synth;
pub mod testing;
pub mod train;
