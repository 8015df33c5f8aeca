//! Hostile image files: a few bytes each, declaring images of any size in their headers (the
//! inputs that once made a reader allocate 40 GB). Tests of the size checks, the service's
//! crash reproductions and the fuzz corpus use them.

use crate::formats::image_io::{write_exr, Image};

/// A valid one-channel EXR file of 1 × 1 pixel whose header then declares a `width × height`
/// data window (its single chunk stays as it was).
pub fn exr_declaring(width: u32, height: u32) -> Vec<u8> {
    let dir = tempfile_dir();
    let path = dir.join("one.exr");
    write_exr(&path, &Image::filled(1, 1, 1, 0.5)).expect("writing a 1×1 EXR");
    let mut bytes = std::fs::read(&path).expect("reading it back");
    let _ = std::fs::remove_dir_all(&dir);
    for name in [&b"dataWindow\0box2i\0"[..], &b"displayWindow\0box2i\0"[..]] {
        let at = find(&bytes, name).expect("a box2i window attribute") + name.len() + 4;
        let max = [width as i32 - 1, height as i32 - 1];
        for (i, value) in [0i32, 0, max[0], max[1]].iter().enumerate() {
            bytes[at + 4 * i..at + 4 * i + 4].copy_from_slice(&value.to_le_bytes());
        }
    }
    bytes
}

/// The signature and header chunk of an 8-bit RGB PNG declaring `width × height`, then an empty
/// image-data chunk and the end chunk (checksums correct, pixels absent).
pub fn png_declaring(width: u32, height: u32) -> Vec<u8> {
    let mut bytes = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut header = Vec::new();
    header.extend_from_slice(&width.to_be_bytes());
    header.extend_from_slice(&height.to_be_bytes());
    header.extend_from_slice(&[8, 2, 0, 0, 0]);
    for (kind, data) in [
        (b"IHDR", header),
        (b"IDAT", Vec::new()),
        (b"IEND", Vec::new()),
    ] {
        bytes.extend_from_slice(&(data.len() as u32).to_be_bytes());
        let mut chunk = kind.to_vec();
        chunk.extend_from_slice(&data);
        bytes.extend_from_slice(&chunk);
        bytes.extend_from_slice(&crc32(&chunk).to_be_bytes());
    }
    bytes
}

/// A Radiance HDR header declaring `width × height` with no pixel data.
pub fn hdr_declaring(width: u32, height: u32) -> Vec<u8> {
    format!("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y {height} +X {width}\n").into_bytes()
}

fn find(haystack: &[u8], needle: &[u8]) -> Option<usize> {
    haystack.windows(needle.len()).position(|w| w == needle)
}

/// A fresh folder under the system's temporary folder.
fn tempfile_dir() -> std::path::PathBuf {
    use std::sync::atomic::{AtomicU64, Ordering};
    static NEXT: AtomicU64 = AtomicU64::new(0);
    let dir = std::env::temp_dir().join(format!(
        "phygap-hostile-{}-{}",
        std::process::id(),
        NEXT.fetch_add(1, Ordering::Relaxed)
    ));
    std::fs::create_dir_all(&dir).expect("creating a temporary folder");
    dir
}

/// CRC-32 (ISO 3309, as PNG uses), bit by bit.
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &byte in bytes {
        crc ^= u32::from(byte);
        for _ in 0..8 {
            crc = if crc & 1 == 1 {
                (crc >> 1) ^ 0xEDB8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crc32_matches_the_standard_check_value() {
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
    }
}
