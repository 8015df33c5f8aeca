//! The resolution a training run works at (`--resolution`, the config's `resolution`): the
//! views' full size, or smaller by a whole factor (an area filter, `io::capture::resample`).
//! Written `auto`, `full`, a longest side in pixels (`512`) or a factor (`/4`); `auto` lets the
//! engine choose: a step's cost grows with the pixel count, so each engine has a pixel budget
//! per view ([`Resolution::HOST_PIXEL_BUDGET`], [`Resolution::DEVICE_PIXEL_BUDGET`]).

use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// The resolution training runs at.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Resolution {
    /// The smallest whole factor that brings a view within the engine's pixel budget.
    #[default]
    Auto,
    /// The views as the files are.
    Full,
    /// The smallest whole factor that brings the longest side to at most this many pixels.
    LongestSide(u32),
    /// This factor.
    Downscale(u32),
}

/// Largest whole downscale factor accepted.
pub const MAX_DOWNSCALE: u32 = 64;

/// Shortest longest side accepted, pixels.
pub const MIN_LONGEST_SIDE: u32 = 16;

impl Resolution {
    /// Pixels a view may have under `auto` on the host engines: a 256 × 256 view (65,536)
    /// stays whole, a polarization camera's 1224 × 1024 becomes 306 × 256. At this size a
    /// default run of 48 views takes about ten minutes on two cores.
    pub const HOST_PIXEL_BUDGET: u64 = 100_000;

    /// Pixels a view may have under `auto` on a hardware GPU (about 1414 × 1414; nerfstudio
    /// and 3DGS shrink real captures past 1600 pixels a side).
    pub const DEVICE_PIXEL_BUDGET: u64 = 2_000_000;

    /// The whole factor a `width × height` view is shrunk by, with `pixel_budget` for `auto`.
    pub fn factor(self, width: u32, height: u32, pixel_budget: u64) -> u32 {
        let factor = match self {
            Resolution::Full => 1,
            Resolution::Downscale(k) => k,
            Resolution::LongestSide(side) => width.max(height).div_ceil(side.max(1)),
            Resolution::Auto => {
                let pixels = u64::from(width) * u64::from(height);
                let mut k = 1u32;
                while pixels.div_ceil(u64::from(k) * u64::from(k)) > pixel_budget.max(1) {
                    k += 1;
                }
                k
            }
        };
        factor.clamp(1, MAX_DOWNSCALE)
    }

    /// What is wrong with the setting, if anything.
    pub fn problem(self) -> Option<String> {
        match self {
            Resolution::Downscale(k) if !(1..=MAX_DOWNSCALE).contains(&k) => Some(format!(
                "a downscale of /{k}: it must be /1 to /{MAX_DOWNSCALE}"
            )),
            Resolution::LongestSide(side) if side < MIN_LONGEST_SIDE => Some(format!(
                "a longest side of {side} pixels: at least {MIN_LONGEST_SIDE}"
            )),
            _ => None,
        }
    }
}

impl std::fmt::Display for Resolution {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Resolution::Auto => write!(f, "auto"),
            Resolution::Full => write!(f, "full"),
            Resolution::LongestSide(side) => write!(f, "{side}"),
            Resolution::Downscale(k) => write!(f, "/{k}"),
        }
    }
}

impl std::str::FromStr for Resolution {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, String> {
        let text = text.trim();
        let number = |digits: &str| digits.trim().parse::<u32>().ok();
        let parsed = match text {
            "auto" => Some(Resolution::Auto),
            "full" => Some(Resolution::Full),
            _ => match text.strip_prefix('/') {
                Some(factor) => number(factor).map(Resolution::Downscale),
                None => number(text).map(Resolution::LongestSide),
            },
        };
        parsed.ok_or_else(|| {
            format!(
                "`{text}`: expected auto, full, a longest side in pixels (512) or a downscale \
                 factor (/4)"
            )
        })
    }
}

impl Serialize for Resolution {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

impl<'de> Deserialize<'de> for Resolution {
    /// A string as [`FromStr`](std::str::FromStr) reads it, or a number (a longest side).
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        crate::core::setting::deserialize_number_or_text(
            deserializer,
            "resolution",
            Resolution::LongestSide,
        )
    }
}

#[cfg(feature = "openapi")]
impl utoipa::PartialSchema for Resolution {
    fn schema() -> utoipa::openapi::RefOr<utoipa::openapi::Schema> {
        utoipa::openapi::ObjectBuilder::new()
            .schema_type(utoipa::openapi::Type::String)
            .description(Some(
                "auto, full, a longest side in pixels (\"512\") or a downscale factor (\"/4\")",
            ))
            .into()
    }
}

#[cfg(feature = "openapi")]
impl utoipa::ToSchema for Resolution {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn settings_read_and_write_as_text() {
        for (text, value) in [
            ("auto", Resolution::Auto),
            ("full", Resolution::Full),
            ("512", Resolution::LongestSide(512)),
            ("/4", Resolution::Downscale(4)),
        ] {
            assert_eq!(text.parse::<Resolution>(), Ok(value));
            assert_eq!(value.to_string(), text);
            let json = serde_json::to_string(&value).unwrap();
            assert_eq!(serde_json::from_str::<Resolution>(&json).unwrap(), value);
        }
        assert_eq!(
            serde_json::from_str::<Resolution>("640").unwrap(),
            Resolution::LongestSide(640)
        );
        assert!("half".parse::<Resolution>().is_err());
        assert!(serde_json::from_str::<Resolution>("-3").is_err());
    }

    #[test]
    fn factors_follow_the_setting_and_the_budget() {
        let host = Resolution::HOST_PIXEL_BUDGET;
        assert_eq!(Resolution::Auto.factor(256, 256, host), 1);
        assert_eq!(Resolution::Auto.factor(1224, 1024, host), 4);
        assert_eq!(Resolution::Auto.factor(2448, 2048, host), 8);
        assert_eq!(Resolution::Auto.factor(512, 512, host), 2);
        let device = Resolution::DEVICE_PIXEL_BUDGET;
        assert_eq!(Resolution::Auto.factor(1224, 1024, device), 1);
        assert_eq!(Resolution::Auto.factor(2448, 2048, device), 2);
        assert_eq!(Resolution::Full.factor(2448, 2048, host), 1);
        assert_eq!(Resolution::LongestSide(512).factor(1224, 1024, host), 3);
        assert_eq!(Resolution::LongestSide(1224).factor(1224, 1024, host), 1);
        assert_eq!(Resolution::Downscale(2).factor(256, 256, host), 2);
        assert!(Resolution::Downscale(0).problem().is_some());
        assert!(Resolution::LongestSide(8).problem().is_some());
        assert!(Resolution::Auto.problem().is_none());
    }
}
