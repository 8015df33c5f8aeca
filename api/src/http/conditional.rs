//! Conditional requests on stored files (RFC 9110 §13): whether a client's cached copy is still
//! good (`If-None-Match`, else `If-Modified-Since` → 304), and whether a `Range` still applies
//! to the file the client started from (`If-Range`: an entity tag compared strongly, or the
//! exact `Last-Modified` date; otherwise the whole file is sent).

use std::time::{Duration, SystemTime};

use axum::http::{header, HeaderMap};

/// What validates a stored file: its strong entity tag (quoted) and modification time.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Validators {
    pub etag: String,
    pub modified: SystemTime,
}

impl Validators {
    /// `Last-Modified` as sent: an HTTP date, whole seconds.
    pub fn last_modified(&self) -> String {
        httpdate::fmt_http_date(self.modified)
    }

    fn modified_seconds(&self) -> u64 {
        self.modified
            .duration_since(SystemTime::UNIX_EPOCH)
            .map_or(0, |d| d.as_secs())
    }

    /// Whether the client's copy is current: `If-None-Match` names this tag (or is `*`), or,
    /// without `If-None-Match`, the file is not newer than `If-Modified-Since`.
    pub fn not_modified(&self, headers: &HeaderMap) -> bool {
        if let Some(value) = headers.get(header::IF_NONE_MATCH) {
            let Ok(value) = value.to_str() else {
                return false;
            };
            return value.trim() == "*"
                || value
                    .split(',')
                    .any(|tag| opaque(tag.trim()) == opaque(&self.etag));
        }
        headers
            .get(header::IF_MODIFIED_SINCE)
            .and_then(|v| v.to_str().ok())
            .and_then(|v| httpdate::parse_http_date(v).ok())
            .is_some_and(|since| {
                let since = since
                    .duration_since(SystemTime::UNIX_EPOCH)
                    .unwrap_or(Duration::ZERO);
                self.modified_seconds() <= since.as_secs()
            })
    }

    /// Whether a `Range` applies: always without `If-Range`; with it, only when it names this
    /// file (its strong tag, or its exact modification date).
    pub fn range_applies(&self, headers: &HeaderMap) -> bool {
        let Some(value) = headers.get(header::IF_RANGE) else {
            return true;
        };
        let Ok(value) = value.to_str().map(str::trim) else {
            return false;
        };
        if value.starts_with('"') || value.starts_with("W/") {
            // A weak tag never matches strongly.
            return value == self.etag;
        }
        httpdate::parse_http_date(value).is_ok_and(|date| {
            date.duration_since(SystemTime::UNIX_EPOCH)
                .is_ok_and(|d| d.as_secs() == self.modified_seconds())
        })
    }
}

/// An entity tag without its weakness marker, for the weak comparison of `If-None-Match`.
fn opaque(tag: &str) -> &str {
    tag.strip_prefix("W/").unwrap_or(tag)
}

#[cfg(test)]
mod tests {
    use super::*;
    use axum::http::HeaderValue;

    fn with(name: header::HeaderName, value: &str) -> HeaderMap {
        let mut headers = HeaderMap::new();
        headers.insert(name, HeaderValue::from_str(value).unwrap());
        headers
    }

    #[test]
    fn cached_copies_and_ranges_are_validated() {
        let file = Validators {
            etag: "\"a1-f00\"".into(),
            modified: SystemTime::UNIX_EPOCH + Duration::from_millis(1_700_000_000_500),
        };
        let date = file.last_modified();
        assert_eq!(date, "Tue, 14 Nov 2023 22:13:20 GMT");
        let inm = header::IF_NONE_MATCH;
        assert!(!file.not_modified(&HeaderMap::new()));
        assert!(file.not_modified(&with(inm.clone(), "\"a1-f00\"")));
        assert!(file.not_modified(&with(inm.clone(), "\"x\", W/\"a1-f00\"")));
        assert!(file.not_modified(&with(inm.clone(), "*")));
        assert!(!file.not_modified(&with(inm.clone(), "\"other\"")));
        let ims = header::IF_MODIFIED_SINCE;
        assert!(file.not_modified(&with(ims.clone(), &date)));
        assert!(!file.not_modified(&with(ims.clone(), "Tue, 14 Nov 2023 22:13:19 GMT")));
        // If-None-Match wins over If-Modified-Since.
        let mut both = with(inm, "\"other\"");
        both.insert(ims, HeaderValue::from_str(&date).unwrap());
        assert!(!file.not_modified(&both));

        let ir = header::IF_RANGE;
        assert!(file.range_applies(&HeaderMap::new()));
        assert!(file.range_applies(&with(ir.clone(), "\"a1-f00\"")));
        assert!(!file.range_applies(&with(ir.clone(), "W/\"a1-f00\"")));
        assert!(!file.range_applies(&with(ir.clone(), "\"stale\"")));
        assert!(file.range_applies(&with(ir.clone(), &date)));
        assert!(!file.range_applies(&with(ir.clone(), "Tue, 14 Nov 2023 22:13:21 GMT")));
        assert!(!file.range_applies(&with(ir, "yesterday")));
    }
}
