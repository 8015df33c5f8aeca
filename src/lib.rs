//! PhyGaP: relightable reconstruction of glossy objects from polarization captures.
//!
//! 2D Gaussian surfels are rasterized into G-buffers, shaded by a polarimetric deferred renderer
//! (PolarDR) into Stokes images, and fitted to captured polarization. The science is in
//! `shared/docs/METHOD.md`; each module is named after the concept it computes.

pub mod bench;
pub mod camera;
pub mod config;
pub mod gradcheck;
pub mod image_io;
pub mod raster;
pub mod surfels;
