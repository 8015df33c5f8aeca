// Resumable capture uploads (POST /v1/uploads, PUT /v1/uploads/ID/parts/N, POST …/commit): an
// archive larger than one part goes up part by part, each with its SHA-256 in a Content-Digest
// header, and a part whose connection fails is sent again. The upload's id is kept in
// localStorage under the file's name, size and date, so choosing the same file again (after a
// dropped connection or a reload) sends only the parts the service lacks.

import { ApiError, json, postJson } from './api.js';

/** localStorage key of the part size (bytes), a setting the browser test lowers. */
const PART_BYTES_KEY = 'phygap.partBytes';
const DEFAULT_PART_BYTES = 32 << 20;
/** The service's smallest part. */
const MIN_PART_BYTES = 64 << 10;
/** Tries of one part before the upload gives up (waiting 0.5, 1, 2, 4 s between). */
const TRIES = 5;

function partBytes() {
  const chosen = Number(localStorage.getItem(PART_BYTES_KEY));
  return chosen >= MIN_PART_BYTES ? chosen : DEFAULT_PART_BYTES;
}

/** Whether `file` goes up in parts: larger than one, in a page that can hash (a secure context). */
export function goesInParts(file) {
  return file.size > partBytes() && Boolean(globalThis.crypto && crypto.subtle);
}

function uploadKey(file) {
  return `phygap.upload:${file.name}:${file.size}:${file.lastModified}`;
}

/** RFC 9530 `Content-Digest` of `bytes`: `sha-256=:BASE64:`. */
async function contentDigest(bytes) {
  const hash = new Uint8Array(await crypto.subtle.digest('SHA-256', bytes));
  return `sha-256=:${btoa(String.fromCharCode(...hash))}:`;
}

/** The file's unfinished upload if the service still has it open, else a new one. */
async function openUpload(file) {
  const known = localStorage.getItem(uploadKey(file));
  if (known) {
    try {
      const upload = await json(`/v1/uploads/${encodeURIComponent(known)}`);
      if (upload.state === 'open') return upload;
    } catch (_) {
      // Expired or deleted: start over.
    }
  }
  const upload = await postJson('/v1/uploads', { size: file.size, part_size: partBytes() });
  localStorage.setItem(uploadKey(file), upload.id);
  return upload;
}

/** Whether a failed part is worth sending again: no answer, a timeout or a server error. */
function transient(error) {
  return !(error instanceof ApiError) || error.status === 408 || error.status >= 500;
}

async function putPart(uploadId, index, blob) {
  const bytes = await blob.arrayBuffer();
  const digest = await contentDigest(bytes);
  for (let attempt = 1; ; attempt += 1) {
    try {
      return await json(`/v1/uploads/${encodeURIComponent(uploadId)}/parts/${index}`, {
        method: 'PUT',
        headers: { 'content-digest': digest },
        body: bytes,
      });
    } catch (error) {
      if (!transient(error) || attempt >= TRIES) throw error;
      await new Promise((resolve) => setTimeout(resolve, 250 * 2 ** attempt));
    }
  }
}

/**
 * Uploads `file` in parts and commits it; resolves with the capture (as POST /v1/captures
 * answers it) and the upload's id. `onProgress(fraction)` follows the bytes the service holds.
 */
export async function uploadInParts(file, onProgress) {
  const upload = await openUpload(file);
  const received = new Set(upload.received);
  let held = upload.received_bytes;
  onProgress(held / file.size);
  for (let index = 0; index < upload.parts; index += 1) {
    if (received.has(index)) continue;
    const start = index * upload.part_size;
    const part = file.slice(start, Math.min(start + upload.part_size, file.size));
    await putPart(upload.id, index, part);
    held += part.size;
    onProgress(held / file.size);
  }
  try {
    const capture = await json(`/v1/uploads/${encodeURIComponent(upload.id)}/commit`, { method: 'POST' });
    localStorage.removeItem(uploadKey(file));
    return { capture, uploadId: upload.id };
  } catch (error) {
    // A refused capture stays refused; only an incomplete or interrupted upload is resumed.
    if (!transient(error) && error.code !== 'upload_incomplete') localStorage.removeItem(uploadKey(file));
    throw error;
  }
}
