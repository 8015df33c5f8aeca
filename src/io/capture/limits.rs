//! The most a capture may declare: views, pixels per view and the bytes its loaded views hold.
//! They are checked against what `transforms.json` (or a COLMAP model) says, before a single image
//! is read, so a capture of 8,000 frames or of one 100000 × 100000 view is refused with the limit
//! it breaks instead of exhausting the memory of the process that loads it. Each image file's
//! header is then checked against its frame's size before it is decoded (`images::read_sized`).

pub use super::error::LimitExceeded;
use super::frame::{FrameSpec, Source};

/// Bounds on a capture, checked before its images are read. The defaults fit a 24 GiB worker.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CaptureLimits {
    /// Most frames (views).
    pub max_views: usize,
    /// Most pixels one frame's images may have (the sensor's for raw mosaic frames).
    pub max_pixels_per_view: u64,
    /// Most bytes the loaded views may hold together ([`CaptureLimits::BYTES_PER_VIEW_PIXEL`] per
    /// pixel of every view).
    pub max_decoded_bytes: u64,
}

impl CaptureLimits {
    /// What one pixel of a loaded view holds: S0, S1 and S2 as f32 RGB, and the f32 mask.
    pub const BYTES_PER_VIEW_PIXEL: u64 = 40;

    /// 2,000 views; 50 megapixels a view (a 2448 × 2048 polarization sensor is 5); 8 GiB of views
    /// (100 views of 1448 × 1448).
    pub const DEFAULT: CaptureLimits = CaptureLimits {
        max_views: 2_000,
        max_pixels_per_view: 50_000_000,
        max_decoded_bytes: 8 << 30,
    };

    /// The bytes `views` views of `width × height` hold once loaded.
    pub fn decoded_bytes(views: usize, width: u64, height: u64) -> u64 {
        (views as u64)
            .saturating_mul(width.saturating_mul(height))
            .saturating_mul(Self::BYTES_PER_VIEW_PIXEL)
    }

    /// Checks a count of views of the given sizes (the sizes of the files each view decodes, and
    /// of the view itself) against the limits; the first limit broken is returned.
    pub fn check(
        &self,
        views: usize,
        file_sizes: impl IntoIterator<Item = (u64, u64)>,
        view_sizes: impl IntoIterator<Item = (u64, u64)>,
    ) -> Result<(), LimitExceeded> {
        if views > self.max_views {
            return Err(LimitExceeded {
                limit: "max_views",
                needed: views as u64,
                allowed: self.max_views as u64,
                message: format!(
                    "{views} views, over the limit of {} (max_views)",
                    self.max_views
                ),
            });
        }
        for (width, height) in file_sizes {
            let pixels = width.saturating_mul(height);
            if pixels > self.max_pixels_per_view {
                return Err(LimitExceeded {
                    limit: "max_pixels_per_view",
                    needed: pixels,
                    allowed: self.max_pixels_per_view,
                    message: format!(
                        "a view of {width}×{height} pixels, over the limit of {} pixels a view \
                         (max_pixels_per_view)",
                        self.max_pixels_per_view
                    ),
                });
            }
        }
        let decoded = view_sizes.into_iter().fold(0u64, |sum, (width, height)| {
            sum.saturating_add(Self::decoded_bytes(1, width, height))
        });
        if decoded > self.max_decoded_bytes {
            return Err(LimitExceeded {
                limit: "max_decoded_bytes",
                needed: decoded,
                allowed: self.max_decoded_bytes,
                message: format!(
                    "{views} views holding {} MiB once loaded ({} bytes a pixel), over the limit \
                     of {} MiB (max_decoded_bytes)",
                    decoded >> 20,
                    Self::BYTES_PER_VIEW_PIXEL,
                    self.max_decoded_bytes >> 20
                ),
            });
        }
        Ok(())
    }

    /// [`CaptureLimits::check`] for parsed frames to be shrunk by `downscale`: a raw frame
    /// decodes its sensor's pixels; the views hold their shrunk size.
    pub(crate) fn check_frames(
        &self,
        frames: &[FrameSpec],
        downscale: u32,
    ) -> Result<(), LimitExceeded> {
        let full = |frame: &FrameSpec| {
            (
                u64::from(frame.camera.width),
                u64::from(frame.camera.height),
            )
        };
        let size = |frame: &FrameSpec| {
            let (width, height) = full(frame);
            let k = u64::from(downscale.max(1));
            (width / k, height / k)
        };
        let file_size = |frame: &FrameSpec| match &frame.source {
            Source::Raw(raw) => (raw.sensor_size.0 as u64, raw.sensor_size.1 as u64),
            _ => full(frame),
        };
        self.check(
            frames.len(),
            frames.iter().map(file_size),
            frames.iter().map(size),
        )
    }
}

impl Default for CaptureLimits {
    fn default() -> Self {
        CaptureLimits::DEFAULT
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_limit_is_named_with_what_the_capture_needs() {
        let limits = CaptureLimits {
            max_views: 10,
            max_pixels_per_view: 100 * 100,
            max_decoded_bytes: 4 * 100 * 100 * CaptureLimits::BYTES_PER_VIEW_PIXEL,
        };
        let sizes = |n: usize, w: u64| vec![(w, w); n];
        assert_eq!(limits.check(4, sizes(4, 100), sizes(4, 100)), Ok(()));
        let over = limits.check(11, sizes(11, 10), sizes(11, 10)).unwrap_err();
        assert_eq!(
            (over.limit, over.needed, over.allowed),
            ("max_views", 11, 10)
        );
        let over = limits.check(1, sizes(1, 101), sizes(1, 101)).unwrap_err();
        assert_eq!(
            (over.limit, over.needed, over.allowed),
            ("max_pixels_per_view", 101 * 101, 100 * 100)
        );
        assert!(over.message.contains("101×101"), "{}", over.message);
        let over = limits.check(5, sizes(5, 100), sizes(5, 100)).unwrap_err();
        assert_eq!(over.limit, "max_decoded_bytes");
        assert_eq!(over.needed, 5 * 100 * 100 * 40);
        // A declared size near u64::MAX saturates instead of wrapping into a small number.
        let over = limits
            .check(1, [(u64::MAX, u64::MAX)], [(u64::MAX, 2)])
            .unwrap_err();
        assert_eq!(over.limit, "max_pixels_per_view");
    }
}
