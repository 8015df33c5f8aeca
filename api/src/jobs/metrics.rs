//! Prometheus text-format metrics: queue depth and running jobs (read from the store at scrape
//! time), job durations and HTTP request latencies (histograms kept in memory since start; the
//! requests are timed by [`crate::http::request_metrics`]).

use std::collections::BTreeMap;
use std::fmt::Write;
use std::sync::Mutex;
use std::time::Duration;

use crate::storage::store::QueueCounts;

const HTTP_BUCKETS: &[f64] = &[
    0.001, 0.0025, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1.0, 2.5, 5.0, 10.0,
];
const JOB_BUCKETS: &[f64] = &[
    1.0,
    5.0,
    15.0,
    60.0,
    300.0,
    900.0,
    3600.0,
    4.0 * 3600.0,
    12.0 * 3600.0,
    86400.0,
];

/// A cumulative histogram with fixed upper bounds.
#[derive(Clone, Debug)]
struct Histogram {
    bounds: &'static [f64],
    counts: Vec<u64>,
    sum: f64,
    count: u64,
}

impl Histogram {
    fn new(bounds: &'static [f64]) -> Self {
        Histogram {
            bounds,
            counts: vec![0; bounds.len()],
            sum: 0.0,
            count: 0,
        }
    }

    fn observe(&mut self, value: f64) {
        for (bound, count) in self.bounds.iter().zip(&mut self.counts) {
            if value <= *bound {
                *count += 1;
            }
        }
        self.sum += value;
        self.count += 1;
    }

    fn render(&self, out: &mut String, name: &str, labels: &str) {
        let sep = if labels.is_empty() { "" } else { "," };
        for (bound, count) in self.bounds.iter().zip(&self.counts) {
            let _ = writeln!(out, "{name}_bucket{{{labels}{sep}le=\"{bound}\"}} {count}");
        }
        let _ = writeln!(
            out,
            "{name}_bucket{{{labels}{sep}le=\"+Inf\"}} {}",
            self.count
        );
        let _ = writeln!(out, "{name}_sum{{{labels}}} {}", self.sum);
        let _ = writeln!(out, "{name}_count{{{labels}}} {}", self.count);
    }
}

/// In-memory metrics of this process.
#[derive(Default)]
pub struct Metrics {
    /// (method, route, status) → latency seconds.
    http: Mutex<BTreeMap<(String, String, u16), Histogram>>,
    /// (kind, final state) → run seconds.
    jobs: Mutex<BTreeMap<(String, String), Histogram>>,
}

fn escape(label: &str) -> String {
    label
        .replace('\\', "\\\\")
        .replace('"', "\\\"")
        .replace('\n', "\\n")
}

impl Metrics {
    pub fn observe_http(&self, method: &str, route: &str, status: u16, latency: Duration) {
        if let Ok(mut map) = self.http.lock() {
            map.entry((method.to_owned(), route.to_owned(), status))
                .or_insert_with(|| Histogram::new(HTTP_BUCKETS))
                .observe(latency.as_secs_f64());
        }
    }

    /// Records one run of a job (a run ends in success, failure, cancel or requeue).
    pub fn observe_job(&self, kind: &str, outcome: &str, duration: Duration) {
        if let Ok(mut map) = self.jobs.lock() {
            map.entry((kind.to_owned(), outcome.to_owned()))
                .or_insert_with(|| Histogram::new(JOB_BUCKETS))
                .observe(duration.as_secs_f64());
        }
    }

    /// The exposition text.
    pub fn render(&self, counts: QueueCounts, workers: usize) -> String {
        let mut out = String::new();
        out.push_str("# HELP phygap_queue_depth Jobs waiting in the queue.\n");
        out.push_str("# TYPE phygap_queue_depth gauge\n");
        let _ = writeln!(out, "phygap_queue_depth {}", counts.queued);
        out.push_str("# HELP phygap_jobs_running Jobs being run by any worker.\n");
        out.push_str("# TYPE phygap_jobs_running gauge\n");
        let _ = writeln!(out, "phygap_jobs_running {}", counts.running);
        out.push_str("# HELP phygap_workers Worker tasks of this process.\n");
        out.push_str("# TYPE phygap_workers gauge\n");
        let _ = writeln!(out, "phygap_workers {workers}");
        out.push_str("# HELP phygap_job_duration_seconds Wall time of job runs by outcome.\n");
        out.push_str("# TYPE phygap_job_duration_seconds histogram\n");
        if let Ok(map) = self.jobs.lock() {
            for ((kind, outcome), h) in map.iter() {
                let labels = format!("kind=\"{}\",outcome=\"{}\"", escape(kind), escape(outcome));
                h.render(&mut out, "phygap_job_duration_seconds", &labels);
            }
        }
        out.push_str("# HELP phygap_http_request_duration_seconds HTTP request latency.\n");
        out.push_str("# TYPE phygap_http_request_duration_seconds histogram\n");
        if let Ok(map) = self.http.lock() {
            for ((method, route, status), h) in map.iter() {
                let labels = format!(
                    "method=\"{}\",route=\"{}\",status=\"{status}\"",
                    escape(method),
                    escape(route)
                );
                h.render(&mut out, "phygap_http_request_duration_seconds", &labels);
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn histogram_buckets_are_cumulative_and_text_is_prometheus() {
        let metrics = Metrics::default();
        metrics.observe_http("GET", "/v1/jobs/{id}", 200, Duration::from_millis(3));
        metrics.observe_http("GET", "/v1/jobs/{id}", 200, Duration::from_millis(30));
        metrics.observe_job("train", "succeeded", Duration::from_secs(20));
        let text = metrics.render(
            QueueCounts {
                queued: 4,
                running: 1,
            },
            2,
        );
        assert!(text.contains("phygap_queue_depth 4\n"));
        assert!(text.contains("phygap_jobs_running 1\n"));
        let prefix = "phygap_http_request_duration_seconds_bucket{method=\"GET\",route=\"/v1/jobs/{id}\",status=\"200\",";
        assert!(
            text.contains(&format!("{prefix}le=\"0.0025\"}} 0\n")),
            "{text}"
        );
        assert!(text.contains(&format!("{prefix}le=\"0.005\"}} 1\n")));
        assert!(text.contains(&format!("{prefix}le=\"0.05\"}} 2\n")));
        assert!(text.contains("phygap_job_duration_seconds_bucket{kind=\"train\",outcome=\"succeeded\",le=\"15\"} 0\n"));
        assert!(text.contains("phygap_job_duration_seconds_bucket{kind=\"train\",outcome=\"succeeded\",le=\"60\"} 1\n"));
    }
}
