//! Whether a capture fits a job's process at the working resolution a training job asks for, judged
//! when the job is submitted rather than found out hours later: the memory its views take in a
//! training run against the job memory limit. A job whose capture cannot fit is refused
//! ([`Refusal`]) with `capture_too_large`, naming a resolution that would make it fit. The surfels
//! are not counted: their budget follows the object's pixels in the views
//! (`surfels_per_mask_pixel`), and a run that outgrows its memory anyway fails `out_of_memory`,
//! never the service.

use phygap::core::config::TrainConfig;
use phygap::core::resolution::{Resolution, MAX_DOWNSCALE};

use crate::domain::refusal::Refusal;
use crate::storage::store::CaptureRecord;

/// What a job's process holds besides its views: one view's G-buffers, the environment, a
/// modest set of surfels (a small capture trains within a 400 MiB limit; the knot's run at 256²
/// holds 0.15 GB of views).
const BASE_BYTES: u64 = 256 << 20;

/// Bytes a view pixel costs a training run: the loaded view (S0–S2 and mask in f32), which the
/// training targets borrow (a step widens the one view it fits to f64).
const BYTES_PER_VIEW_PIXEL: u64 = 40;

/// The estimated memory of training `views` views of `width × height` shrunk by `downscale`.
pub fn estimated_bytes(views: usize, width: u32, height: u32, downscale: u32) -> u64 {
    let k = u64::from(downscale.max(1));
    let pixels = (u64::from(width) / k) * (u64::from(height) / k);
    BASE_BYTES + (views as u64) * pixels * BYTES_PER_VIEW_PIXEL
}

/// The factor `config` trains `capture` at, where the engine is not known yet (the job may run
/// on any worker): `auto` as on a GPU, the larger of the engines' choices, so that the estimate
/// errs on the side of memory.
fn planned_downscale(capture: &CaptureRecord, config: &TrainConfig) -> u32 {
    config.resolution.factor(
        capture.width.max(1),
        capture.height.max(1),
        Resolution::DEVICE_PIXEL_BUDGET,
    )
}

/// `Ok` when training `capture` with `config` fits `memory_bytes` (or nothing is known to judge
/// by); otherwise 422 `capture_too_large` with the estimate and a resolution that fits.
pub fn check(
    capture: &CaptureRecord,
    config: &TrainConfig,
    memory_bytes: Option<u64>,
) -> Result<(), Refusal> {
    let Some(memory) = memory_bytes else {
        return Ok(());
    };
    if capture.width == 0 || capture.height == 0 {
        return Ok(());
    }
    let estimate = |k| estimated_bytes(capture.views, capture.width, capture.height, k);
    let planned = planned_downscale(capture, config);
    let needed = estimate(planned);
    if needed <= memory {
        return Ok(());
    }
    let gib = |bytes: u64| bytes as f64 / f64::from(1u32 << 30);
    let advice = match (planned..=MAX_DOWNSCALE).find(|&k| estimate(k) <= memory) {
        Some(k) => format!(
            "set the config's `resolution` to \"/{k}\" (views of {}×{})",
            capture.width / k,
            capture.height / k
        ),
        None => "no working resolution fits: use fewer views".to_owned(),
    };
    Err(Refusal::unprocessable(
        "capture_too_large",
        format!(
            "training {} views of {}×{} at resolution {} (÷{planned}) needs about {:.1} GiB, over \
             the job memory limit of {:.1} GiB (--job-memory-mb); {advice}",
            capture.views,
            capture.width,
            capture.height,
            config.resolution,
            gib(needed),
            gib(memory),
        ),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn capture(views: usize, width: u32, height: u32) -> CaptureRecord {
        CaptureRecord {
            id: "cap_x".into(),
            views,
            width,
            height,
            kinds: vec![],
            warnings: vec![],
            size_bytes: 0,
            created_at: 0,
            account: None,
        }
    }

    #[test]
    fn jobs_that_cannot_fit_are_refused_with_a_resolution_that_does() {
        let full = TrainConfig {
            resolution: Resolution::Full,
            ..TrainConfig::default()
        };
        let big = capture(100, 2448, 2048);
        let four_gib = Some(4u64 << 30);
        let eight_gib = Some(8u64 << 30);
        let refused = check(&big, &full, four_gib).unwrap_err();
        assert_eq!(refused.code, "capture_too_large");
        // 100 × 5.0 Mpx × 40 B = 20 GB at full size; ÷2 is 4.9 GiB with the rest, ÷3 2.3 GiB.
        assert!(refused.message.contains("\"/3\""), "{}", refused.message);
        assert!(
            refused.message.contains("about 18.9 GiB"),
            "{}",
            refused.message
        );
        assert!(check(
            &big,
            &TrainConfig {
                resolution: Resolution::Downscale(3),
                ..full.clone()
            },
            four_gib
        )
        .is_ok());
        // auto judges as a GPU would train: 2448 × 2048 ÷ 2.
        assert!(check(&big, &TrainConfig::default(), four_gib).is_err());
        assert!(check(&big, &TrainConfig::default(), eight_gib).is_ok());
        assert!(check(&big, &full, None).is_ok());
        assert!(check(&capture(100, 0, 0), &full, eight_gib).is_ok());
        let hopeless = check(&capture(2000, 65536, 65536), &full, eight_gib).unwrap_err();
        assert!(
            hopeless.message.contains("no working resolution fits"),
            "{}",
            hopeless.message
        );
    }
}
