//! Where the service's own outbound requests (webhooks) may go: the address policy that keeps
//! them from reaching inside the network the service runs in (SSRF), and the DNS resolver that
//! enforces it at connection time.
//!
//! An address is *internal* when it is loopback, private (RFC 1918), link-local (a cloud's
//! metadata service is 169.254.169.254), shared (CGNAT, 100.64/10), unique-local, site-local,
//! multicast, unspecified, broadcast or otherwise reserved, in IPv4, IPv6, or IPv4 carried in
//! IPv6 (mapped `::ffff:a.b.c.d`, compatible `::a.b.c.d`, NAT64 `64:ff9b::/96`, 6to4 `2002::/16`).
//! Internal addresses are refused unless the operator allows a range of them
//! (`--webhook-allow-cidr`, for tests and private deployments).
//!
//! A name is checked where it is resolved: [`CheckedResolver`] is the HTTP client's resolver, so
//! the client connects only to addresses that passed the check (no second resolution between the
//! check and the connection, which a DNS answer that changes could exploit).

use std::net::{IpAddr, Ipv4Addr, Ipv6Addr, SocketAddr};
use std::time::Duration;

use ipnet::IpNet;

/// Longest wait for a name's addresses.
const RESOLVE_TIMEOUT: Duration = Duration::from_secs(5);

/// Why an outbound request may not go where it was asked to.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum OutboundError {
    #[error(
        "{address} is a {kind} address, inside the network (--webhook-allow-cidr admits a range)"
    )]
    Internal { address: IpAddr, kind: &'static str },
    #[error("`{host}` resolves to {address}, a {kind} address, inside the network (--webhook-allow-cidr admits a range)")]
    ResolvesInside {
        host: String,
        address: IpAddr,
        kind: &'static str,
    },
    #[error("`{host}` cannot be resolved")]
    Unresolved { host: String },
}

/// The addresses outbound requests may reach: every public address, and the internal ones in
/// the operator's allowed ranges.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct AddressPolicy {
    allowed: Vec<IpNet>,
}

impl AddressPolicy {
    /// Public addresses and those in `allowed` (CIDR ranges, or single addresses).
    pub fn allowing<S: AsRef<str>>(
        allowed: impl IntoIterator<Item = S>,
    ) -> Result<AddressPolicy, String> {
        let allowed = allowed
            .into_iter()
            .map(|range| parse_range(range.as_ref()))
            .collect::<Result<_, _>>()?;
        Ok(AddressPolicy { allowed })
    }

    /// The ranges of internal addresses this policy admits.
    pub fn allowed_ranges(&self) -> &[IpNet] {
        &self.allowed
    }

    /// Whether a request may connect to `address`.
    pub fn check(&self, address: IpAddr) -> Result<(), OutboundError> {
        let address = address.to_canonical();
        if self.allowed.iter().any(|range| range.contains(&address)) {
            return Ok(());
        }
        match internal_kind(address) {
            Some(kind) => Err(OutboundError::Internal { address, kind }),
            None => Ok(()),
        }
    }

    /// The addresses of `host` (a name) that a request may connect to on `port`: all of them
    /// must pass, so that a name cannot mix a public address with an internal one.
    pub async fn resolve(&self, host: &str, port: u16) -> Result<Vec<SocketAddr>, OutboundError> {
        let unresolved = || OutboundError::Unresolved {
            host: host.to_owned(),
        };
        let addresses: Vec<SocketAddr> =
            tokio::time::timeout(RESOLVE_TIMEOUT, tokio::net::lookup_host((host, port)))
                .await
                .map_err(|_| unresolved())?
                .map_err(|_| unresolved())?
                .collect();
        if addresses.is_empty() {
            return Err(unresolved());
        }
        for address in &addresses {
            if let Err(OutboundError::Internal { address, kind }) = self.check(address.ip()) {
                return Err(OutboundError::ResolvesInside {
                    host: host.to_owned(),
                    address,
                    kind,
                });
            }
        }
        Ok(addresses)
    }
}

/// A CIDR range (`10.0.0.0/8`, `::1/128`) or a single address.
fn parse_range(text: &str) -> Result<IpNet, String> {
    let text = text.trim();
    text.parse::<IpNet>()
        .or_else(|_| text.parse::<IpAddr>().map(IpNet::from))
        .map_err(|_| format!("`{text}` is not an address range (e.g. 10.0.0.0/8 or ::1/128)"))
}

/// What kind of internal address `address` is; `None`: a public one.
pub fn internal_kind(address: IpAddr) -> Option<&'static str> {
    match address.to_canonical() {
        IpAddr::V4(v4) => internal_v4(v4),
        IpAddr::V6(v6) => internal_v6(v6),
    }
}

fn internal_v4(address: Ipv4Addr) -> Option<&'static str> {
    Some(match address.octets() {
        [0, ..] => "unspecified (0.0.0.0/8)",
        [127, ..] => "loopback",
        [10, ..] | [192, 168, ..] => "private",
        [172, b, ..] if (16..32).contains(&b) => "private",
        [169, 254, ..] => "link-local",
        [100, b, ..] if (64..128).contains(&b) => "shared (CGNAT)",
        [192, 0, 0, _] => "protocol-assignment",
        [192, 0, 2, _] | [198, 51, 100, _] | [203, 0, 113, _] => "documentation",
        [198, 18 | 19, ..] => "benchmarking",
        [224..=239, ..] => "multicast",
        [240..=255, ..] => "reserved or broadcast",
        _ => return None,
    })
}

fn internal_v6(address: Ipv6Addr) -> Option<&'static str> {
    let segments = address.segments();
    if address.is_unspecified() {
        return Some("unspecified");
    }
    if address.is_loopback() {
        return Some("loopback");
    }
    if let Some(v4) = embedded_v4(address) {
        return internal_v4(v4);
    }
    Some(match segments[0] {
        s if s & 0xfe00 == 0xfc00 => "unique-local",
        s if s & 0xffc0 == 0xfe80 => "link-local",
        s if s & 0xffc0 == 0xfec0 => "site-local",
        s if s & 0xff00 == 0xff00 => "multicast",
        0x2001 if segments[1] == 0x0db8 => "documentation",
        0x0100 if segments[1..4] == [0, 0, 0] => "discard-only",
        // The rest of ::/8 (not mapped, compatible, loopback or unspecified) is reserved.
        s if s & 0xff00 == 0 => "reserved",
        _ => return None,
    })
}

/// The IPv4 address an IPv6 one carries: mapped (`::ffff:a.b.c.d`, canonicalised before this),
/// compatible (`::a.b.c.d`), NAT64 (`64:ff9b::a.b.c.d`) or 6to4 (`2002:aabb:ccdd::/48`).
fn embedded_v4(address: Ipv6Addr) -> Option<Ipv4Addr> {
    let s = address.segments();
    let low = |hi: u16, lo: u16| Ipv4Addr::from((u32::from(hi) << 16) | u32::from(lo));
    match s {
        [0, 0, 0, 0, 0, 0, hi, lo] | [0, 0, 0, 0, 0, 0xffff, hi, lo] => Some(low(hi, lo)),
        [0x64, 0xff9b, 0, 0, 0, 0, hi, lo] => Some(low(hi, lo)),
        [0x2002, hi, lo, ..] => Some(low(hi, lo)),
        _ => None,
    }
}

/// The HTTP client's DNS resolver: a name's addresses, each checked against the policy, so that
/// the client connects only to checked addresses.
#[derive(Clone, Debug)]
pub struct CheckedResolver {
    pub policy: AddressPolicy,
}

impl reqwest::dns::Resolve for CheckedResolver {
    fn resolve(&self, name: reqwest::dns::Name) -> reqwest::dns::Resolving {
        let policy = self.policy.clone();
        let host = name.as_str().to_owned();
        Box::pin(async move {
            // Port 0: the client puts in the URL's port.
            let addresses = policy.resolve(&host, 0).await?;
            let addresses: reqwest::dns::Addrs = Box::new(addresses.into_iter());
            Ok(addresses)
        })
    }
}

/// The policy's refusal in an error chain (a request the resolver stopped), if there is one.
pub fn refusal_in<'a>(error: &'a (dyn std::error::Error + 'static)) -> Option<&'a OutboundError> {
    let mut source = Some(error);
    while let Some(e) = source {
        if let Some(refused) = e.downcast_ref::<OutboundError>() {
            return Some(refused);
        }
        source = e.source();
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ip(text: &str) -> IpAddr {
        text.parse().unwrap()
    }

    #[test]
    fn internal_addresses_are_named_and_public_ones_pass() {
        let internal = [
            ("127.0.0.1", "loopback"),
            ("127.255.0.9", "loopback"),
            ("0.0.0.0", "unspecified (0.0.0.0/8)"),
            ("10.1.2.3", "private"),
            ("172.16.0.1", "private"),
            ("172.31.255.255", "private"),
            ("192.168.1.1", "private"),
            ("169.254.169.254", "link-local"),
            ("100.64.0.1", "shared (CGNAT)"),
            ("100.127.255.254", "shared (CGNAT)"),
            ("224.0.0.1", "multicast"),
            ("255.255.255.255", "reserved or broadcast"),
            ("::1", "loopback"),
            ("::", "unspecified"),
            ("::ffff:127.0.0.1", "loopback"),
            ("::ffff:169.254.169.254", "link-local"),
            ("::127.0.0.1", "loopback"),
            ("64:ff9b::10.0.0.1", "private"),
            ("2002:7f00:1::", "loopback"),
            ("fc00::1", "unique-local"),
            ("fd12:3456::1", "unique-local"),
            ("fe80::1", "link-local"),
            ("fec0::1", "site-local"),
            ("ff02::1", "multicast"),
            ("2001:db8::1", "documentation"),
        ];
        for (address, kind) in internal {
            assert_eq!(internal_kind(ip(address)), Some(kind), "{address}");
        }
        for public in [
            "8.8.8.8",
            "1.1.1.1",
            "172.32.0.1",
            "100.128.0.1",
            "169.255.0.1",
            "2606:4700::1111",
            "::ffff:8.8.8.8",
            "64:ff9b::808:808",
        ] {
            assert_eq!(internal_kind(ip(public)), None, "{public}");
        }
    }

    #[test]
    fn allowed_ranges_admit_their_addresses_only() {
        let policy = AddressPolicy::allowing(["127.0.0.0/8", "::1", "10.0.0.0/24"]).unwrap();
        for admitted in [
            "127.0.0.1",
            "127.0.0.2",
            "::1",
            "::ffff:127.0.0.1",
            "10.0.0.7",
        ] {
            assert_eq!(policy.check(ip(admitted)), Ok(()), "{admitted}");
        }
        for refused in ["10.0.1.1", "169.254.169.254", "192.168.0.1", "fe80::1"] {
            assert!(policy.check(ip(refused)).is_err(), "{refused}");
        }
        let strict = AddressPolicy::default();
        assert_eq!(
            strict.check(ip("127.0.0.1")),
            Err(OutboundError::Internal {
                address: ip("127.0.0.1"),
                kind: "loopback"
            })
        );
        assert_eq!(strict.check(ip("8.8.4.4")), Ok(()));
        assert!(AddressPolicy::allowing(["10.0.0.0/33"]).is_err());
        assert!(AddressPolicy::allowing(["localhost"]).is_err());
    }

    #[tokio::test]
    async fn names_are_checked_by_every_address_they_resolve_to() {
        let strict = AddressPolicy::default();
        match strict.resolve("localhost", 80).await {
            Err(OutboundError::ResolvesInside { host, kind, .. }) => {
                assert_eq!(host, "localhost");
                assert_eq!(kind, "loopback");
            }
            other => panic!("localhost resolved to {other:?}"),
        }
        let loopback = AddressPolicy::allowing(["127.0.0.0/8", "::1"]).unwrap();
        let addresses = loopback.resolve("localhost", 8080).await.unwrap();
        assert!(addresses
            .iter()
            .all(|a| a.port() == 8080 && a.ip().is_loopback()));
        assert!(matches!(
            strict.resolve("no-such-host.invalid", 80).await,
            Err(OutboundError::Unresolved { .. })
        ));
    }
}
