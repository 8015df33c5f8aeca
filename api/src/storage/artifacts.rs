//! Storage of the files a job produces. [`ArtifactStore`] is the seam: [`FsArtifacts`] keeps them
//! on the local filesystem under `DATA_DIR/artifacts/JOB_ID/`, [`BucketArtifacts`] in the object
//! store of a scaled-out deployment under `artifacts/JOB_ID/` ([`crate::storage::bucket`]).
//! Artifact names are relative paths of `/`-separated segments made of `[A-Za-z0-9._-]` that do not
//! start with a dot, so a name can never leave its job's folder.

use std::io::{Seek, SeekFrom};
use std::path::{Path, PathBuf};
use std::pin::Pin;
use std::time::SystemTime;

use serde::Serialize;
use thiserror::Error;
use tokio::io::{AsyncRead, AsyncReadExt};

use crate::storage::bucket::{Bucket, BucketError};
use crate::storage::local_files::walk_files;

/// Failures of artifact storage.
#[derive(Debug, Error)]
pub enum ArtifactError {
    #[error("artifact I/O on `{path}`: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("`{0}` is not a valid artifact name")]
    BadName(String),
    #[error(transparent)]
    Bucket(#[from] BucketError),
}

fn io_err(path: &Path) -> impl FnOnce(std::io::Error) -> ArtifactError + '_ {
    move |source| ArtifactError::Io {
        path: path.to_owned(),
        source,
    }
}

/// One stored file of a job.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, utoipa::ToSchema)]
#[schema(as = Artifact)]
pub struct ArtifactInfo {
    /// Its path among the job's artifacts, e.g. `renders/s0/000.png`.
    pub name: String,
    /// Bytes.
    pub size: u64,
    /// The content type a download answers with.
    pub content_type: &'static str,
}

/// An artifact as a download sees it: its listing, and what validates a cached copy.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ArtifactStat {
    pub info: ArtifactInfo,
    /// When it was stored.
    pub modified: SystemTime,
    /// A strong entity tag, quoted (`"…"`): a new file under the same name gets another.
    pub etag: String,
}

impl ArtifactStat {
    /// The tag of a file of `size` bytes stored at `modified`, for stores without their own.
    fn tag_of(size: u64, modified: SystemTime) -> String {
        let nanos = modified
            .duration_since(SystemTime::UNIX_EPOCH)
            .map_or(0, |d| d.as_nanos());
        format!("\"{size:x}-{nanos:x}\"")
    }
}

/// A byte stream of (part of) an artifact.
pub type ArtifactReader = Pin<Box<dyn AsyncRead + Send>>;

/// Where job products live.
#[async_trait::async_trait]
pub trait ArtifactStore: Send + Sync + 'static {
    /// Moves every file under `staging` (recursively) into the job's artifacts, replacing any
    /// earlier ones; returns what is stored now.
    async fn publish(
        &self,
        job_id: &str,
        staging: &Path,
    ) -> Result<Vec<ArtifactInfo>, ArtifactError>;
    /// The job's artifacts, sorted by name (empty if it has none).
    async fn list(&self, job_id: &str) -> Result<Vec<ArtifactInfo>, ArtifactError>;
    /// One artifact's description and validators, `None` if absent.
    async fn stat(&self, job_id: &str, name: &str) -> Result<Option<ArtifactStat>, ArtifactError>;
    /// `len` bytes of the artifact from byte `start` (the caller checked the range against `stat`).
    async fn open_range(
        &self,
        job_id: &str,
        name: &str,
        start: u64,
        len: u64,
    ) -> Result<ArtifactReader, ArtifactError>;
    /// Removes the job's artifacts.
    async fn delete(&self, job_id: &str) -> Result<(), ArtifactError>;
    /// A URL from which a client may GET the artifact itself for `expires` (a presigned bucket
    /// URL), `None` where the store cannot give one.
    async fn download_url(
        &self,
        _job_id: &str,
        _info: &ArtifactInfo,
        _expires: std::time::Duration,
    ) -> Result<Option<String>, ArtifactError> {
        Ok(None)
    }
}

/// The job's folder name, checked like an artifact name without `/`.
fn job_folder(job_id: &str) -> Result<&str, ArtifactError> {
    if !valid_name(job_id) || job_id.contains('/') {
        return Err(ArtifactError::BadName(job_id.to_owned()));
    }
    Ok(job_id)
}

/// Content type of an artifact by extension.
pub fn content_type(name: &str) -> &'static str {
    let ext = name.rsplit_once('.').map(|(_, e)| e.to_ascii_lowercase());
    match ext.as_deref() {
        Some("json") => "application/json",
        Some("png") => "image/png",
        Some("jpg" | "jpeg") => "image/jpeg",
        Some("exr") => "image/x-exr",
        Some("hdr") => "image/vnd.radiance",
        Some("ply") => "application/x-ply",
        Some("glb") => "model/gltf-binary",
        Some("txt" | "log") => "text/plain; charset=utf-8",
        Some("csv") => "text/csv",
        _ => "application/octet-stream",
    }
}

/// True when `name` is a safe relative artifact path.
pub fn valid_name(name: &str) -> bool {
    !name.is_empty()
        && name.len() <= 255
        && name.split('/').all(|segment| {
            !segment.is_empty()
                && !segment.starts_with('.')
                && segment
                    .bytes()
                    .all(|b| b.is_ascii_alphanumeric() || matches!(b, b'.' | b'_' | b'-'))
        })
}

/// Artifacts as files under one root folder.
pub struct FsArtifacts {
    root: PathBuf,
}

impl FsArtifacts {
    pub fn new(root: PathBuf) -> Result<Self, ArtifactError> {
        std::fs::create_dir_all(&root).map_err(io_err(&root))?;
        Ok(FsArtifacts { root })
    }

    fn job_dir(&self, job_id: &str) -> Result<PathBuf, ArtifactError> {
        Ok(self.root.join(job_folder(job_id)?))
    }

    fn path(&self, job_id: &str, name: &str) -> Result<PathBuf, ArtifactError> {
        if !valid_name(name) {
            return Err(ArtifactError::BadName(name.to_owned()));
        }
        Ok(self.job_dir(job_id)?.join(name))
    }
}

// The file operations below are metadata changes and small reads, done in place; the bytes of a
// download are streamed by tokio's file reader.
#[async_trait::async_trait]
impl ArtifactStore for FsArtifacts {
    async fn publish(
        &self,
        job_id: &str,
        staging: &Path,
    ) -> Result<Vec<ArtifactInfo>, ArtifactError> {
        let dir = self.job_dir(job_id)?;
        let mut files = Vec::new();
        walk_files(staging, "", &mut files).map_err(io_err(staging))?;
        if dir.exists() {
            std::fs::remove_dir_all(&dir).map_err(io_err(&dir))?;
        }
        for (name, source) in files {
            if !valid_name(&name) {
                tracing::warn!(
                    job_id,
                    name,
                    "skipping an exported file with an unsafe name"
                );
                continue;
            }
            let target = dir.join(&name);
            if let Some(parent) = target.parent() {
                std::fs::create_dir_all(parent).map_err(io_err(parent))?;
            }
            std::fs::rename(&source, &target).map_err(io_err(&target))?;
        }
        self.list(job_id).await
    }

    async fn list(&self, job_id: &str) -> Result<Vec<ArtifactInfo>, ArtifactError> {
        let dir = self.job_dir(job_id)?;
        if !dir.is_dir() {
            return Ok(Vec::new());
        }
        let mut files = Vec::new();
        walk_files(&dir, "", &mut files).map_err(io_err(&dir))?;
        let mut infos = Vec::with_capacity(files.len());
        for (name, path) in files {
            let size = std::fs::metadata(&path).map_err(io_err(&path))?.len();
            infos.push(ArtifactInfo {
                content_type: content_type(&name),
                name,
                size,
            });
        }
        infos.sort_by(|a, b| a.name.cmp(&b.name));
        Ok(infos)
    }

    async fn stat(&self, job_id: &str, name: &str) -> Result<Option<ArtifactStat>, ArtifactError> {
        let path = match self.path(job_id, name) {
            Ok(path) => path,
            Err(ArtifactError::BadName(_)) => return Ok(None),
            Err(e) => return Err(e),
        };
        match std::fs::metadata(&path) {
            Ok(meta) if meta.is_file() => {
                let modified = meta.modified().unwrap_or(SystemTime::UNIX_EPOCH);
                Ok(Some(ArtifactStat {
                    info: ArtifactInfo {
                        name: name.to_owned(),
                        size: meta.len(),
                        content_type: content_type(name),
                    },
                    etag: ArtifactStat::tag_of(meta.len(), modified),
                    modified,
                }))
            }
            Ok(_) => Ok(None),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(None),
            Err(e) => Err(io_err(&path)(e)),
        }
    }

    async fn open_range(
        &self,
        job_id: &str,
        name: &str,
        start: u64,
        len: u64,
    ) -> Result<ArtifactReader, ArtifactError> {
        let path = self.path(job_id, name)?;
        let mut file = std::fs::File::open(&path).map_err(io_err(&path))?;
        file.seek(SeekFrom::Start(start)).map_err(io_err(&path))?;
        Ok(Box::pin(tokio::fs::File::from_std(file).take(len)))
    }

    async fn delete(&self, job_id: &str) -> Result<(), ArtifactError> {
        let dir = self.job_dir(job_id)?;
        match std::fs::remove_dir_all(&dir) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(io_err(&dir)(e)),
            _ => Ok(()),
        }
    }
}

/// Artifacts as objects under `artifacts/JOB_ID/` of the deployment's bucket.
pub struct BucketArtifacts {
    bucket: std::sync::Arc<Bucket>,
}

impl BucketArtifacts {
    pub fn new(bucket: std::sync::Arc<Bucket>) -> Self {
        BucketArtifacts { bucket }
    }

    fn folder(job_id: &str) -> Result<String, ArtifactError> {
        Ok(crate::storage::object_keys::artifacts(job_folder(job_id)?))
    }

    /// The object of one artifact.
    fn object(job_id: &str, name: &str) -> Result<String, ArtifactError> {
        Ok(format!("{}/{name}", Self::folder(job_id)?))
    }
}

#[async_trait::async_trait]
impl ArtifactStore for BucketArtifacts {
    async fn publish(
        &self,
        job_id: &str,
        staging: &Path,
    ) -> Result<Vec<ArtifactInfo>, ArtifactError> {
        let folder = Self::folder(job_id)?;
        let mut files = Vec::new();
        walk_files(staging, "", &mut files).map_err(io_err(staging))?;
        for (name, path) in files.iter().filter(|(name, _)| !valid_name(name)) {
            tracing::warn!(
                job_id,
                name,
                "skipping an exported file with an unsafe name"
            );
            std::fs::remove_file(path).map_err(io_err(path))?;
        }
        self.bucket.delete_folder(&folder).await?;
        self.bucket
            .upload_dir_typed(&folder, staging, content_type)
            .await?;
        self.list(job_id).await
    }

    async fn download_url(
        &self,
        job_id: &str,
        info: &ArtifactInfo,
        expires: std::time::Duration,
    ) -> Result<Option<String>, ArtifactError> {
        let path = Self::object(job_id, &info.name)?;
        let file_name = info.name.rsplit('/').next().unwrap_or(&info.name);
        Ok(self
            .bucket
            .presigned_get(&path, expires, info.content_type, file_name)
            .await?)
    }

    async fn list(&self, job_id: &str) -> Result<Vec<ArtifactInfo>, ArtifactError> {
        let files = self.bucket.list(&Self::folder(job_id)?).await?;
        Ok(files
            .into_iter()
            .filter(|f| valid_name(&f.name))
            .map(|f| ArtifactInfo {
                content_type: content_type(&f.name),
                name: f.name,
                size: f.size,
            })
            .collect())
    }

    async fn stat(&self, job_id: &str, name: &str) -> Result<Option<ArtifactStat>, ArtifactError> {
        if !valid_name(name) {
            return Ok(None);
        }
        let key = Self::object(job_id, name)?;
        Ok(self.bucket.head(&key).await?.map(|meta| {
            let modified = SystemTime::from(meta.last_modified);
            ArtifactStat {
                etag: match meta.e_tag {
                    // The store's tag, quoted as HTTP wants it (S3's already are).
                    Some(tag) if tag.starts_with('"') => tag,
                    Some(tag) => format!("\"{tag}\""),
                    None => ArtifactStat::tag_of(meta.size, modified),
                },
                info: ArtifactInfo {
                    name: name.to_owned(),
                    size: meta.size,
                    content_type: content_type(name),
                },
                modified,
            }
        }))
    }

    async fn open_range(
        &self,
        job_id: &str,
        name: &str,
        start: u64,
        len: u64,
    ) -> Result<ArtifactReader, ArtifactError> {
        if !valid_name(name) {
            return Err(ArtifactError::BadName(name.to_owned()));
        }
        let key = Self::object(job_id, name)?;
        if len == 0 {
            return Ok(Box::pin(tokio::io::empty()));
        }
        let stream = self.bucket.read_range(&key, start, len).await?;
        Ok(Box::pin(tokio_util::io::StreamReader::new(stream)))
    }

    async fn delete(&self, job_id: &str) -> Result<(), ArtifactError> {
        Ok(self.bucket.delete_folder(&Self::folder(job_id)?).await?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_cannot_escape_or_hide() {
        for good in ["mesh.ply", "renders/test_000.png", "a-b_c.d"] {
            assert!(valid_name(good), "{good}");
        }
        for bad in [
            "",
            "../x",
            "a/../b",
            "/etc/passwd",
            ".env",
            "a//b",
            "a\\b",
            "r/.x",
            "a b",
        ] {
            assert!(!valid_name(bad), "{bad}");
        }
    }

    /// What every artifact store must do: publish nested files (replacing earlier ones), list,
    /// stat and read byte ranges, refuse names that leave the job, delete.
    async fn exercise(store: &dyn ArtifactStore, scratch: &Path) {
        let staging = scratch.join("staging");
        std::fs::create_dir_all(staging.join("renders")).unwrap();
        std::fs::write(staging.join("old.txt"), b"old").unwrap();
        store.publish("job_1", &staging).await.unwrap();
        std::fs::remove_dir_all(&staging).unwrap();
        std::fs::create_dir_all(staging.join("renders")).unwrap();
        std::fs::write(staging.join("metrics.json"), b"{\"psnr\": 30}").unwrap();
        std::fs::write(staging.join("renders/test_000.png"), b"0123456789").unwrap();
        std::fs::write(staging.join(".hidden"), b"x").unwrap();
        let listed = store.publish("job_1", &staging).await.unwrap();
        let names: Vec<_> = listed.iter().map(|a| (a.name.as_str(), a.size)).collect();
        assert_eq!(names, [("metrics.json", 12), ("renders/test_000.png", 10)]);
        assert_eq!(listed[1].content_type, "image/png");
        let mut part = Vec::new();
        store
            .open_range("job_1", "renders/test_000.png", 3, 4)
            .await
            .unwrap()
            .read_to_end(&mut part)
            .await
            .unwrap();
        assert_eq!(part, b"3456");
        let stat = store.stat("job_1", "metrics.json").await.unwrap().unwrap();
        assert_eq!(
            (stat.info.size, stat.info.content_type),
            (12, "application/json")
        );
        assert!(
            stat.etag.len() > 2 && stat.etag.starts_with('"') && stat.etag.ends_with('"'),
            "{}",
            stat.etag
        );
        let again = store.stat("job_1", "metrics.json").await.unwrap().unwrap();
        assert_eq!(again.etag, stat.etag, "a stored file keeps its tag");
        assert!(store.stat("job_1", "nope.json").await.unwrap().is_none());
        assert!(store
            .stat("job_1", "../job_1/metrics.json")
            .await
            .unwrap()
            .is_none());
        assert!(store.list("job_2").await.unwrap().is_empty());
        assert!(matches!(
            store.list("../job_1").await,
            Err(ArtifactError::BadName(_))
        ));
        store.delete("job_1").await.unwrap();
        assert!(store.list("job_1").await.unwrap().is_empty());
        store.delete("job_1").await.unwrap();
    }

    #[tokio::test]
    async fn filesystem_artifacts_pass_the_suite_and_move_files() {
        let dir = tempfile::tempdir().unwrap();
        let store = FsArtifacts::new(dir.path().join("artifacts")).unwrap();
        exercise(&store, dir.path()).await;
        assert!(
            !dir.path().join("staging/metrics.json").exists(),
            "moved, not copied"
        );
    }

    #[tokio::test]
    async fn bucket_artifacts_pass_the_suite() {
        let dir = tempfile::tempdir().unwrap();
        let url = format!("file://{}", dir.path().join("bucket").display());
        let bucket = std::sync::Arc::new(Bucket::open(&url, &[]).unwrap());
        exercise(&BucketArtifacts::new(bucket), dir.path()).await;
    }
}
