//! PhyGaP: relightable reconstruction of glossy objects from polarization captures.
//!
//! 2D Gaussian surfels are rasterized into G-buffers, shaded by a polarimetric deferred renderer
//! (PolarDR) into Stokes images, and fitted to captured polarization. The science is in
//! `shared/docs/METHOD.md`; each module is named after the concept it computes.
//!
//! The modules form layers, each using only the layers listed before it (`tests/module_layers.rs`
//! checks this, and that no modules of one layer use each other in a circle):
//!
//! 1. [`formats`]: file formats that know nothing of the method (images, PLY, checkpoints);
//! 2. [`core`]: the method's maths and the f64 reference engine, plus the fast host engine;
//! 3. [`testing`]: fixtures for the tests and benchmarks (synthetic surfels, random gradients,
//!    the shared captures' folder);
//! 4. [`gpu`]: the wgpu engine, built on the core's types only;
//! 5. [`io`]: captures in, trained model folders in and out;
//! 6. [`pipeline`]: training, reconstruction, meshing, relighting, export, evaluation, benchmarks;
//!
//! with the CLI (`src/bin/phygap`) and the REST service (the `phygap-api` crate) on top.

pub mod core;
pub mod formats;
pub mod gpu;
pub mod io;
pub mod pipeline;
pub mod testing;
