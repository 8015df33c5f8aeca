//! How many optimization steps a training run takes (`--iterations`, the config's
//! `iterations`): a fixed count, or `auto`, which sizes the schedule to the capture. A step
//! renders one view, and its cost grows with the object's pixels in that view; `auto` gives an
//! object smaller than [`Iterations::REFERENCE_OBJECT_PIXELS`] per view proportionally more steps,
//! so that a run of a small object costs what the default schedule costs on a larger one,
//! between [`Iterations::AUTO_MIN`] and [`Iterations::AUTO_MAX`] steps. The count depends only on
//! the capture and the working resolution, never on the machine, so equal settings still give
//! equal runs.

use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// The length of a training run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Iterations {
    /// Sized to the capture's object pixels per view ([`Iterations::for_object`]).
    #[default]
    Auto,
    /// This many steps.
    Fixed(u32),
}

/// Most steps a run may take.
pub const MAX_ITERATIONS: u32 = 1_000_000;

impl Iterations {
    /// Steps `auto` gives an object of [`Self::REFERENCE_OBJECT_PIXELS`] or more per view: the
    /// default schedule (the paper trains 15,000).
    pub const AUTO_MIN: u32 = 6_000;

    /// Most steps `auto` gives: twice the default schedule, for the smallest objects.
    pub const AUTO_MAX: u32 = 12_000;

    /// Mean object pixels per training view (mask pixels at the working resolution) at which
    /// `auto` gives [`Self::AUTO_MIN`] steps: about a quarter of a 256 × 256 view. The default run
    /// of an object this size takes about eight minutes on two cores (the shared knot, 16,091
    /// pixels per view, on which the default schedule was measured).
    pub const REFERENCE_OBJECT_PIXELS: f64 = 16_000.0;

    /// The steps of a run whose training views hold `mean_object_pixels` mask pixels on average.
    /// `auto`: [`Self::AUTO_MIN`] × reference ÷ object pixels, rounded to a hundred steps and
    /// kept within [`Self::AUTO_MIN`]..=[`Self::AUTO_MAX`].
    pub fn for_object(self, mean_object_pixels: f64) -> u32 {
        match self {
            Iterations::Fixed(count) => count,
            Iterations::Auto => {
                let scaled = f64::from(Self::AUTO_MIN) * Self::REFERENCE_OBJECT_PIXELS
                    / mean_object_pixels.max(1.0);
                let rounded = (scaled / 100.0).round() * 100.0;
                // Within u32 after the clamp (no pixels at all, or NaN, give the most).
                rounded.clamp(f64::from(Self::AUTO_MIN), f64::from(Self::AUTO_MAX)) as u32
            }
        }
    }

    /// The count where it is known before a capture is read: the fixed count, or `auto`'s
    /// least ([`Self::AUTO_MIN`]), which estimates made before training starts use.
    pub fn at_least(self) -> u32 {
        match self {
            Iterations::Fixed(count) => count,
            Iterations::Auto => Self::AUTO_MIN,
        }
    }

    /// What is wrong with the setting, if anything.
    pub fn problem(self) -> Option<String> {
        match self {
            Iterations::Fixed(count) if !(1..=MAX_ITERATIONS).contains(&count) => {
                Some(format!("must be auto or in 1..={MAX_ITERATIONS}"))
            }
            _ => None,
        }
    }
}

impl From<u32> for Iterations {
    fn from(count: u32) -> Self {
        Iterations::Fixed(count)
    }
}

impl std::fmt::Display for Iterations {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Iterations::Auto => write!(f, "auto"),
            Iterations::Fixed(count) => write!(f, "{count}"),
        }
    }
}

impl std::str::FromStr for Iterations {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, String> {
        let text = text.trim();
        if text == "auto" {
            return Ok(Iterations::Auto);
        }
        text.parse::<u32>().map(Iterations::Fixed).map_err(|_| {
            format!("`{text}`: expected auto or a number of steps in 1..={MAX_ITERATIONS}")
        })
    }
}

impl Serialize for Iterations {
    /// A count as a number, `auto` as the string.
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self {
            Iterations::Auto => serializer.serialize_str("auto"),
            Iterations::Fixed(count) => serializer.serialize_u32(*count),
        }
    }
}

impl<'de> Deserialize<'de> for Iterations {
    /// A number of steps, or a string as [`FromStr`](std::str::FromStr) reads it.
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        crate::core::setting::deserialize_number_or_text(
            deserializer,
            "iterations",
            Iterations::Fixed,
        )
    }
}

#[cfg(feature = "openapi")]
impl utoipa::PartialSchema for Iterations {
    fn schema() -> utoipa::openapi::RefOr<utoipa::openapi::Schema> {
        use utoipa::openapi::schema::{ObjectBuilder, OneOfBuilder, Type};
        OneOfBuilder::new()
            .item(
                ObjectBuilder::new()
                    .schema_type(Type::Integer)
                    .minimum(Some(1)),
            )
            .item(
                ObjectBuilder::new()
                    .schema_type(Type::String)
                    .enum_values(Some(["auto"])),
            )
            .description(Some(
                "a number of steps, or \"auto\": sized to the capture's object pixels per view",
            ))
            .into()
    }
}

#[cfg(feature = "openapi")]
impl utoipa::ToSchema for Iterations {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn settings_read_and_write_as_numbers_or_auto() {
        for (json, value) in [
            ("\"auto\"", Iterations::Auto),
            ("300", Iterations::Fixed(300)),
        ] {
            assert_eq!(serde_json::from_str::<Iterations>(json).unwrap(), value);
            assert_eq!(serde_json::to_string(&value).unwrap(), json);
        }
        assert_eq!(
            serde_json::from_str::<Iterations>("\"4000\"").unwrap(),
            Iterations::Fixed(4000)
        );
        assert_eq!("auto".parse::<Iterations>(), Ok(Iterations::Auto));
        assert_eq!(" 40 ".parse::<Iterations>(), Ok(Iterations::Fixed(40)));
        assert_eq!(Iterations::Fixed(40).to_string(), "40");
        for bad in ["\"many\"", "-3", "1.5", "null"] {
            assert!(serde_json::from_str::<Iterations>(bad).is_err(), "{bad}");
        }
        assert!(Iterations::Fixed(0).problem().is_some());
        assert!(Iterations::Fixed(MAX_ITERATIONS + 1).problem().is_some());
        assert!(Iterations::Auto.problem().is_none());
    }

    #[test]
    fn auto_gives_smaller_objects_more_steps_within_its_bounds() {
        let auto = |pixels: f64| Iterations::Auto.for_object(pixels);
        assert_eq!(
            auto(Iterations::REFERENCE_OBJECT_PIXELS),
            Iterations::AUTO_MIN
        );
        assert_eq!(auto(40_000.0), Iterations::AUTO_MIN);
        // Half the reference's pixels: twice the steps; two thirds: 1.5 times.
        assert_eq!(auto(8_000.0), 12_000);
        assert_eq!(auto(16_000.0 / 1.5), 9_000);
        // 6,000 × 16,000 / 8,880 = 10,810.8, rounded to a hundred.
        assert_eq!(auto(8_880.0), 10_800);
        assert_eq!(auto(16_091.0), Iterations::AUTO_MIN);
        assert_eq!(auto(100.0), Iterations::AUTO_MAX);
        assert_eq!(auto(0.0), Iterations::AUTO_MAX);
        assert_eq!(auto(f64::NAN), Iterations::AUTO_MAX);
        // Fewer pixels never mean fewer steps.
        let counts: Vec<u32> = (1..200).map(|k| auto(f64::from(k) * 200.0)).collect();
        assert!(counts.windows(2).all(|w| w[0] >= w[1]), "{counts:?}");
        assert_eq!(Iterations::Fixed(40).for_object(100.0), 40);
        assert_eq!(Iterations::Auto.at_least(), Iterations::AUTO_MIN);
        assert_eq!(Iterations::Fixed(40).at_least(), 40);
    }
}
