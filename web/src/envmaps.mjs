// Writes the environment maps bundled with the page (for relighting without a map of one's own)
// as Radiance .hdr files: node envmaps.mjs OUT_DIR. Procedural, so they need no download:
// "studio" (two softboxes over a dark room), "sky" (blue sky, a sun, brown ground) and
// "sunset" (a low warm sun). Lat-long, row 0 = straight up, as phygap and three.js read them.

import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

const WIDTH = 256;
const HEIGHT = 128;

/** Direction of texel (row, column): [up component, azimuth in radians]. */
function angles(row, column) {
  const theta = (Math.PI * (row + 0.5)) / HEIGHT;
  const phi = (2 * Math.PI * (column + 0.5)) / WIDTH;
  return [Math.cos(theta), phi];
}

/** Unit vector of (elevation cosine, azimuth) in a frame with +z up. */
function vector(up, phi) {
  const s = Math.sqrt(Math.max(0, 1 - up * up));
  return [s * Math.sin(phi), s * Math.cos(phi), up];
}

const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/** A disc light of `radiance` around `centre` (a unit vector) with angular radius `radius`. */
function disc(direction, centre, radius, radiance) {
  return dot(direction, centre) > Math.cos(radius) ? radiance : [0, 0, 0];
}

const MAPS = {
  studio(up, phi) {
    const d = vector(up, phi);
    const room = 0.03 + 0.05 * Math.max(0, up);
    const key = disc(d, vector(0.45, 0.8), 0.35, [6, 6, 5.6]);
    const rim = disc(d, vector(0.2, 3.6), 0.25, [2.5, 2.8, 3.2]);
    return [room + key[0] + rim[0], room + key[1] + rim[1], room + key[2] + rim[2]];
  },
  sky(up, phi) {
    const d = vector(up, phi);
    const sun = disc(d, vector(0.7, 2.2), 0.05, [400, 380, 340]);
    const base = up > 0 ? [0.35 + 0.4 * (1 - up), 0.55 + 0.3 * (1 - up), 1.0] : [0.25, 0.18, 0.1];
    return base.map((v, i) => v + sun[i]);
  },
  sunset(up, phi) {
    const d = vector(up, phi);
    const sun = disc(d, vector(0.08, 5.0), 0.06, [300, 150, 50]);
    const glow = Math.max(0, dot(d, vector(0.08, 5.0))) ** 8;
    const base = up > 0 ? [0.25 + 1.5 * glow, 0.2 + 0.6 * glow, 0.35 + 0.1 * glow] : [0.08, 0.06, 0.05];
    return base.map((v, i) => v + sun[i]);
  },
};

/** RGBE bytes of a linear RGB triple. */
function rgbe([r, g, b]) {
  const v = Math.max(r, g, b);
  if (v < 1e-32) return [0, 0, 0, 0];
  const e = Math.floor(Math.log2(v)) + 1;
  const scale = 256 / 2 ** e;
  return [Math.min(255, Math.floor(r * scale)), Math.min(255, Math.floor(g * scale)), Math.min(255, Math.floor(b * scale)), e + 128];
}

/** A Radiance file: header, then each scanline in the run-length format (literal runs only). */
function encodeHdr(pixel) {
  const header = `#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y ${HEIGHT} +X ${WIDTH}\n`;
  const bytes = [...Buffer.from(header, 'ascii')];
  for (let row = 0; row < HEIGHT; row++) {
    const line = [];
    for (let column = 0; column < WIDTH; column++) line.push(rgbe(pixel(...angles(row, column))));
    bytes.push(2, 2, WIDTH >> 8, WIDTH & 255);
    for (let channel = 0; channel < 4; channel++) {
      for (let start = 0; start < WIDTH; start += 128) {
        const count = Math.min(128, WIDTH - start);
        bytes.push(count);
        for (let i = start; i < start + count; i++) bytes.push(line[i][channel]);
      }
    }
  }
  return Buffer.from(bytes);
}

const out = process.argv[2];
mkdirSync(out, { recursive: true });
for (const [name, pixel] of Object.entries(MAPS)) {
  writeFileSync(join(out, `${name}.hdr`), encodeHdr(pixel));
}
