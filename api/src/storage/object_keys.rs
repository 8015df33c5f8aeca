//! Every key the service gives an object in the deployment's bucket (`--artifact-url`), in one
//! place. They mirror the data dir's folders ([`crate::jobs::settings::Paths`]), under the URL's
//! prefix: `captures/ID/…` (extracted captures), `jobs/ID/input/…` (relight inputs),
//! `jobs/ID/model/…` (checkpoints), `artifacts/ID/…` (downloadable results), `uploads/ID/…` (parts
//! of resumable uploads).

/// An extracted capture's folder.
pub fn capture(capture_id: &str) -> String {
    format!("captures/{capture_id}")
}

/// Everything stored for a job but its artifacts: its inputs and its model.
pub fn job(job_id: &str) -> String {
    format!("jobs/{job_id}")
}

/// A relight job's inputs (the environment map, the cameras).
pub fn job_input(job_id: &str) -> String {
    format!("jobs/{job_id}/input")
}

/// A training job's model folder (checkpoints, then the trained model).
pub fn job_model(job_id: &str) -> String {
    format!("jobs/{job_id}/model")
}

/// A job's artifacts (the caller has checked `job_id` as a folder name).
pub fn artifacts(job_id: &str) -> String {
    format!("artifacts/{job_id}")
}

/// A resumable upload's parts.
pub fn upload(upload_id: &str) -> String {
    format!("uploads/{upload_id}")
}

/// One part of a resumable upload, named by its number and digest (a part sent again with other
/// bytes is another object).
pub fn upload_part(upload_id: &str, index: u32, sha256: &str) -> String {
    format!("uploads/{upload_id}/{index:05}.{sha256}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_mirror_the_data_dir() {
        assert_eq!(capture("cap_1"), "captures/cap_1");
        assert_eq!(job("job_1"), "jobs/job_1");
        assert!(job_input("job_1").starts_with(&job("job_1")));
        assert!(job_model("job_1").starts_with(&job("job_1")));
        assert_eq!(artifacts("job_1"), "artifacts/job_1");
        assert_eq!(upload_part("upl_1", 7, "ab"), "uploads/upl_1/00007.ab");
        assert!(upload_part("upl_1", 7, "ab").starts_with(&upload("upl_1")));
    }
}
