//! Settings of the training configuration that JSON may write either as a number or as a word
//! (`resolution`, `iterations`): one reader for both forms.

use serde::Deserialize;

/// Reads a setting written either as a number (`from_number`) or as text its `FromStr` reads
/// (`resolution`, `iterations`): `512` and `"512"` are the same setting.
pub fn deserialize_number_or_text<'de, D, T>(
    deserializer: D,
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
        Text(String),
    }
    match Written::deserialize(deserializer)? {
        Written::Number(n) => Ok(from_number(n)),
        Written::Text(text) => text.parse().map_err(serde::de::Error::custom),
    }
}
