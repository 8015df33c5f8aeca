//! A request refused by the service's rules, as the layers below HTTP answer it: a stable
//! machine-readable code (`priority_not_allowed`, `capture_too_large`, …), a message for people,
//! and the kind of refusal, from which [`crate::http::error`] alone chooses the HTTP status.

/// What kind of refusal: the reason a client has to change its request.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RefusalKind {
    /// The request is malformed (400).
    Invalid,
    /// The caller may not do this, e.g. over its account's storage (403).
    Forbidden,
    /// The request conflicts with the state of what it names (409).
    Conflict,
    /// What the request names is past its expiry (410).
    Gone,
    /// Well-formed, but its values are refused (422).
    Unprocessable,
    /// The caller has too much under way already (429).
    TooMany,
}

/// A refused request: its kind, stable code and message.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{message}")]
pub struct Refusal {
    pub kind: RefusalKind,
    pub code: &'static str,
    pub message: String,
}

impl Refusal {
    pub fn new(kind: RefusalKind, code: &'static str, message: impl Into<String>) -> Self {
        Refusal {
            kind,
            code,
            message: message.into(),
        }
    }

    pub fn unprocessable(code: &'static str, message: impl Into<String>) -> Self {
        Self::new(RefusalKind::Unprocessable, code, message)
    }
}
