//! PhyGaP: relightable reconstruction of glossy objects from polarization captures.
//!
//! 2D Gaussian surfels are rasterized into G-buffers, shaded by a polarimetric deferred renderer
//! (PolarDR) into Stokes images, and fitted to captured polarization. The science is in
//! `shared/docs/METHOD.md`; each module is named after the concept it computes.

pub mod bvh;
pub mod camera;
pub mod checkpoint;
pub mod config;
pub mod densify;
pub mod events;
pub mod gradcheck;
pub mod image_io;
pub mod kdtree;
pub mod mesh;
pub mod surfels;
