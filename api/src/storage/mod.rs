//! Above the domain: where the service keeps things — [`store`] (durable records of captures,
//! jobs, uploads and the queue: SQLite or PostgreSQL), [`bucket`] (the object store a scaled-out
//! deployment shares), [`artifacts`] (what jobs produce), [`object_keys`] (every key of the
//! bucket), [`upload_parts`] (the parts of resumable uploads), [`local_files`] (walking the data
//! dir's folders) and [`archive`] (safe extraction of uploaded archives). Each answers its own
//! errors.

pub mod archive;
pub mod artifacts;
pub mod bucket;
pub mod local_files;
pub mod object_keys;
pub mod store;
pub mod upload_parts;
