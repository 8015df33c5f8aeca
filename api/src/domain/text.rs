//! Inputs quoted in messages: an error message quotes the start of an input, never the whole.

/// The first `chars` characters of an input, with `…` where it was cut: what an error message
/// quotes of an input, which it never echoes whole.
pub fn quoted_prefix(text: &str, chars: usize) -> String {
    match text.char_indices().nth(chars) {
        Some((end, _)) => format!("{}…", &text[..end]),
        None => text.to_owned(),
    }
}
