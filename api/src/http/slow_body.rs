//! Request bodies that must keep moving: every window of [`HttpLimits::body_window`] must bring
//! [`HttpLimits::min_body_bytes`] (a client sending ten bytes a second, or nothing, is cut off
//! after one window instead of holding a connection and an upload slot for hours). tower-http's
//! body timeout resets on every frame, so a trickle of one-byte frames would pass it; this counts
//! bytes. A body that falls behind ends with [`BodyTooSlow`], which the upload handlers answer
//! with 408 `request_timeout`.

use std::future::Future;
use std::pin::Pin;
use std::task::{Context, Poll};
use std::time::Duration;

use axum::body::{Body, Bytes};
use axum::extract::Request;
use axum::middleware::Next;
use axum::response::Response;
use http_body::{Body as HttpBody, Frame, SizeHint};
use tokio::time::{Instant, Sleep};

use crate::jobs::settings::HttpLimits;

/// The error a body that fell below the minimum rate ends with.
#[derive(Debug, thiserror::Error)]
#[error(
    "the request body arrived slower than {min_bytes} bytes in {window:?}; the upload was cut off"
)]
pub struct BodyTooSlow {
    pub min_bytes: u64,
    pub window: Duration,
}

/// A request body checked against a minimum rate.
pub struct MinRateBody {
    inner: Body,
    min_bytes: u64,
    window: Duration,
    /// Bytes received in the current window.
    received: u64,
    /// The end of the current window.
    deadline: Pin<Box<Sleep>>,
}

impl MinRateBody {
    pub fn new(inner: Body, limits: &HttpLimits) -> Self {
        MinRateBody {
            inner,
            min_bytes: limits.min_body_bytes,
            window: limits.body_window,
            received: 0,
            deadline: Box::pin(tokio::time::sleep(limits.body_window)),
        }
    }

    fn too_slow(&self) -> axum::Error {
        axum::Error::new(BodyTooSlow {
            min_bytes: self.min_bytes,
            window: self.window,
        })
    }
}

impl HttpBody for MinRateBody {
    type Data = Bytes;
    type Error = axum::Error;

    fn poll_frame(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
    ) -> Poll<Option<Result<Frame<Bytes>, axum::Error>>> {
        let this = self.get_mut();
        let polled = Pin::new(&mut this.inner).poll_frame(cx);
        if let Poll::Ready(Some(Ok(frame))) = &polled {
            if let Some(data) = frame.data_ref() {
                this.received += data.len() as u64;
            }
        }
        if let Poll::Ready(None | Some(Err(_))) = polled {
            return polled;
        }
        // A window that ended: short of the minimum, the body is cut off; else a new one starts.
        while this.deadline.as_mut().poll(cx).is_ready() {
            if this.received < this.min_bytes {
                return Poll::Ready(Some(Err(this.too_slow())));
            }
            this.received = 0;
            let next = this.deadline.deadline() + this.window;
            this.deadline.as_mut().reset(next.max(Instant::now()));
        }
        polled
    }

    fn is_end_stream(&self) -> bool {
        self.inner.is_end_stream()
    }

    fn size_hint(&self) -> SizeHint {
        self.inner.size_hint()
    }
}

/// Middleware: every request's body becomes a [`MinRateBody`].
pub async fn enforce_min_rate(limits: HttpLimits, request: Request, next: Next) -> Response {
    let request = request.map(|body| Body::new(MinRateBody::new(body, &limits)));
    next.run(request).await
}

/// Whether a body-read error is a [`BodyTooSlow`] cut-off.
pub fn is_too_slow(error: &(dyn std::error::Error + 'static)) -> bool {
    let mut current = Some(error);
    while let Some(e) = current {
        if e.is::<BodyTooSlow>() {
            return true;
        }
        current = e.source();
    }
    false
}
