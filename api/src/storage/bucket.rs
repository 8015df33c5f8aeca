//! The files every process of a scaled-out deployment must see — uploaded captures, relight
//! inputs, checkpoints (a job's model folder) and artifacts — kept in an object store named by
//! `--artifact-url`: `s3://bucket[/prefix]` (any S3-compatible server, configured from the usual
//! AWS variables) or `file:///shared/folder`. The `object_store` crate speaks the protocols.
//!
//! Each process keeps a local working copy under its own data dir: the API uploads what it
//! accepts, a worker downloads a job's capture (and, when it resumes a job, the latest
//! checkpoint) before running it and uploads every checkpoint it writes, so a worker on another
//! machine can take the job over. Keys mirror the data dir, under the URL's prefix; every one is
//! spelled in [`crate::storage::object_keys`].

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Duration;

use futures_util::{StreamExt, TryStreamExt};
use object_store::aws::AmazonS3Builder;
use object_store::local::LocalFileSystem;
use object_store::path::Path as Key;
use object_store::signer::{Method, SignedUrlOptions, Signer};
use object_store::{
    Attribute, GetOptions, GetRange, ObjectStore, ObjectStoreExt, PutOptions, PutPayload,
};
use thiserror::Error;

/// Files moved at once by [`Bucket::upload_dir`] and [`Bucket::download_dir`].
const CONCURRENT_TRANSFERS: usize = 8;

/// Failures of the object store.
#[derive(Debug, Error)]
pub enum BucketError {
    #[error("invalid artifact URL `{url}`: {reason}")]
    InvalidUrl { url: String, reason: String },
    /// The store could not be reached or refused the request: it may succeed later, and nothing
    /// stored was changed by it.
    #[error("the object store is unavailable: {0}")]
    Unavailable(String),
    #[error("`{0}` is not a valid object key")]
    BadKey(String),
    #[error("local file `{path}`: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
}

impl From<object_store::Error> for BucketError {
    fn from(e: object_store::Error) -> Self {
        BucketError::Unavailable(e.to_string())
    }
}

fn io_err(path: &Path) -> impl FnOnce(std::io::Error) -> BucketError + '_ {
    move |source| BucketError::Io {
        path: path.to_owned(),
        source,
    }
}

/// One stored object below a folder key.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StoredFile {
    /// `/`-separated path relative to the folder.
    pub name: String,
    pub size: u64,
}

/// An object store with the service's prefix.
pub struct Bucket {
    store: Arc<dyn ObjectStore>,
    /// The same store where it can sign URLs (S3), for presigned downloads.
    signer: Option<Arc<dyn Signer>>,
    prefix: Key,
}

impl std::fmt::Debug for Bucket {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Bucket({}, prefix `{}`)", self.store, self.prefix)
    }
}

impl Bucket {
    /// Opens `s3://bucket[/prefix]` or `file:///folder[/prefix]`. S3 settings come from the AWS
    /// variables (`AWS_ENDPOINT_URL`, `AWS_ACCESS_KEY_ID`, `AWS_SECRET_ACCESS_KEY`, `AWS_REGION`,
    /// `AWS_ALLOW_HTTP` for a plain-http endpoint, …), then from `options` (the same keys in
    /// snake case, e.g. `("aws_endpoint", "http://127.0.0.1:9000")`), which win.
    pub fn open(url: &str, options: &[(String, String)]) -> Result<Bucket, BucketError> {
        let invalid = |reason: &str| BucketError::InvalidUrl {
            url: url.to_owned(),
            reason: reason.to_owned(),
        };
        if let Some(rest) = url.strip_prefix("s3://") {
            let (bucket, prefix) = rest.split_once('/').unwrap_or((rest, ""));
            if bucket.is_empty() {
                return Err(invalid("no bucket name"));
            }
            let mut builder = AmazonS3Builder::from_env().with_bucket_name(bucket);
            for (key, value) in options {
                let key = key
                    .parse()
                    .map_err(|e| invalid(&format!("option `{key}`: {e}")))?;
                builder = builder.with_config(key, value);
            }
            let store = Arc::new(builder.build().map_err(|e| invalid(&e.to_string()))?);
            Ok(Bucket {
                store: store.clone(),
                signer: Some(store),
                prefix: parse_key(prefix)?,
            })
        } else if let Some(folder) = url.strip_prefix("file://") {
            if !folder.starts_with('/') {
                return Err(invalid("a file URL needs an absolute path (file:///…)"));
            }
            std::fs::create_dir_all(folder).map_err(io_err(Path::new(folder)))?;
            let store =
                LocalFileSystem::new_with_prefix(folder).map_err(|e| invalid(&e.to_string()))?;
            Ok(Bucket {
                store: Arc::new(store.with_automatic_cleanup(true)),
                signer: None,
                prefix: Key::default(),
            })
        } else {
            Err(invalid("expected s3://bucket[/prefix] or file:///folder"))
        }
    }

    /// The key of `relative` (a `/`-separated path) under the prefix.
    fn key(&self, relative: &str) -> Result<Key, BucketError> {
        let relative = parse_key(relative)?;
        Ok(self.prefix.parts().chain(relative.parts()).collect())
    }

    /// Every object below `folder`, sorted by name.
    pub async fn list(&self, folder: &str) -> Result<Vec<StoredFile>, BucketError> {
        let root = self.key(folder)?;
        let mut files: Vec<StoredFile> = self
            .store
            .list(Some(&root))
            .map_ok(|meta| {
                let name = meta
                    .location
                    .prefix_match(&root)
                    .map(|parts| parts.map(|p| p.as_ref().to_owned()).collect::<Vec<_>>())
                    .unwrap_or_default()
                    .join("/");
                StoredFile {
                    name,
                    size: meta.size,
                }
            })
            .try_collect()
            .await?;
        files.retain(|f| !f.name.is_empty());
        files.sort_by(|a, b| a.name.cmp(&b.name));
        Ok(files)
    }

    /// The size of one object, `None` where there is none.
    pub async fn size(&self, path: &str) -> Result<Option<u64>, BucketError> {
        Ok(self.head(path).await?.map(|meta| meta.size))
    }

    /// One object's size, modification time and entity tag, `None` where there is none.
    pub async fn head(&self, path: &str) -> Result<Option<object_store::ObjectMeta>, BucketError> {
        match self.store.head(&self.key(path)?).await {
            Ok(meta) => Ok(Some(meta)),
            Err(object_store::Error::NotFound { .. }) => Ok(None),
            Err(e) => Err(e.into()),
        }
    }

    /// A URL that lets anyone holding it GET one object for `expires`, its answer carrying
    /// `content_type` and an attachment `file_name`; `None` where the store cannot sign (a
    /// `file://` bucket).
    pub async fn presigned_get(
        &self,
        path: &str,
        expires: Duration,
        content_type: &str,
        file_name: &str,
    ) -> Result<Option<String>, BucketError> {
        let Some(signer) = &self.signer else {
            return Ok(None);
        };
        // S3 answers with these headers in place of the object's own (they are signed too).
        let options = SignedUrlOptions::default().with_query([
            ("response-content-type", content_type.to_owned()),
            (
                "response-content-disposition",
                format!("attachment; filename=\"{file_name}\""),
            ),
        ]);
        let url = signer
            .signed_url_opts(Method::GET, &self.key(path)?, expires, &options)
            .await?;
        Ok(Some(url.to_string()))
    }

    /// `len` bytes of one object from byte `start`, as a stream.
    pub async fn read_range(
        &self,
        path: &str,
        start: u64,
        len: u64,
    ) -> Result<
        impl futures_util::Stream<Item = std::io::Result<bytes::Bytes>> + Send + 'static,
        BucketError,
    > {
        let options = GetOptions {
            range: Some(GetRange::Bounded(start..start + len)),
            ..GetOptions::default()
        };
        let got = self.store.get_opts(&self.key(path)?, options).await?;
        Ok(got.into_stream().map_err(std::io::Error::other))
    }

    /// Uploads every file under `dir` (recursively) to `folder`, replacing objects of the same
    /// name; returns how many. Objects of `folder` that `dir` lacks are left alone.
    pub async fn upload_dir(&self, folder: &str, dir: &Path) -> Result<usize, BucketError> {
        self.upload_files(folder, dir, None).await
    }

    /// [`Bucket::upload_dir`], each object stored with the content type `content_type` gives its
    /// name (which the bucket answers a presigned GET with), where the store keeps one (S3).
    pub async fn upload_dir_typed(
        &self,
        folder: &str,
        dir: &Path,
        content_type: fn(&str) -> &'static str,
    ) -> Result<usize, BucketError> {
        self.upload_files(folder, dir, Some(content_type)).await
    }

    async fn upload_files(
        &self,
        folder: &str,
        dir: &Path,
        content_type: Option<fn(&str) -> &'static str>,
    ) -> Result<usize, BucketError> {
        let dir_owned = dir.to_owned();
        let files = tokio::task::spawn_blocking(move || local_files(&dir_owned))
            .await
            .map_err(|e| BucketError::Io {
                path: dir.to_owned(),
                source: std::io::Error::other(e),
            })??;
        let count = files.len();
        // A local folder keeps no attributes (and refuses them).
        let content_type = content_type.filter(|_| self.signer.is_some());
        futures_util::stream::iter(files)
            .map(|(name, path)| async move {
                let key = self.key(&format!("{folder}/{name}"))?;
                let bytes = tokio::fs::read(&path).await.map_err(io_err(&path))?;
                let mut options = PutOptions::default();
                if let Some(content_type) = content_type {
                    options
                        .attributes
                        .insert(Attribute::ContentType, content_type(&name).into());
                }
                self.store
                    .put_opts(&key, PutPayload::from(bytes), options)
                    .await?;
                Ok::<_, BucketError>(())
            })
            .buffer_unordered(CONCURRENT_TRANSFERS)
            .try_collect::<Vec<()>>()
            .await?;
        Ok(count)
    }

    /// Downloads every object below `folder` into `dir` (created; whatever it held is replaced
    /// only once every file arrived); returns how many. Nothing is written when there are none.
    pub async fn download_dir(&self, folder: &str, dir: &Path) -> Result<usize, BucketError> {
        let files = self.list(folder).await?;
        if files.is_empty() {
            return Ok(0);
        }
        let partial = dir.with_extension("partial");
        if partial.exists() {
            tokio::fs::remove_dir_all(&partial)
                .await
                .map_err(io_err(&partial))?;
        }
        let count = files.len();
        let partial_ref = &partial;
        futures_util::stream::iter(files)
            .map(|file| async move {
                let key = self.key(&format!("{folder}/{}", file.name))?;
                let bytes = self.store.get(&key).await?.bytes().await?;
                let target = partial_ref.join(&file.name);
                if let Some(parent) = target.parent() {
                    tokio::fs::create_dir_all(parent)
                        .await
                        .map_err(io_err(parent))?;
                }
                tokio::fs::write(&target, &bytes)
                    .await
                    .map_err(io_err(&target))?;
                Ok::<_, BucketError>(())
            })
            .buffer_unordered(CONCURRENT_TRANSFERS)
            .try_collect::<Vec<()>>()
            .await?;
        if dir.exists() {
            tokio::fs::remove_dir_all(dir).await.map_err(io_err(dir))?;
        }
        if let Some(parent) = dir.parent() {
            tokio::fs::create_dir_all(parent)
                .await
                .map_err(io_err(parent))?;
        }
        tokio::fs::rename(&partial, dir)
            .await
            .map_err(io_err(dir))?;
        Ok(count)
    }

    /// Stores one file as the object `path`.
    pub async fn upload_file(&self, path: &str, file: &Path) -> Result<(), BucketError> {
        let bytes = tokio::fs::read(file).await.map_err(io_err(file))?;
        self.store
            .put(&self.key(path)?, PutPayload::from(bytes))
            .await?;
        Ok(())
    }

    /// Removes the object `path` (none there is no error).
    pub async fn delete(&self, path: &str) -> Result<(), BucketError> {
        match self.store.delete(&self.key(path)?).await {
            Ok(()) | Err(object_store::Error::NotFound { .. }) => Ok(()),
            Err(e) => Err(e.into()),
        }
    }

    /// Removes every object below `folder`.
    pub async fn delete_folder(&self, folder: &str) -> Result<(), BucketError> {
        let root = self.key(folder)?;
        let locations = self
            .store
            .list(Some(&root))
            .map_ok(|meta| meta.location)
            .boxed();
        self.store
            .delete_stream(locations)
            .try_collect::<Vec<_>>()
            .await?;
        Ok(())
    }
}

/// A `/`-separated relative path as a key (no empty, `.` or `..` segments).
fn parse_key(relative: &str) -> Result<Key, BucketError> {
    let trimmed = relative.trim_matches('/');
    if trimmed.split('/').any(|s| s == "." || s == "..") {
        return Err(BucketError::BadKey(relative.to_owned()));
    }
    Key::parse(trimmed).map_err(|_| BucketError::BadKey(relative.to_owned()))
}

/// Every file under `dir` with its `/`-separated relative name.
fn local_files(dir: &Path) -> Result<Vec<(String, PathBuf)>, BucketError> {
    let mut out = Vec::new();
    crate::storage::local_files::walk_files(dir, "", &mut out).map_err(io_err(dir))?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn urls_are_checked() {
        for bad in [
            "",
            "s3://",
            "ftp://x",
            "file://relative/path",
            "/plain/path",
        ] {
            assert!(
                matches!(Bucket::open(bad, &[]), Err(BucketError::InvalidUrl { .. })),
                "{bad}"
            );
        }
        let unknown_option = [("no_such_option".to_string(), "1".to_string())];
        assert!(matches!(
            Bucket::open("s3://b", &unknown_option),
            Err(BucketError::InvalidUrl { .. })
        ));
    }

    #[test]
    fn keys_cannot_climb_out_of_the_prefix() {
        for bad in ["../x", "a/../b", "a//b", "./a"] {
            assert!(parse_key(bad).is_err(), "{bad}");
        }
        assert_eq!(
            parse_key("jobs/j1/model").unwrap().as_ref(),
            "jobs/j1/model"
        );
    }

    #[tokio::test]
    async fn folders_round_trip_through_a_file_bucket() {
        let dir = tempfile::tempdir().unwrap();
        let url = format!("file://{}", dir.path().join("bucket").display());
        let bucket = Bucket::open(&url, &[]).unwrap();
        let source = dir.path().join("source");
        std::fs::create_dir_all(source.join("images")).unwrap();
        std::fs::write(source.join("transforms.json"), b"{}").unwrap();
        std::fs::write(source.join("images/r_0.exr"), b"0123456789").unwrap();
        assert_eq!(
            bucket.upload_dir("captures/cap_1", &source).await.unwrap(),
            2
        );
        let listed = bucket.list("captures/cap_1").await.unwrap();
        let names: Vec<_> = listed.iter().map(|f| (f.name.as_str(), f.size)).collect();
        assert_eq!(names, [("images/r_0.exr", 10), ("transforms.json", 2)]);
        assert_eq!(
            bucket.size("captures/cap_1/images/r_0.exr").await.unwrap(),
            Some(10)
        );
        assert_eq!(bucket.size("captures/cap_1/missing").await.unwrap(), None);
        let part: Vec<u8> = bucket
            .read_range("captures/cap_1/images/r_0.exr", 3, 4)
            .await
            .unwrap()
            .try_fold(Vec::new(), |mut all, chunk| async move {
                all.extend_from_slice(&chunk);
                Ok(all)
            })
            .await
            .unwrap();
        assert_eq!(part, b"3456");

        let copy = dir.path().join("copy/cap_1");
        assert_eq!(
            bucket.download_dir("captures/cap_1", &copy).await.unwrap(),
            2
        );
        assert_eq!(
            std::fs::read(copy.join("images/r_0.exr")).unwrap(),
            b"0123456789"
        );
        assert_eq!(
            bucket
                .download_dir("captures/none", &dir.path().join("n"))
                .await
                .unwrap(),
            0
        );
        assert!(!dir.path().join("n").exists());

        bucket.delete_folder("captures/cap_1").await.unwrap();
        assert!(bucket.list("captures/cap_1").await.unwrap().is_empty());
    }
}
