//! File formats that know nothing of the method: images (EXR, HDR, PNG), the PLY container and
//! bit-exact checkpoint files. The lowest layer: it uses no other module of the crate.

pub mod checkpoint;
pub mod image_io;
pub mod ply;
