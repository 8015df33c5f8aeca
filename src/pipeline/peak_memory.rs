//! The peak resident memory of this process, as the kernel counts it (`VmHWM` in
//! `/proc/self/status`): what `bench quality`, a training run's events and a service job report.
//!
//! A service job trains in a process of its own (`phygap-api stage`), so there the figure is the
//! job's; a run inside another program (`phygap train`, a test) reports that program's peak.

/// The process's peak resident set size in bytes; `None` where `/proc` does not say (not Linux).
pub fn peak_resident_bytes() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    parse_high_water_mark(&status)
}

/// `VmHWM` of a `/proc/PID/status` text, in bytes.
fn parse_high_water_mark(status: &str) -> Option<u64> {
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let mut fields = line.split_whitespace().skip(1);
    let value: u64 = fields.next()?.parse().ok()?;
    match fields.next() {
        Some("kB") => value.checked_mul(1024),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_the_high_water_mark_in_bytes() {
        let status =
            "Name:\tphygap\nVmPeak:\t  900000 kB\nVmHWM:\t  612345 kB\nVmRSS:\t  500000 kB\n";
        assert_eq!(parse_high_water_mark(status), Some(612_345 * 1024));
        assert_eq!(parse_high_water_mark("VmRSS:\t 5 kB\n"), None);
        assert_eq!(parse_high_water_mark("VmHWM:\t 5 pages\n"), None);
        assert_eq!(parse_high_water_mark("VmHWM:\t lots kB\n"), None);
    }

    #[cfg(target_os = "linux")]
    #[test]
    fn this_process_has_a_peak_at_least_as_large_as_a_buffer_it_touched() {
        let buffer = vec![1u8; 64 << 20];
        let peak = peak_resident_bytes().expect("Linux reports VmHWM");
        assert!(buffer.iter().all(|&b| b == 1));
        assert!(
            peak >= 64 << 20,
            "peak {peak} below the 64 MiB just touched"
        );
    }
}
