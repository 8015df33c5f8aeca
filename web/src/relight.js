// Relighting in the page: pick a bundled environment map or upload one (.hdr/.exr), rotate it,
// see the model under it in a live WebGL preview, and ask the service for its own relit renders
// (a relight job), shown next to the preview when the job has finished.

import { json, request, artifactBlob, followJob, ApiError } from './api.js';
import { loadModel } from './viewer.js';
import { parseEnvironment } from './scene.js';
import { el } from './format.js';

const BUNDLED = ['studio', 'sky', 'sunset'];

let view = null;
let stopFollowing = null;
const objectUrls = [];

export function leaveRelightPage() {
  if (stopFollowing) stopFollowing();
  stopFollowing = null;
  if (view) view.dispose();
  view = null;
  objectUrls.splice(0).forEach((u) => URL.revokeObjectURL(u));
}

export async function showRelightPage(root, jobId) {
  root.replaceChildren(document.getElementById('relight-page').content.cloneNode(true));
  root.querySelector('.job-title').textContent = jobId;
  const form = root.querySelector('#relight-form');
  const message = root.querySelector('#relight-message');
  for (const name of BUNDLED) form.elements.bundled.append(new Option(name, name));
  const job = await json(`/v1/jobs/${encodeURIComponent(jobId)}`);
  if (job.state !== 'succeeded') {
    message.textContent = `Job ${jobId} is ${job.state}; only a succeeded training job can be relit.`;
    return;
  }
  const modelInfo = JSON.parse(await (await artifactBlob(jobId, 'model.json')).text());
  const { modelView } = await loadModel(root.querySelector('#relight-canvas'), jobId, modelInfo);
  view = modelView;

  // The map the form would send now, as a File (bundled ones are fetched from the page's assets).
  let chosen = null;
  const preview = async (file) => {
    chosen = file;
    view.setEnvironment(parseEnvironment(await file.arrayBuffer()));
    view.setRotation(Number(form.elements.rotate.value));
  };
  const pickBundled = async () => {
    const name = form.elements.bundled.value;
    const response = await fetch(`/assets/envmaps/${name}.hdr`);
    await preview(new File([await response.blob()], `${name}.hdr`));
  };
  form.elements.bundled.addEventListener('change', () => {
    form.elements.file.value = '';
    pickBundled();
  });
  form.elements.file.addEventListener('change', () => {
    const file = form.elements.file.files[0];
    if (file) preview(file).catch((e) => (message.textContent = `Cannot read ${file.name}: ${e.message}`));
  });
  form.elements.rotate.addEventListener('input', () => {
    form.elements.rotate_out.value = `${form.elements.rotate.value}°`;
    view.setRotation(Number(form.elements.rotate.value));
  });
  form.addEventListener('submit', async (event) => {
    event.preventDefault();
    const body = new FormData();
    body.append('envmap', chosen, chosen.name);
    body.append('rotate_deg', form.elements.rotate.value);
    message.className = 'muted';
    try {
      const response = await request(`/v1/jobs/${encodeURIComponent(jobId)}/relight`, { method: 'POST', body });
      const answer = await response.json();
      if (!response.ok) throw new ApiError(response.status, answer.error.code, answer.error.message);
      follow(root, answer);
    } catch (error) {
      message.className = 'error';
      message.textContent = error.message;
    }
  });
  await pickBundled();
  root.querySelector('#relight-canvas').dataset.ready = 'true';
  const { jobs } = await json('/v1/jobs?limit=200');
  const latest = jobs.find((j) => j.kind === 'relight' && j.parent_job_id === jobId);
  if (latest) follow(root, latest);
}

/** Follows a relight job and shows its S0 renders when it has succeeded. */
function follow(root, job) {
  const message = root.querySelector('#relight-message');
  if (stopFollowing) stopFollowing();
  const show = (update) => {
    message.textContent = `Relight job ${update.id}: ${update.state}` + (update.stage ? ` (${update.stage})` : '') +
      (update.error ? ` — ${update.error}` : '');
    message.dataset.state = update.state;
    if (update.state === 'succeeded') showRenders(root.querySelector('#relit-renders'), update.id);
  };
  show(job);
  if (job.state === 'queued' || job.state === 'running') stopFollowing = followJob(job.id, show);
}

async function showRenders(box, relightId) {
  const { artifacts } = await json(`/v1/jobs/${encodeURIComponent(relightId)}/artifacts`);
  box.replaceChildren();
  for (const a of artifacts.filter((a) => /^s0\/\d+\.png$/.test(a.name))) {
    const figure = el('figure');
    const img = el('img');
    img.alt = `relit ${a.name}`;
    const url = URL.createObjectURL(await artifactBlob(relightId, a.name));
    objectUrls.push(url);
    img.src = url;
    figure.append(img, el('figcaption', null, `Service render, test view ${parseInt(a.name.slice(3), 10)}`));
    box.append(figure);
  }
}
