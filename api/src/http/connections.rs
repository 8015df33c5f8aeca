//! The HTTP/1.1 listener, with the limits a public server needs: at most
//! [`HttpLimits::max_connections`] connections at once (past it, new ones wait in the kernel's
//! backlog until one closes), at most [`HttpLimits::max_connections_per_client`] of them from one
//! client address (past it, that client's new connections are closed at once, so one client
//! cannot hold every slot and keep others, `/healthz` among them, waiting), a connection that sends no complete request head within
//! [`HttpLimits::header_timeout`] is closed (whether it trickles a header a byte at a time or sits
//! idle between requests), and request bodies must keep up a minimum rate ([`crate::http::slow_body`]).
//! Oversized request lines and headers are answered by [`crate::http::error::oversized_requests`] in the
//! JSON error shape; hyper's own buffer (well above those limits) only meets requests that are
//! not HTTP at all, which it answers with a bare 400 and a closed connection.
//!
//! Threading: one tokio task accepts; each connection is served by a task of its own.

use std::collections::HashMap;
use std::net::IpAddr;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use hyper_util::rt::{TokioIo, TokioTimer};
use hyper_util::server::graceful::GracefulShutdown;
use hyper_util::service::TowerToHyperService;
use tokio::net::TcpListener;
use tokio::sync::Semaphore;
use tokio_util::sync::CancellationToken;

use crate::jobs::settings::HttpLimits;

/// hyper's read buffer: room for the largest head [`HttpLimits`] admits, several times over, so
/// that the service, not hyper, answers an oversized one.
const HYPER_BUFFER_BYTES: usize = 256 << 10;

/// hyper's own cap on header fields (ours, [`HttpLimits::max_headers`], is checked below it).
const HYPER_MAX_HEADERS: usize = 1000;

/// How long to pause accepting after the process ran out of file descriptors.
const ACCEPT_BACKOFF: Duration = Duration::from_millis(100);

/// How many connections each client address holds open.
#[derive(Default)]
struct ClientCounts {
    open: Mutex<HashMap<IpAddr, usize>>,
}

impl ClientCounts {
    /// A slot for one more connection of `client`, unless it already holds `cap`.
    fn take(self: &Arc<Self>, client: IpAddr, cap: usize) -> Option<ClientSlot> {
        let mut open = self
            .open
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        let count = open.entry(client).or_default();
        if *count >= cap.max(1) {
            return None;
        }
        *count += 1;
        Some(ClientSlot {
            counts: self.clone(),
            client,
        })
    }
}

/// One open connection of a client, given back when dropped.
struct ClientSlot {
    counts: Arc<ClientCounts>,
    client: IpAddr,
}

impl Drop for ClientSlot {
    fn drop(&mut self) {
        let mut open = self
            .counts
            .open
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        if let Some(count) = open.get_mut(&self.client) {
            *count -= 1;
            if *count == 0 {
                open.remove(&self.client);
            }
        }
    }
}

/// Serves `app` on `listener` until `stop` is cancelled; then stops accepting and waits for the
/// open connections' requests to finish.
pub async fn serve(
    listener: TcpListener,
    app: axum::Router,
    limits: HttpLimits,
    stop: CancellationToken,
) {
    let slots = Arc::new(Semaphore::new(limits.max_connections.max(1)));
    let clients = Arc::new(ClientCounts::default());
    let graceful = GracefulShutdown::new();
    let mut http = hyper::server::conn::http1::Builder::new();
    http.timer(TokioTimer::new())
        .header_read_timeout(limits.header_timeout)
        .max_buf_size(HYPER_BUFFER_BYTES)
        .max_headers(HYPER_MAX_HEADERS);
    loop {
        let slot = tokio::select! {
            slot = slots.clone().acquire_owned() => match slot {
                Ok(slot) => slot,
                Err(_) => break,
            },
            _ = stop.cancelled() => break,
        };
        let (stream, client) = tokio::select! {
            accepted = listener.accept() => match accepted {
                Ok((stream, peer)) => (stream, peer.ip().to_canonical()),
                Err(e) => {
                    // EMFILE and the like: wait for descriptors to free up, keep serving.
                    tracing::warn!(error = %e, "accepting a connection failed");
                    tokio::time::sleep(ACCEPT_BACKOFF).await;
                    continue;
                }
            },
            _ = stop.cancelled() => break,
        };
        let Some(client_slot) = clients.take(client, limits.max_connections_per_client) else {
            tracing::debug!(%client, "a client over its connection limit: closed");
            drop(stream);
            continue;
        };
        let connection =
            http.serve_connection(TokioIo::new(stream), TowerToHyperService::new(app.clone()));
        let connection = graceful.watch(connection);
        tokio::spawn(async move {
            if let Err(e) = connection.await {
                tracing::debug!(error = %e, "connection ended with an error");
            }
            drop(client_slot);
            drop(slot);
        });
    }
    graceful.shutdown().await;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_client_holds_at_most_its_cap_and_gets_slots_back() {
        let counts = Arc::new(ClientCounts::default());
        let a: IpAddr = "127.0.0.2".parse().unwrap();
        let b: IpAddr = "127.0.0.1".parse().unwrap();
        let held: Vec<ClientSlot> = (0..3).map(|_| counts.take(a, 3).unwrap()).collect();
        assert!(counts.take(a, 3).is_none(), "a fourth of the same client");
        let other = counts.take(b, 3);
        assert!(other.is_some(), "another client is not held back");
        drop(held);
        assert!(
            counts.take(a, 3).is_some(),
            "slots come back when connections close"
        );
        drop(other);
        assert!(
            counts.open.lock().unwrap().is_empty(),
            "every slot was given back"
        );
    }
}
