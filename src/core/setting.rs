//! Settings of the training configuration that JSON may write either as a number or as a word
//! (`resolution`, `iterations`): one reader for both forms.

use serde::Deserialize;

/// Reads the setting `key` written either as a number (`from_number`) or as text its `FromStr`
/// reads (`resolution`, `iterations`): `512` and `"512"` are the same setting. Anything else (a
/// negative or fractional number, a number past `u32`, a word `FromStr` refuses) is an error
/// naming `key` and what it takes, as [`ConfigError`](crate::core::config::ConfigError)s do.
pub fn deserialize_number_or_text<'de, D, T>(
    deserializer: D,
    key: &'static str,
    from_number: fn(u32) -> T,
) -> Result<T, D::Error>
where
    D: serde::Deserializer<'de>,
    T: std::str::FromStr<Err = String>,
{
    #[derive(Deserialize)]
    #[serde(untagged)]
    enum Written {
        Number(u32),
        Signed(i64),
        Fraction(f64),
        Text(String),
    }
    let refused =
        |problem: String| -> D::Error { serde::de::Error::custom(format!("`{key}`: {problem}")) };
    let written = Written::deserialize(deserializer)
        .map_err(|_| refused("expected a number or a string".to_owned()))?;
    match written {
        Written::Number(n) => Ok(from_number(n)),
        // Never a count: what `FromStr` says of the text, which names the range.
        Written::Signed(n) => Err(refused(parse_problem::<T>(&n.to_string()))),
        Written::Fraction(x) => Err(refused(parse_problem::<T>(&format!("{x:?}")))),
        Written::Text(text) => text.parse().map_err(refused),
    }
}

/// Why `T` refuses `text` (which it always does for the numbers given here).
fn parse_problem<T: std::str::FromStr<Err = String>>(text: &str) -> String {
    match text.parse::<T>() {
        Err(problem) => problem,
        Ok(_) => format!("`{text}` is not a setting"),
    }
}

#[cfg(test)]
mod tests {
    use crate::core::config::TrainConfig;

    #[test]
    fn a_negative_or_fractional_count_names_the_key_and_its_range() {
        for written in ["-5", "2.5", "5000000000", "\"lots\""] {
            let e = TrainConfig::from_json(&format!(r#"{{"iterations": {written}}}"#)).unwrap_err();
            let message = e.to_string();
            assert!(message.contains("`iterations`"), "{message}");
            assert!(message.contains("1..=1000000"), "{message}");
        }
        let e = TrainConfig::from_json(r#"{"resolution": -2}"#).unwrap_err();
        assert!(e.to_string().contains("`resolution`"), "{e}");
        assert!(e.to_string().contains("longest side"), "{e}");
    }
}
