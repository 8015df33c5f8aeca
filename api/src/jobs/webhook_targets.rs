//! Where webhooks may go: the operator's settings ([`WebhookSettings`]: the default URL, the
//! signing secret, the hosts and address ranges allowed) and the checks a URL passes before a
//! job may name it and again when it is called: parsed once by the parser the HTTP client uses
//! (the host checked is the host called), `http` or `https`, no credentials, a host of
//! `--webhook-hosts` when that is set, and every address it names or resolves to outside the
//! network unless `--webhook-allow-cidr` admits it ([`crate::jobs::outbound`]). A URL refused is
//! a [`Refusal`] `invalid_webhook`. The deliveries are [`crate::jobs::webhooks`].

use std::net::IpAddr;

use crate::domain::refusal::Refusal;
use crate::jobs::outbound::AddressPolicy;

/// The operator's webhook settings.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct WebhookSettings {
    /// The URL jobs without their own are reported to.
    pub default_url: Option<String>,
    /// The HMAC key of the signatures (empty: the requests carry an unkeyed signature, which
    /// proves nothing; set one).
    pub secret: String,
    /// Hosts webhooks may target; empty: any.
    pub allowed_hosts: Vec<String>,
    /// The addresses webhooks may reach: public ones, and the internal ranges the operator
    /// allows (`--webhook-allow-cidr`).
    pub addresses: AddressPolicy,
}

/// Longest webhook URL, bytes.
const MAX_URL_BYTES: usize = 2048;

/// Characters of a refused URL quoted back in the error.
const QUOTED_CHARS: usize = 120;

impl WebhookSettings {
    /// The URL a job submitted with `requested` reports to, checked as far as it can be without
    /// the network (see [`Self::parse`]), its name resolved and every address it resolves to
    /// checked; `Ok(None)`: none.
    pub async fn target(&self, requested: Option<&str>) -> Result<Option<String>, Refusal> {
        let Some(url) = requested.or(self.default_url.as_deref()) else {
            return Ok(None);
        };
        let parsed = self.parse(url)?;
        if let Some(url::Host::Domain(name)) = parsed.host() {
            let port = parsed.port_or_known_default().unwrap_or(80);
            self.addresses
                .resolve(name, port)
                .await
                .map_err(|e| invalid_webhook(format!("`{}`: {e}", quoted(url))))?;
        }
        Ok(Some(parsed.into()))
    }

    /// `url` parsed by the parser the HTTP client uses (so the host checked is the host called),
    /// and checked: http(s), no credentials, a host in `--webhook-hosts` when that is set, an
    /// address literal outside the network unless allowed. The name of a host is checked where
    /// it is resolved.
    pub fn parse(&self, url: &str) -> Result<url::Url, Refusal> {
        let shown = quoted(url);
        if url.len() > MAX_URL_BYTES {
            return Err(invalid_webhook(format!(
                "`{shown}` is longer than {MAX_URL_BYTES} bytes"
            )));
        }
        let parsed = url::Url::parse(url)
            .map_err(|e| invalid_webhook(format!("`{shown}` is not a usable URL: {e}")))?;
        if !matches!(parsed.scheme(), "http" | "https") {
            return Err(invalid_webhook(format!(
                "`{shown}`: webhooks are http or https"
            )));
        }
        if !parsed.username().is_empty() || parsed.password().is_some() {
            return Err(invalid_webhook(format!(
                "`{}`: webhook URLs may not carry credentials (the signature authenticates \
                 the service to the receiver)",
                quoted(&without_userinfo(&parsed))
            )));
        }
        let host = parsed
            .host()
            .ok_or_else(|| invalid_webhook(format!("`{shown}` has no host")))?;
        if !self.allowed_hosts.is_empty() && !self.allowed_hosts.iter().any(|a| same_host(a, &host))
        {
            return Err(invalid_webhook(format!(
                "webhooks may call {} only (--webhook-hosts), not `{}`",
                self.allowed_hosts.join(", "),
                quoted(&host.to_string())
            )));
        }
        let literal = match host {
            url::Host::Ipv4(v4) => Some(IpAddr::V4(v4)),
            url::Host::Ipv6(v6) => Some(IpAddr::V6(v6)),
            url::Host::Domain(_) => None,
        };
        if let Some(address) = literal {
            self.addresses
                .check(address)
                .map_err(|e| invalid_webhook(format!("`{shown}`: {e}")))?;
        }
        Ok(parsed)
    }
}

fn invalid_webhook(why: String) -> Refusal {
    Refusal::unprocessable("invalid_webhook", why)
}

/// The start of `text`, for an error message (an input is never echoed whole).
fn quoted(text: &str) -> String {
    crate::domain::text::quoted_prefix(text, QUOTED_CHARS)
}

/// `url` with its credentials removed (never shown back).
fn without_userinfo(url: &url::Url) -> String {
    let mut shown = url.clone();
    let _ = shown.set_username("");
    let _ = shown.set_password(None);
    shown.to_string()
}

/// Whether `allowed` (an entry of `--webhook-hosts`) names `host`: the same address, or the same
/// name once both are normalised as URL hosts (case, IDN).
fn same_host(allowed: &str, host: &url::Host<&str>) -> bool {
    let allowed = allowed.trim().trim_start_matches('[').trim_end_matches(']');
    if let Ok(address) = allowed.parse::<IpAddr>() {
        return match host {
            url::Host::Ipv4(v4) => IpAddr::V4(*v4) == address.to_canonical(),
            url::Host::Ipv6(v6) => IpAddr::V6(*v6).to_canonical() == address.to_canonical(),
            url::Host::Domain(_) => false,
        };
    }
    match (url::Host::parse(allowed), host) {
        (Ok(url::Host::Domain(name)), url::Host::Domain(host)) => name == *host,
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Settings that admit loopback (as tests and private deployments do) and `hosts`.
    fn loopback_settings(hosts: &[&str]) -> WebhookSettings {
        WebhookSettings {
            allowed_hosts: hosts.iter().map(|h| h.to_string()).collect(),
            addresses: AddressPolicy::allowing(["127.0.0.0/8", "::1"]).unwrap(),
            ..WebhookSettings::default()
        }
    }

    #[test]
    fn urls_are_http_without_credentials_and_outside_the_network() {
        let open = WebhookSettings::default();
        let ok = open.parse("https://hooks.example.com/phygap?x=1").unwrap();
        assert_eq!(ok.as_str(), "https://hooks.example.com/phygap?x=1");
        for bad in [
            "ftp://x/y",
            "file:///etc/passwd",
            "localhost:80",
            "http://",
            "http://a b",
            "http://user:pw@hooks.example.com/x",
            "http://user@hooks.example.com/x",
            // Address literals inside the network, however they are written.
            "http://127.0.0.1/",
            "http://2130706433/",
            "http://0x7f000001/",
            "http://0177.0.0.1/",
            "http://127.1/",
            "http://0.0.0.0/",
            "http://[::1]/",
            "http://[::ffff:127.0.0.1]/",
            "http://[::ffff:7f00:1]/",
            "http://169.254.169.254/latest/meta-data",
            "http://10.0.0.1/",
            "http://[fd00::1]/",
            "http://100.64.0.1/",
        ] {
            assert!(open.parse(bad).is_err(), "{bad}");
        }
        let long = format!("https://hooks.example.com/{}", "a".repeat(3000));
        let refused = open.parse(&long).unwrap_err();
        assert!(refused.message.len() < 400, "{}", refused.message);
    }

    #[test]
    fn credentials_are_never_shown_back() {
        let refused = WebhookSettings::default()
            .parse("https://alice:s3cret@hooks.example.com/x")
            .unwrap_err();
        assert!(!refused.message.contains("s3cret"), "{}", refused.message);
        assert!(!refused.message.contains("alice"), "{}", refused.message);
    }

    #[test]
    fn the_host_checked_is_the_host_the_client_calls() {
        let settings = loopback_settings(&["localhost"]);
        // The client reads `\` as `/`: the host is 127.0.0.1, not `localhost`.
        let backslash = r"http://127.0.0.1:9\@localhost:8/x";
        assert!(settings.parse(backslash).is_err());
        assert_eq!(
            settings.parse("http://LOCALHOST:8/x").unwrap().host_str(),
            Some("localhost")
        );
        // IDN: fullwidth letters are the same name once normalised.
        assert!(settings.parse("http://ｌｏｃａｌｈｏｓｔ:8/x").is_ok());
        let by_address = loopback_settings(&["127.0.0.1", "::1"]);
        assert!(by_address.parse("http://127.0.0.1:8123/hook").is_ok());
        assert!(by_address.parse("http://2130706433:8123/hook").is_ok());
        assert!(by_address.parse("http://[::1]:80/").is_ok());
        assert!(by_address.parse("http://127.0.0.2/").is_err());
        assert!(by_address.parse("http://localhost/").is_err());
    }

    #[tokio::test]
    async fn names_are_resolved_and_checked_at_submit() {
        let strict = WebhookSettings::default();
        let inside = strict
            .target(Some("http://localhost:8/x"))
            .await
            .unwrap_err();
        assert_eq!(inside.code, "invalid_webhook");
        assert!(inside.message.contains("loopback"), "{}", inside.message);
        assert!(strict
            .target(Some("http://no-such-host.invalid/x"))
            .await
            .is_err());
        let allowed = loopback_settings(&[]);
        assert_eq!(
            allowed.target(Some("http://localhost:8/x")).await.unwrap(),
            Some("http://localhost:8/x".to_owned())
        );
        let with_default = WebhookSettings {
            default_url: Some("http://127.0.0.1:9/default".into()),
            ..loopback_settings(&[])
        };
        assert_eq!(
            with_default.target(None).await.unwrap().as_deref(),
            Some("http://127.0.0.1:9/default")
        );
        assert_eq!(strict.target(None).await.unwrap(), None);
    }
}
