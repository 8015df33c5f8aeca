//! Where the parts of resumable uploads are kept: in the deployment's object store when it has
//! one (any replica may receive any part), else under `uploads/` in the data dir. Every request
//! stores its copy of a part under a key of its own ([`part_key`]: the part's number and digest,
//! and an id of the request's), so no request overwrites or removes a copy another stored. The
//! sessions themselves (digests, assembly, expiry) are [`crate::http::upload_sessions`].

use std::path::Path;
use std::pin::Pin;

use thiserror::Error;

use crate::storage::bucket::{Bucket, BucketError};
use crate::storage::store::UploadPart;

/// The bytes of one stored part, as they are read back.
pub type PartStream =
    Pin<Box<dyn futures_util::Stream<Item = std::io::Result<bytes::Bytes>> + Send>>;

/// Why a part could not be stored.
#[derive(Debug, Error)]
pub enum PartStorageError {
    #[error(transparent)]
    Bucket(#[from] BucketError),
    #[error(transparent)]
    Io(#[from] std::io::Error),
}

/// Where a part's copy is kept, relative to the object store's root or the data dir.
pub fn part_key(upload_id: &str, part: &UploadPart) -> String {
    let key = crate::storage::object_keys::upload_part(upload_id, part.index, &part.sha256);
    match &part.copy {
        Some(copy) => format!("{key}.{copy}"),
        None => key,
    }
}

/// The place parts are kept: the object store when there is one, else `data_dir`.
#[derive(Clone, Copy)]
pub struct PartStorage<'a> {
    pub bucket: Option<&'a Bucket>,
    pub data_dir: &'a Path,
}

impl PartStorage<'_> {
    /// Moves the received `file` under `part`'s key.
    pub async fn store(
        &self,
        upload_id: &str,
        part: &UploadPart,
        file: &Path,
    ) -> Result<(), PartStorageError> {
        let key = part_key(upload_id, part);
        match self.bucket {
            Some(bucket) => bucket.upload_file(&key, file).await?,
            None => {
                let target = self.data_dir.join(&key);
                if let Some(folder) = target.parent() {
                    tokio::fs::create_dir_all(folder).await?;
                }
                tokio::fs::rename(file, &target).await?;
            }
        }
        Ok(())
    }

    /// The stored bytes of `part` (its first `part.size`), or why they cannot be read.
    pub async fn read(&self, upload_id: &str, part: &UploadPart) -> Result<PartStream, String> {
        let key = part_key(upload_id, part);
        match self.bucket {
            Some(bucket) => match bucket.read_range(&key, 0, part.size).await {
                Ok(stream) => Ok(Box::pin(stream)),
                Err(e) => Err(e.to_string()),
            },
            None => match tokio::fs::File::open(self.data_dir.join(&key)).await {
                Ok(local) => Ok(Box::pin(tokio_util::io::ReaderStream::new(local))),
                Err(e) => Err(e.to_string()),
            },
        }
    }

    /// Removes one stored copy of a part: one that a part sent again replaced, or the copy of a
    /// request that was refused after storing it (each request removes only its own copy).
    pub async fn discard(&self, upload_id: &str, part: &UploadPart) {
        let key = part_key(upload_id, part);
        let result = match self.bucket {
            Some(bucket) => bucket.delete(&key).await.map_err(|e| e.to_string()),
            None => match tokio::fs::remove_file(self.data_dir.join(&key)).await {
                Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(e.to_string()),
                _ => Ok(()),
            },
        };
        if let Err(e) = result {
            tracing::warn!(upload_id, key, error = %e, "removing a replaced part failed");
        }
    }

    /// Removes every stored part of an upload, and its folder.
    pub async fn discard_all(&self, upload_id: &str) {
        let folder = crate::storage::object_keys::upload(upload_id);
        if let Some(bucket) = self.bucket {
            if let Err(e) = bucket.delete_folder(&folder).await {
                tracing::warn!(upload_id, error = %e, "removing an upload's parts failed");
            }
        }
        match tokio::fs::remove_dir_all(self.data_dir.join(&folder)).await {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
                tracing::warn!(upload_id, error = %e, "removing an upload's parts failed");
            }
            _ => {}
        }
    }
}
