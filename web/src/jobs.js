// The "Captures and jobs" page: drop a capture archive (upload progress, the validation report
// when it is rejected), start a training job with the common settings, and the list of jobs with
// their live state, stage, loss curve and test PSNR from each job's event stream, and cancel.

import { json, postJson, upload, followJob, ApiError } from './api.js';
import { goesInParts, uploadInParts } from './resumable.js';
import { drawLossCurve } from './chart.js';
import { el, duration, size, problemsOf } from './format.js';

/** Event streams of the jobs shown, by job id (stopped when the page is left). */
const streams = new Map();
/** Loss points per job id, kept while the page is open. */
const curves = new Map();

export function leaveJobsPage() {
  for (const stop of streams.values()) stop();
  streams.clear();
}

export async function showJobsPage(root) {
  root.replaceChildren(document.getElementById('jobs-page').content.cloneNode(true));
  setUpDropZone(root);
  root.querySelector('#job-form').addEventListener('submit', (event) => {
    event.preventDefault();
    submitJob(root);
  });
  await refreshJobs(root);
}

function setUpDropZone(root) {
  const zone = root.querySelector('#drop-zone');
  const input = root.querySelector('#capture-file');
  zone.addEventListener('dragover', (event) => {
    event.preventDefault();
    zone.classList.add('over');
  });
  zone.addEventListener('dragleave', () => zone.classList.remove('over'));
  zone.addEventListener('drop', (event) => {
    event.preventDefault();
    zone.classList.remove('over');
    const file = event.dataTransfer.files[0];
    if (file) uploadCapture(root, file);
  });
  input.addEventListener('change', () => input.files[0] && uploadCapture(root, input.files[0]));
}

async function uploadCapture(root, file) {
  const bar = root.querySelector('#upload-progress');
  const report = root.querySelector('#upload-report');
  bar.hidden = false;
  bar.value = 0;
  report.replaceChildren(el('p', 'muted', `Uploading ${file.name} (${size(file.size)})…`));
  const type = /\.tar$/i.test(file.name) ? 'application/x-tar' : 'application/zip';
  const progress = (f) => (bar.value = f);
  delete report.dataset.uploadId;
  try {
    let capture;
    if (goesInParts(file)) {
      // Large archives go up in parts that survive a dropped connection.
      const done = await uploadInParts(file, progress);
      capture = done.capture;
      report.dataset.uploadId = done.uploadId;
    } else {
      capture = await upload('/v1/captures', file, progress, type);
    }
    bar.value = 1;
    report.replaceChildren(captureSummary(capture));
    root.querySelector('#capture-id').value = capture.id;
  } catch (error) {
    bar.hidden = true;
    report.replaceChildren(rejection(error));
  }
}

function captureSummary(capture) {
  const box = el('div', 'accepted');
  box.append(el('p', null, `Capture ${capture.id} accepted: ${capture.views} views (${capture.kinds.join(', ')}).`));
  if (capture.warnings.length) {
    const list = el('ul', 'warnings');
    capture.warnings.forEach((w) => list.append(el('li', null, w)));
    box.append(el('p', null, 'Warnings:'), list);
  }
  return box;
}

/** The validation report of a rejected upload: every problem on its own line. */
function rejection(error) {
  const box = el('div', 'rejected');
  const code = error instanceof ApiError ? error.code : 'error';
  box.append(el('p', null, `Rejected (${code}):`));
  const list = el('ul', 'problems');
  const problems = code === 'invalid_capture' ? problemsOf(error.message) : [error.message];
  problems.forEach((p) => list.append(el('li', null, p)));
  box.append(list);
  return box;
}

/** The config object of the job form: the common settings plus the optional extra JSON. */
function formConfig(root) {
  const form = root.querySelector('#job-form');
  const config = {};
  const extra = form.elements.extra.value.trim();
  if (extra) Object.assign(config, JSON.parse(extra));
  const iterations = form.elements.iterations.value.trim();
  if (iterations) config.iterations = Number(iterations);
  config.mode = form.elements.mode.value;
  config.backend = form.elements.backend.value;
  config.gridmap = form.elements.gridmap.checked;
  return config;
}

async function submitJob(root) {
  const message = root.querySelector('#job-message');
  const captureId = root.querySelector('#capture-id').value.trim();
  message.className = 'muted';
  try {
    if (!captureId) throw new Error('upload a capture first (or paste a capture id)');
    const job = await postJson('/v1/jobs', { capture_id: captureId, config: formConfig(root) });
    message.textContent = `Job ${job.id} queued.`;
    await refreshJobs(root);
  } catch (error) {
    message.className = 'error';
    message.textContent = error instanceof SyntaxError ? `extra settings: ${error.message}` : error.message;
  }
}

/** The loss curve a training job's runs recorded so far (GET /v1/jobs/{id}/progress, page by page). */
async function loadHistory(jobId) {
  const points = [];
  let from = 0;
  for (;;) {
    const page = await json(`/v1/jobs/${jobId}/progress?from=${from}`);
    for (const { event } of page.events) {
      if (event.type === 'step') points.push([event.iteration, event.loss]);
    }
    if (!page.events.length || page.next === from) break;
    from = page.next;
  }
  curves.set(jobId, points);
}

async function refreshJobs(root) {
  const list = root.querySelector('#job-list');
  const { jobs } = await json('/v1/jobs?limit=50');
  await Promise.all(jobs.filter((job) => job.kind === 'train').map((job) => loadHistory(job.id)));
  leaveJobsPage();
  list.replaceChildren();
  if (!jobs.length) list.append(el('p', 'muted', 'No jobs yet.'));
  for (const job of jobs) {
    const card = jobCard(job);
    list.append(card);
    if (job.state === 'queued' || job.state === 'running') {
      streams.set(job.id, followJob(job.id, (update) => updateCard(card, update)));
    }
  }
}

function jobCard(job) {
  const card = el('article', 'job');
  card.dataset.jobId = job.id;
  const head = el('header');
  const title = el('a', 'job-id', job.id);
  title.href = job.kind === 'relight' ? `#/jobs/${job.parent_job_id}/relight` : `#/jobs/${job.id}`;
  head.append(title, el('span', 'job-kind', job.kind), el('span', 'job-state'));
  const cancel = el('button', 'cancel', 'Cancel');
  cancel.type = 'button';
  cancel.addEventListener('click', async () => {
    cancel.disabled = true;
    try {
      updateCard(card, await postJson(`/v1/jobs/${job.id}/cancel`, {}));
    } catch (error) {
      card.querySelector('.job-error').textContent = error.message;
    }
  });
  head.append(cancel);
  const progress = el('progress', 'job-progress');
  progress.max = 1;
  const canvas = el('canvas', 'loss-curve');
  card.append(head, el('div', 'job-stats'), progress, canvas, el('p', 'job-error'));
  updateCard(card, job);
  return card;
}

/** Shows a job's latest state on its card and adds its loss to the curve. */
function updateCard(card, job) {
  const state = card.querySelector('.job-state');
  state.textContent = job.state;
  state.dataset.state = job.state;
  const live = job.state === 'queued' || job.state === 'running';
  card.querySelector('.cancel').hidden = !live || job.cancel_requested;
  const stats = card.querySelector('.job-stats');
  const parts = [];
  if (job.stage) parts.push(`stage ${job.stage}`);
  if (job.kind === 'train') parts.push(`iteration ${job.iteration} / ${job.iterations}`);
  if (job.test_psnr != null) parts.push(`test PSNR ${job.test_psnr.toFixed(2)} dB`);
  if (live && job.eta_seconds != null) parts.push(`ETA ${duration(job.eta_seconds)}`);
  if (job.backend) parts.push(job.backend);
  if (job.resolution) parts.push(job.resolution);
  if (job.peak_rss_bytes != null) parts.push(`${size(job.peak_rss_bytes)} peak memory`);
  stats.textContent = parts.join(' · ');
  const progress = card.querySelector('.job-progress');
  progress.value = job.iterations ? job.iteration / job.iterations : job.state === 'succeeded' ? 1 : 0;
  card.querySelector('.job-error').textContent = job.error || job.warning || '';
  if (job.kind === 'train') {
    const points = curves.get(job.id) || [];
    const total = job.losses && job.losses.total;
    if (total != null && (!points.length || points[points.length - 1][0] !== job.iteration)) {
      points.push([job.iteration, total]);
    }
    curves.set(job.id, points);
    const canvas = card.querySelector('.loss-curve');
    // The curve starts from the job's recorded history, so an ended job shows it too.
    canvas.hidden = !live && points.length < 2;
    if (!canvas.hidden) drawLossCurve(canvas, points, job.iterations);
  } else {
    card.querySelector('.loss-curve').hidden = true;
  }
}
