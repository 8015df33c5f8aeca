// The service's REST API and event streams as the page uses them. Every call goes through
// `request`, which adds the bearer token when one is known and, on a 401, asks for the token
// once (the answer is kept in localStorage) and retries.

const TOKEN_KEY = 'phygap.token';

let tokenPrompt = null;

/** The stored token, or null. */
export function token() {
  return localStorage.getItem(TOKEN_KEY);
}

/** Headers that authenticate a request (empty without a token). */
export function authHeaders() {
  const t = token();
  return t ? { Authorization: `Bearer ${t}` } : {};
}

/** An error answered by the API: HTTP status, the API's error code and message. */
export class ApiError extends Error {
  constructor(status, code, message) {
    super(message);
    this.status = status;
    this.code = code;
  }
}

async function errorOf(response) {
  let code = 'http_' + response.status;
  let message = response.statusText || `HTTP ${response.status}`;
  try {
    const body = await response.json();
    if (body && body.error) {
      code = body.error.code;
      message = body.error.message;
    }
  } catch (_) {
    // Not JSON: keep the status text.
  }
  return new ApiError(response.status, code, message);
}

/** Shows the token dialog and resolves with what the user entered (one dialog at a time). */
function askToken(reason) {
  if (!tokenPrompt) {
    tokenPrompt = new Promise((resolve) => {
      const dialog = document.getElementById('token-dialog');
      const form = dialog.querySelector('form');
      const input = dialog.querySelector('input');
      dialog.querySelector('.reason').textContent = reason;
      input.value = '';
      form.onsubmit = (event) => {
        event.preventDefault();
        dialog.close();
        localStorage.setItem(TOKEN_KEY, input.value.trim());
        tokenPrompt = null;
        resolve();
      };
      dialog.showModal();
      input.focus();
    });
  }
  return tokenPrompt;
}

/** fetch() against the API with the token; asks for it on a 401 and retries. */
export async function request(path, options = {}) {
  for (;;) {
    const headers = { ...(options.headers || {}), ...authHeaders() };
    const response = await fetch(path, { ...options, headers });
    if (response.status !== 401) return response;
    const error = await errorOf(response);
    await askToken(token() ? 'The token was refused: ' + error.message : 'This server needs an access token.');
  }
}

/** A JSON call; throws ApiError unless the answer is 2xx. */
export async function json(path, options = {}) {
  const response = await request(path, options);
  if (!response.ok) throw await errorOf(response);
  return response.status === 204 ? null : response.json();
}

/** POSTs a JSON body. */
export function postJson(path, body, headers = {}) {
  return json(path, {
    method: 'POST',
    headers: { 'content-type': 'application/json', ...headers },
    body: JSON.stringify(body),
  });
}

/** An artifact's bytes as a Blob. */
export async function artifactBlob(jobId, name) {
  const response = await request(artifactUrl(jobId, name));
  if (!response.ok) throw await errorOf(response);
  return response.blob();
}

export function artifactUrl(jobId, name) {
  return `/v1/jobs/${encodeURIComponent(jobId)}/artifacts/${name}`;
}

/**
 * Uploads with XMLHttpRequest (fetch has no upload progress). `onProgress(fraction)` follows the
 * upload; resolves with the parsed JSON answer, rejects with ApiError.
 */
export function upload(path, body, onProgress, contentType) {
  return new Promise((resolve, reject) => {
    const send = () => {
      const xhr = new XMLHttpRequest();
      xhr.open('POST', path);
      if (contentType) xhr.setRequestHeader('content-type', contentType);
      const t = token();
      if (t) xhr.setRequestHeader('Authorization', `Bearer ${t}`);
      xhr.upload.onprogress = (e) => e.lengthComputable && onProgress(e.loaded / e.total);
      xhr.onerror = () => reject(new ApiError(0, 'network', 'the upload could not reach the server'));
      xhr.onload = async () => {
        let body = null;
        try {
          body = JSON.parse(xhr.responseText);
        } catch (_) {
          // An empty or non-JSON answer.
        }
        if (xhr.status === 401) {
          await askToken('This server needs an access token.');
          send();
        } else if (xhr.status >= 200 && xhr.status < 300) {
          resolve(body);
        } else {
          const err = body && body.error ? body.error : { code: 'http_' + xhr.status, message: xhr.statusText };
          reject(new ApiError(xhr.status, err.code, err.message));
        }
      };
      xhr.send(body);
    };
    send();
  });
}

/**
 * Follows a job's server-sent events. EventSource cannot send an Authorization header, so the
 * stream is read with fetch(). `onJob(job)` gets every event's job; the returned function stops.
 * The stream ends by itself after the job's `end` event; a dropped stream is reopened.
 */
export function followJob(jobId, onJob) {
  const controller = new AbortController();
  let ended = false;
  const run = async () => {
    while (!ended && !controller.signal.aborted) {
      try {
        const response = await request(`/v1/jobs/${encodeURIComponent(jobId)}/events`, {
          signal: controller.signal,
          headers: { accept: 'text/event-stream' },
        });
        if (!response.ok) throw await errorOf(response);
        const reader = response.body.pipeThrough(new TextDecoderStream()).getReader();
        let buffer = '';
        for (;;) {
          const { value, done } = await reader.read();
          if (done) break;
          buffer += value;
          let cut;
          while ((cut = buffer.indexOf('\n\n')) >= 0) {
            const block = buffer.slice(0, cut);
            buffer = buffer.slice(cut + 2);
            const event = parseEvent(block);
            if (event.data) onJob(JSON.parse(event.data));
            if (event.name === 'end') ended = true;
          }
        }
      } catch (error) {
        if (controller.signal.aborted) return;
        if (error instanceof ApiError && error.status === 404) return;
      }
      if (!ended) await new Promise((r) => setTimeout(r, 1000));
    }
  };
  run();
  return () => controller.abort();
}

/** One SSE block's event name and joined data lines. */
function parseEvent(block) {
  let name = 'message';
  const data = [];
  for (const line of block.split('\n')) {
    if (line.startsWith('event:')) name = line.slice(6).trim();
    else if (line.startsWith('data:')) data.push(line.slice(5).replace(/^ /, ''));
  }
  return { name, data: data.join('\n') };
}
