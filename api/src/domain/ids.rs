//! Identifiers of the records the service keeps (captures, jobs, uploads) and of stored copies.

use rand::RngCore;

/// A random identifier with a prefix (`job_…`, `cap_…`): 96 random bits, hex.
pub fn new_id(prefix: &str) -> String {
    let mut bytes = [0u8; 12];
    rand::rng().fill_bytes(&mut bytes);
    let hex: String = bytes.iter().map(|b| format!("{b:02x}")).collect();
    format!("{prefix}_{hex}")
}
