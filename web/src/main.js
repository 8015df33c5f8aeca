// Entry point of the phygap web page: a hash router over its three pages —
// #/ (captures and jobs), #/jobs/ID (result viewer), #/jobs/ID/relight (relighting).

import { showJobsPage, leaveJobsPage } from './jobs.js';
import { showViewerPage, leaveViewerPage } from './viewer.js';
import { showRelightPage, leaveRelightPage } from './relight.js';
import { el } from './format.js';

function leaveAll() {
  leaveJobsPage();
  leaveViewerPage();
  leaveRelightPage();
}

function navigation(jobId) {
  const nav = document.getElementById('nav');
  nav.replaceChildren();
  const link = (href, text) => {
    const a = el('a', location.hash === href ? 'current' : null, text);
    a.href = href;
    nav.append(a);
  };
  link('#/', 'Captures & jobs');
  if (jobId) {
    link(`#/jobs/${jobId}`, 'Result');
    link(`#/jobs/${jobId}/relight`, 'Relight');
  }
}

async function route() {
  leaveAll();
  const root = document.getElementById('page');
  const match = location.hash.match(/^#\/jobs\/([A-Za-z0-9_-]+)(\/relight)?$/);
  navigation(match && match[1]);
  try {
    if (!match) await showJobsPage(root);
    else if (match[2]) await showRelightPage(root, match[1]);
    else await showViewerPage(root, match[1]);
  } catch (error) {
    root.append(el('p', 'error page-error', error.message));
  }
}

window.addEventListener('hashchange', route);
route();
