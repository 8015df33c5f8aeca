//! Resumable uploads: a capture archive sent in parts, in any order, over as many requests (and
//! broken connections) as it takes.
//!
//! An upload declares the archive's size and a part size, which fix every part's length. Each part
//! arrives with its SHA-256 (`Content-Digest: sha-256=:…:`, RFC 9530) and is kept only when its
//! length and digest match. Every request stores its copy of a part under a key of its own (the
//! part's number and digest, and an id of the request's: [`UploadPart::copy`]), so no request
//! overwrites or removes a copy another stored: a part sent again while a commit reads the
//! first copy, and refused, removes only its own. A commit reads the copies its snapshot of the
//! upload's record names; a copy that cannot be read back (gone, or changed) is answered with
//! 409 `part_unreadable` naming the part, whose record is dropped so that it is sent again.
//! Parts live in the object store when the deployment has one (any replica may receive any
//! part), else under `uploads/` in the data dir. A commit joins the parts in order into one
//! file, checking each part's digest again and the whole archive's when one was declared, and
//! hands it to the validation a one-shot upload gets. An upload idle for longer than
//! `--upload-expiry-hours` takes nothing more (410 `upload_expired`) and is removed with its
//! parts by the next sweep ([`crate::jobs::purge::sweep_idle`]). Where the parts are kept is
//! [`crate::storage::upload_parts`]; the routes are [`crate::http::routes::uploads`].

use std::path::{Path, PathBuf};

use axum::body::Body;
use axum::http::{HeaderMap, StatusCode};
use base64::Engine as _;
use futures_util::StreamExt;
use sha2::{Digest as _, Sha256};
use tokio::io::AsyncWriteExt;

use crate::http::error::ApiError;
use crate::jobs::state::AppState;
use crate::storage::store::{UploadPart, UploadRecord};
use crate::storage::upload_parts::{part_key, PartStorage, PartStorageError};

/// Points where a test holds a request to force an interleaving ([`pause::at`]): a part received
/// but not yet stored, a part stored but not yet recorded, and a commit that took its upload but
/// has read no part yet. Only
/// `cfg(test)` builds hold anywhere; elsewhere [`pause::at`] returns at once.
pub(crate) mod pause {
    /// A part's bytes are received and checked, not yet moved under its key.
    pub const PART_RECEIVED: &str = "part received";
    /// A part's bytes are stored under its key; the store has not recorded it yet.
    pub const PART_STORED: &str = "part stored";
    /// A commit holds the upload (`committing`); it has read none of its parts yet.
    pub const COMMIT_TAKEN: &str = "commit taken";

    #[cfg(test)]
    pub use armed::{arm, at, Pause};

    /// Returns at once: outside tests nothing is ever held.
    #[cfg(not(test))]
    pub async fn at(_upload_id: &str, _point: &'static str) {}

    #[cfg(test)]
    mod armed {
        use std::sync::{Arc, Mutex};

        use tokio::sync::Notify;

        /// One armed point: `reached` is notified when a request gets there, which then waits
        /// for `release`.
        #[derive(Default)]
        pub struct Pause {
            pub reached: Notify,
            pub release: Notify,
        }

        type Armed = Vec<(String, &'static str, Arc<Pause>)>;
        static ARMED: Mutex<Armed> = Mutex::new(Vec::new());

        /// Holds the next request about `upload_id` that reaches `point`.
        pub fn arm(upload_id: &str, point: &'static str) -> Arc<Pause> {
            let pause = Arc::new(Pause::default());
            ARMED
                .lock()
                .unwrap()
                .push((upload_id.to_owned(), point, pause.clone()));
            pause
        }

        /// Waits here when this point is armed for `upload_id` (once: it disarms itself).
        pub async fn at(upload_id: &str, point: &'static str) {
            let armed = {
                let mut armed = ARMED.lock().unwrap();
                armed
                    .iter()
                    .position(|(id, p, _)| id == upload_id && *p == point)
                    .map(|i| armed.remove(i).2)
            };
            if let Some(pause) = armed {
                pause.reached.notify_one();
                pause.release.notified().await;
            }
        }
    }
}

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
/// Returns the part to record, stored under a key no other request writes; nothing is left
/// behind when it is refused or the body breaks off.
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
        crate::domain::ids::new_id("part")
    )));
    let mut hasher = Sha256::new();
    let received = crate::http::bodies::stream_to_file_with(
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
        copy: Some(crate::domain::ids::new_id("copy")),
    };
    pause::at(&upload.id, pause::PART_RECEIVED).await;
    parts(state)
        .store(&upload.id, &part, &temp.0)
        .await
        .map_err(|e| match e {
            PartStorageError::Bucket(e) => e.into(),
            PartStorageError::Io(e) => ApiError::internal("storing a part", e),
        })?;
    Ok(part)
}

/// Where this service keeps parts.
fn parts(state: &AppState) -> PartStorage<'_> {
    PartStorage {
        bucket: state.bucket.as_deref(),
        data_dir: &state.paths.root,
    }
}

/// Removes one stored copy of a part: one that a part sent again replaced, or the copy of a
/// request that was refused after storing it (each request removes only its own copy).
pub async fn discard_part(state: &AppState, upload_id: &str, part: &UploadPart) {
    parts(state).discard(upload_id, part).await;
}

/// Removes every stored part of an upload, and its folder.
pub async fn discard_parts(state: &AppState, upload_id: &str) {
    parts(state).discard_all(upload_id).await;
}

/// Why a commit could not join an upload's parts.
#[derive(Debug)]
pub enum AssembleError {
    /// The stored copy of this part could not be read back, or no longer matches its digest:
    /// the client sends the part again.
    PartUnreadable { index: u32 },
    /// Anything else: the whole archive's digest (the client's), or writing the joined file.
    Refused(ApiError),
}

impl From<ApiError> for AssembleError {
    fn from(e: ApiError) -> Self {
        AssembleError::Refused(e)
    }
}

/// The answer to a commit that could not read part `index` back.
pub fn part_unreadable(upload_id: &str, index: u32) -> ApiError {
    ApiError::conflict(
        "part_unreadable",
        format!(
            "part {index} of upload `{upload_id}` could not be read back from storage; it is \
             no longer listed as received: send part {index} again, then commit"
        ),
    )
}

/// Joins an upload's parts, in order, into `target`: each part's bytes are checked against the
/// digest recorded for it, and the whole archive's against the upload's declared SHA-256.
/// A whole-archive mismatch is the client's (422 `digest_mismatch`); a part whose stored copy
/// is gone or no longer matches its record is [`AssembleError::PartUnreadable`].
pub async fn assemble(
    state: &AppState,
    upload: &UploadRecord,
    target: &Path,
) -> Result<(), AssembleError> {
    let mut file = tokio::fs::File::create(target)
        .await
        .map_err(|e| ApiError::internal("joining the parts", e))?;
    let mut whole = Sha256::new();
    for part in &upload.parts {
        let key = part_key(&upload.id, part);
        let unreadable = |e: &dyn std::fmt::Display| {
            tracing::warn!(upload_id = %upload.id, key, error = %e, "a stored part cannot be read");
            AssembleError::PartUnreadable { index: part.index }
        };
        let mut part_digest = Sha256::new();
        let mut stream = match parts(state).read(&upload.id, part).await {
            Ok(stream) => stream,
            Err(e) => return Err(unreadable(&e)),
        };
        while let Some(chunk) = stream.next().await {
            let chunk = chunk.map_err(|e| unreadable(&e))?;
            part_digest.update(&chunk);
            whole.update(&chunk);
            file.write_all(&chunk)
                .await
                .map_err(|e| ApiError::internal("joining the parts", e))?;
        }
        if hex(&part_digest.finalize()) != part.sha256 {
            return Err(unreadable(&"its bytes no longer match its digest"));
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
    .map_err(AssembleError::Refused)
}

/// When an upload last touched at `updated_at` expires (unix ms).
pub fn expires_at(state: &AppState, updated_at: i64) -> i64 {
    let expiry = i64::try_from(state.config.upload_expiry.as_millis()).unwrap_or(i64::MAX);
    updated_at.saturating_add(expiry)
}

/// 410 `upload_expired` for an upload past its expiry at `now`, which takes no more parts and
/// no commit (the next sweep removes it).
pub fn refuse_expired(state: &AppState, upload: &UploadRecord, now: i64) -> Result<(), ApiError> {
    let expired = expires_at(state, upload.updated_at);
    if now >= expired {
        return Err(ApiError::new(
            StatusCode::GONE,
            "upload_expired",
            format!(
                "upload `{}` expired at {} (idle past --upload-expiry-hours); start a new one",
                upload.id,
                crate::storage::store::rfc3339(expired)
            ),
        ));
    }
    Ok(())
}

/// A part number as the path gives it: decimal digits without a sign or leading zeros (`0`,
/// `17`), so one part has one name.
pub fn part_number(text: &str) -> Option<u32> {
    let canonical = !text.is_empty()
        && text.bytes().all(|b| b.is_ascii_digit())
        && (text == "0" || !text.starts_with('0'));
    canonical.then(|| text.parse().ok()).flatten()
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
            state: crate::storage::store::UploadState::Open,
            parts: Vec::new(),
            created_at: 0,
            updated_at: 0,
        }
    }

    #[test]
    fn part_numbers_are_canonical_decimals() {
        assert_eq!(part_number("0"), Some(0));
        assert_eq!(part_number("17"), Some(17));
        assert_eq!(part_number("4294967295"), Some(u32::MAX));
        for bad in [
            "",
            "+1",
            "01",
            "00",
            "-0",
            " 1",
            "1 ",
            "1.0",
            "0x1",
            "4294967296",
            "１",
        ] {
            assert_eq!(part_number(bad), None, "{bad:?}");
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
