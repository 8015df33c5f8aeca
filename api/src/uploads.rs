//! Resumable uploads: a capture archive sent in parts, in any order, over as many requests (and
//! broken connections) as it takes.
//!
//! An upload declares the archive's size and a part size, which fix every part's length. Each part
//! arrives with its SHA-256 (`Content-Digest: sha-256=:…:`, RFC 9530) and is kept only when its
//! length and digest match; it is stored under a name that holds its digest, so a part sent again
//! never overwrites the copy a commit may be reading. Parts live in the object store when the
//! deployment has one (any replica may receive any part), else under `uploads/` in the data dir.
//! A commit joins the parts in order into one file, checking each part's digest again and the
//! whole archive's when one was declared, and hands it to the validation a one-shot upload gets.
//! Uploads idle for longer than `--upload-expiry-hours` are removed with their parts
//! ([`sweep_idle`]).

use std::path::{Path, PathBuf};

use axum::body::Body;
use axum::http::{HeaderMap, StatusCode};
use base64::Engine as _;
use futures_util::StreamExt;
use sha2::{Digest as _, Sha256};
use tokio::io::AsyncWriteExt;

use crate::error::ApiError;
use crate::store::{UploadPart, UploadRecord};
use crate::AppState;

/// Smallest part size an upload may choose (the last part may be shorter).
pub const MIN_PART_BYTES: u64 = 64 << 10;
/// Largest part size: what one request carries, and what the object store holds in memory while
/// it stores the part.
pub const MAX_PART_BYTES: u64 = 128 << 20;
/// The part size of an upload that names none.
pub const DEFAULT_PART_BYTES: u64 = 64 << 20;
/// Most parts of one upload.
pub const MAX_PARTS: u64 = 10_000;

/// How many parts an archive of `size` bytes has in parts of `part_size` bytes.
pub fn part_count(size: u64, part_size: u64) -> u64 {
    size.div_ceil(part_size.max(1))
}

/// The length part `index` must have, `None` past the last part.
pub fn part_length(upload: &UploadRecord, index: u32) -> Option<u64> {
    let start = u64::from(index).checked_mul(upload.part_size)?;
    (start < upload.size).then(|| upload.part_size.min(upload.size - start))
}

/// The SHA-256 a request declares in its `Content-Digest` header (RFC 9530: a dictionary such as
/// `sha-256=:<base64>:`; other algorithms beside it are ignored).
pub fn content_digest(headers: &HeaderMap) -> Result<[u8; 32], ApiError> {
    let Some(value) = headers.get("content-digest") else {
        return Err(ApiError::bad_request(
            "digest_required",
            "send the part's SHA-256 as `Content-Digest: sha-256=:<base64>:`",
        ));
    };
    let invalid = || {
        ApiError::bad_request(
            "invalid_digest",
            "Content-Digest needs a `sha-256=:<base64 of 32 bytes>:` member",
        )
    };
    let text = value.to_str().map_err(|_| invalid())?;
    let encoded = text
        .split(',')
        .filter_map(|member| member.trim().split_once('='))
        .find(|(algorithm, _)| algorithm.trim().eq_ignore_ascii_case("sha-256"))
        .and_then(|(_, value)| value.trim().strip_prefix(':')?.strip_suffix(':'))
        .ok_or_else(invalid)?;
    base64::engine::general_purpose::STANDARD
        .decode(encoded)
        .ok()
        .and_then(|bytes| <[u8; 32]>::try_from(bytes).ok())
        .ok_or_else(invalid)
}

/// Lower-case hexadecimal of a digest.
pub fn hex(digest: &[u8]) -> String {
    digest.iter().map(|b| format!("{b:02x}")).collect()
}

/// Whether `text` is a SHA-256 in lower- or upper-case hexadecimal.
pub fn is_sha256_hex(text: &str) -> bool {
    text.len() == 64 && text.bytes().all(|b| b.is_ascii_hexdigit())
}

/// Where a part's bytes are kept, relative to the object store's root or the data dir.
fn part_key(upload_id: &str, part: &UploadPart) -> String {
    crate::object_keys::upload_part(upload_id, part.index, &part.sha256)
}

/// A temporary file removed when dropped, unless it was moved away.
struct TempFile(PathBuf);

impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

fn part_size_mismatch(index: u32, expected: u64) -> ApiError {
    ApiError::bad_request(
        "part_size_mismatch",
        format!("part {index} must be {expected} bytes long"),
    )
}

/// Receives part `index` of `upload` (`expected` bytes long) from `body`, checks its length and
/// `digest`, and stores it.
/// Returns the part to record; nothing is left behind when it is refused or the body breaks off.
pub async fn receive_part(
    state: &AppState,
    upload: &UploadRecord,
    index: u32,
    expected: u64,
    body: Body,
    digest: [u8; 32],
) -> Result<UploadPart, ApiError> {
    let temp = TempFile(state.paths.tmp.join(format!(
        "{}.{index}.{}",
        upload.id,
        crate::queue::new_id("part")
    )));
    let mut hasher = Sha256::new();
    let received = crate::routes::captures::stream_to_file_with(
        body,
        &temp.0,
        expected,
        || part_size_mismatch(index, expected),
        |chunk| hasher.update(chunk),
    )
    .await?;
    if received != expected {
        return Err(part_size_mismatch(index, expected));
    }
    let actual: [u8; 32] = hasher.finalize().into();
    if actual != digest {
        return Err(ApiError::bad_request(
            "digest_mismatch",
            format!(
                "part {index}'s SHA-256 is {}, not the {} its Content-Digest declares",
                hex(&actual),
                hex(&digest)
            ),
        ));
    }
    let part = UploadPart {
        index,
        size: received,
        sha256: hex(&actual),
    };
    let key = part_key(&upload.id, &part);
    match &state.bucket {
        Some(bucket) => bucket.upload_file(&key, &temp.0).await?,
        None => {
            let target = state.paths.root.join(&key);
            if let Some(folder) = target.parent() {
                tokio::fs::create_dir_all(folder)
                    .await
                    .map_err(|e| ApiError::internal("storing a part", e))?;
            }
            tokio::fs::rename(&temp.0, &target)
                .await
                .map_err(|e| ApiError::internal("storing a part", e))?;
        }
    }
    Ok(part)
}

/// Removes one stored copy of a part (one that was replaced by a part sent again).
pub async fn discard_part(state: &AppState, upload_id: &str, part: &UploadPart) {
    let key = part_key(upload_id, part);
    let result = match &state.bucket {
        Some(bucket) => bucket.delete(&key).await.map_err(|e| e.to_string()),
        None => match tokio::fs::remove_file(state.paths.root.join(&key)).await {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(e.to_string()),
            _ => Ok(()),
        },
    };
    if let Err(e) = result {
        tracing::warn!(upload_id, key, error = %e, "removing a replaced part failed");
    }
}

/// Removes every stored part of an upload.
pub async fn discard_parts(state: &AppState, upload_id: &str) {
    let folder = crate::object_keys::upload(upload_id);
    if let Some(bucket) = &state.bucket {
        if let Err(e) = bucket.delete_folder(&folder).await {
            tracing::warn!(upload_id, error = %e, "removing an upload's parts failed");
        }
    }
    match tokio::fs::remove_dir_all(state.paths.root.join(&folder)).await {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
            tracing::warn!(upload_id, error = %e, "removing an upload's parts failed");
        }
        _ => {}
    }
}

/// Joins an upload's parts, in order, into `target`: each part's bytes are checked against the
/// digest recorded for it, and the whole archive's against the upload's declared SHA-256.
/// A whole-archive mismatch is the client's (422 `digest_mismatch`); a part that no longer
/// matches its record is a storage fault (500).
pub async fn assemble(
    state: &AppState,
    upload: &UploadRecord,
    target: &Path,
) -> Result<(), ApiError> {
    let mut file = tokio::fs::File::create(target)
        .await
        .map_err(|e| ApiError::internal("joining the parts", e))?;
    let mut whole = Sha256::new();
    for part in &upload.parts {
        let key = part_key(&upload.id, part);
        let mut part_digest = Sha256::new();
        let mut stream: std::pin::Pin<
            Box<dyn futures_util::Stream<Item = std::io::Result<bytes::Bytes>> + Send>,
        > = match &state.bucket {
            Some(bucket) => Box::pin(bucket.read_range(&key, 0, part.size).await?),
            None => {
                let local = tokio::fs::File::open(state.paths.root.join(&key))
                    .await
                    .map_err(|e| ApiError::internal("reading a stored part", e))?;
                Box::pin(tokio_util::io::ReaderStream::new(local))
            }
        };
        while let Some(chunk) = stream.next().await {
            let chunk = chunk.map_err(|e| ApiError::internal("reading a stored part", e))?;
            part_digest.update(&chunk);
            whole.update(&chunk);
            file.write_all(&chunk)
                .await
                .map_err(|e| ApiError::internal("joining the parts", e))?;
        }
        if hex(&part_digest.finalize()) != part.sha256 {
            return Err(ApiError::internal(
                "joining the parts",
                format!("stored part {} of {} changed", part.index, upload.id),
            ));
        }
    }
    file.flush()
        .await
        .map_err(|e| ApiError::internal("joining the parts", e))?;
    let actual = hex(&whole.finalize());
    match &upload.sha256 {
        Some(declared) if !declared.eq_ignore_ascii_case(&actual) => Err(ApiError::new(
            StatusCode::UNPROCESSABLE_ENTITY,
            "digest_mismatch",
            format!("the joined archive's SHA-256 is {actual}, not the {declared} declared"),
        )),
        _ => Ok(()),
    }
}

/// Removes uploads (and their parts) untouched for longer than the service's upload expiry;
/// returns how many.
pub async fn sweep_idle(state: &AppState, now: i64) -> Result<usize, crate::store::StoreError> {
    let expiry = i64::try_from(state.config.upload_expiry.as_millis()).unwrap_or(i64::MAX);
    let mut removed = 0;
    for id in state
        .store
        .uploads_idle_before(now.saturating_sub(expiry))
        .await?
    {
        if state.store.delete_upload(&id).await? {
            discard_parts(state, &id).await;
            removed += 1;
        }
    }
    Ok(removed)
}

/// When an upload last touched at `updated_at` expires (unix ms).
pub fn expires_at(state: &AppState, updated_at: i64) -> i64 {
    let expiry = i64::try_from(state.config.upload_expiry.as_millis()).unwrap_or(i64::MAX);
    updated_at.saturating_add(expiry)
}

#[cfg(test)]
mod tests {
    use super::*;
    use axum::http::HeaderValue;

    fn upload(size: u64, part_size: u64) -> UploadRecord {
        UploadRecord {
            id: "upl_x".into(),
            account: None,
            size,
            part_size,
            sha256: None,
            state: crate::store::UploadState::Open,
            parts: Vec::new(),
            created_at: 0,
            updated_at: 0,
        }
    }

    #[test]
    fn parts_cover_the_archive_exactly() {
        let u = upload(10, 4);
        assert_eq!(part_count(10, 4), 3);
        assert_eq!(
            (0..4).map(|i| part_length(&u, i)).collect::<Vec<_>>(),
            [Some(4), Some(4), Some(2), None]
        );
        assert_eq!(part_count(8, 4), 2);
        assert_eq!(part_length(&upload(8, 4), 2), None);
        assert_eq!(part_length(&u, u32::MAX), None);
    }

    #[test]
    fn content_digest_reads_the_sha256_member() {
        let digest: [u8; 32] = Sha256::digest(b"part").into();
        let encoded = base64::engine::general_purpose::STANDARD.encode(digest);
        let mut headers = HeaderMap::new();
        headers.insert(
            "content-digest",
            HeaderValue::from_str(&format!("sha-512=:AAAA:, sha-256=:{encoded}:")).unwrap(),
        );
        assert_eq!(content_digest(&headers).unwrap(), digest);
        for bad in ["sha-256=abc", "sha-256=:AAAA:", "md5=:AAAA:", "sha-256=::"] {
            headers.insert("content-digest", HeaderValue::from_static(bad));
            assert_eq!(content_digest(&headers).unwrap_err().code, "invalid_digest");
        }
        headers.remove("content-digest");
        assert_eq!(
            content_digest(&headers).unwrap_err().code,
            "digest_required"
        );
    }

    #[test]
    fn hex_digests() {
        assert_eq!(hex(&[0, 15, 255]), "000fff");
        assert!(is_sha256_hex(&"aB".repeat(32)));
        assert!(!is_sha256_hex(&"g0".repeat(32)));
        assert!(!is_sha256_hex("00"));
    }
}
