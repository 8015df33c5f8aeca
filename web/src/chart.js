// A small line chart on a 2D canvas: the loss curve of a job (log scale), drawn from the
// (iteration, value) points collected from its event stream.

/** Draws `points` ([iteration, value] pairs, value > 0) into `canvas` on a log10 axis. */
export function drawLossCurve(canvas, points, iterations) {
  const ctx = canvas.getContext('2d');
  const ratio = window.devicePixelRatio || 1;
  const width = canvas.clientWidth || 300;
  const height = canvas.clientHeight || 80;
  canvas.width = Math.round(width * ratio);
  canvas.height = Math.round(height * ratio);
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  ctx.clearRect(0, 0, width, height);
  const usable = points.filter(([, v]) => v > 0 && Number.isFinite(v));
  ctx.fillStyle = '#8a94a6';
  ctx.font = '11px system-ui, sans-serif';
  if (usable.length < 2) {
    ctx.fillText('loss curve: waiting for steps…', 6, height / 2);
    return;
  }
  const logs = usable.map(([, v]) => Math.log10(v));
  const lo = Math.min(...logs);
  const hi = Math.max(...logs);
  const span = hi - lo || 1;
  const maxIt = Math.max(iterations || 0, usable[usable.length - 1][0]) || 1;
  const pad = 4;
  const x = (it) => pad + ((width - 2 * pad) * it) / maxIt;
  const y = (l) => height - pad - ((height - 2 * pad - 12) * (l - lo)) / span;
  ctx.strokeStyle = '#4f8cff';
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  usable.forEach(([it], i) => (i === 0 ? ctx.moveTo(x(it), y(logs[i])) : ctx.lineTo(x(it), y(logs[i]))));
  ctx.stroke();
  const last = usable[usable.length - 1][1];
  ctx.fillText(`loss ${last.toPrecision(3)} (log scale)`, 6, 11);
}
