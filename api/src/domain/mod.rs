//! The bottom layer: plain values every other layer shares, with no I/O and no HTTP — record
//! identifiers ([`ids`]), inputs quoted in messages ([`text`]) and the refusal the layers below
//! HTTP answer when a request breaks the service's rules ([`refusal`]).

pub mod ids;
pub mod refusal;
pub mod text;
