//! A small mutational fuzzer for the readers of untrusted bytes (images, capture documents,
//! COLMAP models, PLY, checkpoints, archives). Each target has a corpus folder of real files,
//! committed as regression cases: every file is run first, then mutants of them (the "havoc"
//! of coverage-guided fuzzers: bit flips, interesting integers, chunks deleted, duplicated,
//! spliced from another seed) until a time budget is spent. A panic is a crash: the input is
//! saved in the corpus as `crash-…` (to be committed once fixed) and the run fails. An abort
//! (an allocation that fails) ends the process; the input being run is always on disk in
//! `target/fuzz-last/TARGET`, for the same purpose.
//!
//! Why not cargo-fuzz: it needs a nightly compiler and its own build, and CI has one stable
//! toolchain and one `cargo test`; this runs inside the tests, reproducibly from its printed
//! seed (`PHYGAP_FUZZ_SEED`), for `PHYGAP_FUZZ_SECONDS` per target.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// One input: the corpus file it came from (its name tells a target which file it stands for)
/// and its bytes.
pub struct Input<'a> {
    pub name: &'a str,
    pub bytes: &'a [u8],
}

/// What a run did.
#[derive(Clone, Debug)]
pub struct Report {
    pub target: String,
    pub seeds: usize,
    pub executions: u64,
    pub seconds: f64,
    pub seed: u64,
}

impl std::fmt::Display for Report {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "fuzz {}: {} executions ({} corpus files, then mutants) in {:.1} s, seed {}, no crash",
            self.target, self.executions, self.seeds, self.seconds, self.seed
        )
    }
}

/// Seconds each target runs: `PHYGAP_FUZZ_SECONDS`, else `default`.
pub fn budget(default: u64) -> Duration {
    let seconds = std::env::var("PHYGAP_FUZZ_SECONDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default);
    Duration::from_secs(seconds)
}

/// The corpus files of a folder, sorted by name.
pub fn corpus(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("corpus folder {}: {e}", dir.display()))
        .filter_map(Result::ok)
        .filter(|e| e.path().is_file())
        .map(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            (
                name,
                std::fs::read(e.path()).expect("reading a corpus file"),
            )
        })
        .collect();
    files.sort();
    assert!(!files.is_empty(), "empty corpus {}", dir.display());
    files
}

/// How mutants are made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mutation {
    /// Byte havoc ([`mutate`]).
    Bytes,
    /// Half of the mutants structured: a value of the seed's JSON replaced by an extreme one
    /// ([`mutate_json`]); the other half byte havoc.
    Json,
}

/// Runs `check` on every corpus file of `dir`, then on mutants of them until `budget` is spent.
///
/// # Panics
/// When `check` panics on an input (after saving it in the corpus as `crash-HASH-NAME`).
pub fn run(
    target: &str,
    dir: &Path,
    mutation: Mutation,
    budget: Duration,
    mut check: impl FnMut(&Input<'_>),
) -> Report {
    let seeds = corpus(dir);
    let seed = std::env::var("PHYGAP_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| rand::rng().random());
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let last = last_input_path(target);
    let started = Instant::now();
    let mut executions = 0u64;
    let mut execute = |name: &str, bytes: &[u8]| {
        let _ = std::fs::write(&last, bytes);
        let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            check(&Input { name, bytes })
        }));
        if let Err(panic) = outcome {
            let saved = dir.join(format!("crash-{:016x}-{name}", fnv1a(bytes)));
            let _ = std::fs::write(&saved, bytes);
            let message = panic
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default();
            panic!(
                "fuzz {target}: a crash on a mutant of {name} (seed {seed}), saved as {}: {message}",
                saved.display()
            );
        }
    };
    for (name, bytes) in &seeds {
        execute(name, bytes);
        executions += 1;
    }
    while started.elapsed() < budget {
        let (name, base) = &seeds[rng.random_range(0..seeds.len())];
        let other = &seeds[rng.random_range(0..seeds.len())].1;
        let structured = match mutation {
            Mutation::Json if rng.random() => serde_json::from_slice(base).ok().map(|value| {
                serde_json::to_vec(&mutate_json(&mut rng, &value)).unwrap_or_default()
            }),
            _ => None,
        };
        let mutant = structured.unwrap_or_else(|| mutate(&mut rng, base, other));
        execute(name, &mutant);
        executions += 1;
    }
    let report = Report {
        target: target.to_owned(),
        seeds: seeds.len(),
        executions,
        seconds: started.elapsed().as_secs_f64(),
        seed,
    };
    println!("{report}");
    report
}

/// Where the input being run is kept (`target/fuzz-last/TARGET`, or the system's temporary
/// folder outside a build tree).
fn last_input_path(target: &str) -> PathBuf {
    let dir = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("target"))
        .join("fuzz-last");
    let dir = if std::fs::create_dir_all(&dir).is_ok() {
        dir
    } else {
        std::env::temp_dir()
    };
    dir.join(target)
}

/// Integers that find off-by-one and overflow mistakes in sizes and counts.
const INTERESTING: [u64; 12] = [
    0,
    1,
    0x7f,
    0xff,
    0x7fff,
    0xffff,
    0x7fff_ffff,
    0xffff_ffff,
    0x1_0000_0000,
    0x7fff_ffff_ffff_ffff,
    u64::MAX,
    100_000,
];

/// One to eight havoc operations on `base` (`other` supplies spliced bytes).
pub fn mutate(rng: &mut impl Rng, base: &[u8], other: &[u8]) -> Vec<u8> {
    let mut data = base.to_vec();
    for _ in 0..rng.random_range(1..=8) {
        let len = data.len();
        match rng.random_range(0..7) {
            // Flip one bit.
            0 if len > 0 => {
                let at = rng.random_range(0..len);
                data[at] ^= 1 << rng.random_range(0..8);
            }
            // A random byte.
            1 if len > 0 => {
                let at = rng.random_range(0..len);
                data[at] = rng.random();
            }
            // An interesting integer's low 1, 2, 4 or 8 bytes, either endianness.
            2 if len > 0 => {
                let value = INTERESTING[rng.random_range(0..INTERESTING.len())].to_le_bytes();
                let width = [1usize, 2, 4, 8][rng.random_range(0..4)].min(len);
                let mut chunk = value[..width].to_vec();
                if rng.random() {
                    chunk.reverse();
                }
                let at = rng.random_range(0..=len - width);
                data[at..at + width].copy_from_slice(&chunk);
            }
            // Delete a chunk.
            3 if len > 1 => {
                let at = rng.random_range(0..len);
                let n = rng.random_range(1..=(len - at).min(64));
                data.drain(at..at + n);
            }
            // Duplicate a chunk in place.
            4 if len > 1 => {
                let at = rng.random_range(0..len);
                let n = rng.random_range(1..=(len - at).min(64));
                let chunk: Vec<u8> = data[at..at + n].to_vec();
                data.splice(at..at, chunk);
            }
            // Splice in a chunk of another seed.
            5 if !other.is_empty() => {
                let from = rng.random_range(0..other.len());
                let n = rng.random_range(1..=(other.len() - from).min(256));
                let at = rng.random_range(0..=len);
                data.splice(at..at, other[from..from + n].iter().copied());
            }
            // Truncate.
            6 if len > 1 => data.truncate(rng.random_range(0..len)),
            _ => data.push(rng.random()),
        }
    }
    data
}

/// JSON values that find missing range checks.
fn interesting_json(rng: &mut impl Rng) -> serde_json::Value {
    use serde_json::json;
    match rng.random_range(0..14) {
        0 => json!(0),
        1 => json!(-1),
        2 => json!(u32::MAX),
        3 => json!(u64::MAX),
        4 => json!(1e308),
        5 => json!(-1e308),
        6 => json!(1e-308),
        7 => json!(0.5),
        8 => json!(""),
        9 => json!("../../etc/passwd"),
        10 => serde_json::Value::Null,
        11 => json!([]),
        12 => json!({}),
        _ => json!([[1e308, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]),
    }
}

/// The value with one of its parts (a random path into objects and arrays) replaced by an
/// extreme value, removed, or repeated.
pub fn mutate_json(rng: &mut impl Rng, value: &serde_json::Value) -> serde_json::Value {
    let mut value = value.clone();
    mutate_json_at(rng, &mut value);
    value
}

fn mutate_json_at(rng: &mut impl Rng, value: &mut serde_json::Value) {
    use serde_json::Value;
    let descend = rng.random_range(0..4) != 0;
    match value {
        Value::Object(map) if descend && !map.is_empty() => {
            let key = map.keys().nth(rng.random_range(0..map.len())).cloned();
            let Some(key) = key else { return };
            if rng.random_range(0..6) == 0 {
                map.remove(&key);
            } else if let Some(child) = map.get_mut(&key) {
                mutate_json_at(rng, child);
            }
        }
        Value::Array(items) if descend && !items.is_empty() => {
            let i = rng.random_range(0..items.len());
            if rng.random_range(0..6) == 0 {
                let copy = items[i].clone();
                items.extend(std::iter::repeat_n(copy, rng.random_range(1..200)));
            } else {
                mutate_json_at(rng, &mut items[i]);
            }
        }
        _ => *value = interesting_json(rng),
    }
}

/// A stable 64-bit hash of bytes (FNV-1a), naming saved crashes.
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |hash, &b| {
        (hash ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mutants_differ_and_stay_reproducible() {
        let base = b"phygap fuzz seed with some bytes".to_vec();
        let mutants = |seed| {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            (0..50)
                .map(|_| mutate(&mut rng, &base, b"other"))
                .collect::<Vec<_>>()
        };
        let (a, b) = (mutants(7), mutants(7));
        assert_eq!(a, b, "the same seed gives the same mutants");
        assert!(a.iter().filter(|m| **m != base).count() >= 45);
        assert!(mutate(&mut ChaCha8Rng::seed_from_u64(1), &[], &[]).len() <= 8);
        let doc = serde_json::json!({"w": 8, "frames": [{"fl_x": 2.0}, {"fl_x": 3.0}]});
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let changed = (0..50)
            .filter(|_| mutate_json(&mut rng, &doc) != doc)
            .count();
        assert!(changed >= 40, "{changed} of 50 JSON mutants differ");
    }

    #[test]
    fn a_panicking_check_saves_its_input_and_fails_the_run() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("seed.txt"), b"fine").unwrap();
        std::fs::write(dir.path().join("zz.txt"), b"boom").unwrap();
        let outcome = std::panic::catch_unwind(|| {
            run(
                "self-test",
                dir.path(),
                Mutation::Bytes,
                Duration::ZERO,
                |input| {
                    assert!(input.bytes != b"boom", "exploded");
                },
            )
        });
        let message = *outcome.unwrap_err().downcast::<String>().unwrap();
        assert!(message.contains("exploded"), "{message}");
        let saved: Vec<String> = corpus(dir.path()).into_iter().map(|(n, _)| n).collect();
        assert!(saved
            .iter()
            .any(|n| n.starts_with("crash-") && n.ends_with("-zz.txt")));
    }
}
