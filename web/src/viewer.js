// The result viewer of a trained job: the mesh with its learned materials under the learned
// environment map (WebGL, orbit controls), or the exported glTF (model.glb) under the same map,
// the learned polarizer angles, metrics and downloads, and each test view's captured images
// beside the model's renders (S0, DoLP, AoLP).

import { json, request, artifactBlob, artifactUrl } from './api.js';
import { ModelView, parseMaterialMesh, parseEnvironment, parseGltf } from './scene.js';
import { el, size } from './format.js';

let view = null;
const objectUrls = [];

export function leaveViewerPage() {
  if (view) view.dispose();
  view = null;
  objectUrls.splice(0).forEach((u) => URL.revokeObjectURL(u));
}

/** An <img> of a blob fetched with the token (an <img src> cannot send one). */
async function imageOf(blobPromise, alt) {
  const img = el('img');
  img.alt = alt;
  try {
    const url = URL.createObjectURL(await blobPromise);
    objectUrls.push(url);
    img.src = url;
  } catch (error) {
    const missing = el('p', 'muted', `${alt}: ${error.message}`);
    return missing;
  }
  return img;
}

async function bytes(path) {
  const response = await request(path);
  if (!response.ok) throw new Error(`${path}: HTTP ${response.status}`);
  return response.arrayBuffer();
}

/** Loads the model into a ModelView on `canvas`: world up, environment, material mesh. */
export async function loadModel(canvas, jobId, modelInfo) {
  const modelView = new ModelView(canvas);
  modelView.setWorldUp(modelInfo.world_up);
  const [envmap, mesh] = await Promise.all([
    bytes(artifactUrl(jobId, 'envmap.exr')),
    bytes(`/v1/jobs/${encodeURIComponent(jobId)}/material-mesh`),
  ]);
  modelView.setEnvironment(parseEnvironment(envmap));
  const geometry = parseMaterialMesh(mesh);
  modelView.setMesh(geometry);
  modelView.fit();
  return { modelView, geometry };
}

function facts(list, entries) {
  list.replaceChildren();
  for (const [name, value] of entries) list.append(el('dt', null, name), el('dd', null, value));
}

/** Median and range of a per-vertex attribute. */
function spread(attribute) {
  const values = Array.from(attribute.array).sort((a, b) => a - b);
  const at = (q) => values[Math.min(values.length - 1, Math.floor(q * values.length))];
  return `${at(0.5).toFixed(2)} (5–95%: ${at(0.05).toFixed(2)}–${at(0.95).toFixed(2)})`;
}

export async function showViewerPage(root, jobId) {
  root.replaceChildren(document.getElementById('viewer-page').content.cloneNode(true));
  root.querySelector('.job-title').textContent = jobId;
  const job = await json(`/v1/jobs/${encodeURIComponent(jobId)}`);
  const summary = root.querySelector('.job-summary');
  summary.textContent = `${job.state} · ${job.iteration} / ${job.iterations} iterations` +
    (job.test_psnr != null ? ` · test PSNR ${job.test_psnr.toFixed(2)} dB` : '');
  summary.dataset.state = job.state;
  if (job.state !== 'succeeded') {
    summary.textContent += ' — the viewer opens once the job has succeeded.';
    return;
  }
  const { artifacts } = await json(`/v1/jobs/${encodeURIComponent(jobId)}/artifacts`);
  const names = artifacts.map((a) => a.name);
  const [modelInfo, metrics] = await Promise.all([
    artifactBlob(jobId, 'model.json').then((b) => b.text()).then(JSON.parse),
    names.includes('metrics.json') ? artifactBlob(jobId, 'metrics.json').then((b) => b.text()).then(JSON.parse) : {},
  ]);
  const angles = Object.entries(modelInfo.polarizer_angles_deg || {});
  facts(root.querySelector('#polarizer-facts'), angles.length
    ? angles.map(([group, deg]) => [group, `${deg.toFixed(1)}°`])
    : [['–', modelInfo.mode === 'partial' ? 'none learned' : `none to learn (${modelInfo.mode} mode)`]]);
  const shown = ['psnr', 'ssim', 'normal_mae_deg', 'aolp_mae_deg', 'dolp_mae', 'num_surfels', 'train_seconds'];
  facts(root.querySelector('#metric-facts'), shown
    .filter((k) => metrics[k] != null)
    .map((k) => [k, typeof metrics[k] === 'number' && !Number.isInteger(metrics[k]) ? metrics[k].toFixed(3) : String(metrics[k])]));
  const downloads = root.querySelector('#downloads');
  for (const a of artifacts.filter((a) => !a.name.startsWith('renders/'))) {
    const link = el('a', null, `${a.name} (${size(a.size)})`);
    link.href = '#';
    link.addEventListener('click', async (event) => {
      event.preventDefault();
      const url = URL.createObjectURL(await artifactBlob(jobId, a.name));
      const save = Object.assign(document.createElement('a'), { href: url, download: a.name });
      save.click();
      setTimeout(() => URL.revokeObjectURL(url), 10000);
    });
    const item = el('li');
    item.append(link);
    downloads.append(item);
  }
  const relight = el('a', 'button', 'Relight this model');
  relight.href = `#/jobs/${jobId}/relight`;
  downloads.after(relight);
  showComparisons(root.querySelector('#comparisons'), jobId, names);
  const { modelView, geometry } = await loadModel(root.querySelector('#viewer-canvas'), jobId, modelInfo);
  view = modelView;
  const colors = geometry.getAttribute('color');
  facts(root.querySelector('#material-facts'), [
    ['vertices', String(geometry.getAttribute('position').count)],
    ['albedo (mean, linear)', colors ? meanColor(colors) : '–'],
    ['roughness', spread(geometry.getAttribute('aRoughness'))],
    ['IoR', spread(geometry.getAttribute('aIor'))],
  ]);
  root.querySelector('#viewer-canvas').dataset.ready = 'true';
  if (names.includes('model.glb')) gltfToggle(root, jobId, modelView);
}

/**
 * The "Material mesh | glTF" switch under the canvas. The first switch to glTF downloads
 * model.glb and loads it with three.js's GLTFLoader (base colour, metallic-roughness and normal
 * textures, or COLOR_0 and a roughness ramp in the vertex form; KHR_materials_ior) and adds the material's one IoR to the facts; the
 * canvas's data-shown says what is drawn, data-gltf-vertices how many vertices the glTF has.
 */
function gltfToggle(root, jobId, modelView) {
  const box = root.querySelector('#view-toggle');
  const canvas = root.querySelector('#viewer-canvas');
  const buttons = [...box.querySelectorAll('button')];
  let loading = null;
  canvas.dataset.shown = 'mesh';
  box.hidden = false;
  const select = async (which) => {
    if (which === 'gltf' && !loading) {
      loading = bytes(artifactUrl(jobId, 'model.glb')).then(parseGltf).then((scene) => {
        modelView.setGltf(scene);
        let vertices = 0;
        let ior = null;
        scene.traverse((node) => {
          if (!node.isMesh) return;
          vertices += node.geometry.getAttribute('position').count;
          ior = node.material.ior;
        });
        canvas.dataset.gltfVertices = String(vertices);
        if (ior != null) {
          root.querySelector('#material-facts').append(el('dt', null, 'glTF IoR'), el('dd', 'gltf-ior', ior.toFixed(3)));
        }
      });
    }
    try {
      if (which === 'gltf') await loading;
    } catch (error) {
      loading = null;
      box.append(el('p', 'muted', `model.glb: ${error.message}`));
      return;
    }
    if (view !== modelView) return;
    modelView.showGltf(which === 'gltf');
    for (const b of buttons) b.setAttribute('aria-pressed', String(b.dataset.view === which));
    canvas.dataset.shown = which;
  };
  for (const b of buttons) b.addEventListener('click', () => select(b.dataset.view));
}

function meanColor(colors) {
  const sum = [0, 0, 0];
  for (let i = 0; i < colors.count; i++) {
    sum[0] += colors.getX(i);
    sum[1] += colors.getY(i);
    sum[2] += colors.getZ(i);
  }
  return sum.map((s) => (s / colors.count).toFixed(2)).join(', ');
}

/** Per test view: captured S0 | rendered S0, captured DoLP | rendered, captured AoLP | rendered. */
async function showComparisons(box, jobId, names) {
  const views = names.filter((n) => /^renders\/s0\/\d+\.png$/.test(n)).map((n) => n.split('/').pop());
  if (!views.length) {
    box.append(el('p', 'muted', 'This job has no renders of test views.'));
    return;
  }
  for (const file of views) {
    const row = el('div', 'comparison');
    row.append(el('h3', null, `Test view ${parseInt(file, 10)}`));
    const grid = el('div', 'pairs');
    for (const kind of ['s0', 'dolp', 'aolp']) {
      if (!names.includes(`renders/${kind}/${file}`)) continue;
      const pair = el('figure', 'pair');
      const captured = request(`/v1/jobs/${encodeURIComponent(jobId)}/ground-truth/${kind}/${file}`).then(async (r) => {
        if (!r.ok) throw new Error((await r.json()).error.message);
        return r.blob();
      });
      pair.append(
        await imageOf(captured, `captured ${kind}`),
        await imageOf(artifactBlob(jobId, `renders/${kind}/${file}`), `rendered ${kind}`),
        el('figcaption', null, `${kind.toUpperCase()}: captured | rendered`),
      );
      grid.append(pair);
    }
    row.append(grid);
    box.append(row);
  }
}
