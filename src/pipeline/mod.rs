//! The work a user asks for, composed from the layers below: choosing an engine, training,
//! making a trained model ready to render (reconstruction), mesh extraction, relighting, export,
//! evaluation and its scorecard, synthetic captures, and the benchmarks of `phygap bench`.

pub mod allocator;
pub mod backend;
pub mod bench;
pub mod diagnose;
pub mod evaluate;
pub mod export;
pub mod mesh_extraction;
pub mod peak_memory;
pub mod previews;
pub mod reconstruction;
pub mod relight;
pub mod scorecard;
pub mod synth;
pub mod train;
