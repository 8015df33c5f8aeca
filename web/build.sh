#!/usr/bin/env bash
# Builds the web page into web/dist, which is committed and embedded in phygap-api by
# api/src/http/web_page.rs (cargo builds need no Node.js). Run after changing anything under web/src:
#   web/build.sh          (needs Node.js ≥ 18 and npm; installs the pinned packages from package-lock.json)
# Output: dist/index.html, dist/assets/app.js (the page and three.js, bundled by esbuild),
# dist/assets/app.css, dist/assets/envmaps/*.hdr (bundled environment maps for relighting).
set -euo pipefail
cd "$(dirname "$0")"
npm ci --no-audit --no-fund --loglevel=error
rm -rf dist
mkdir -p dist/assets/envmaps
node_modules/.bin/esbuild src/main.js --bundle --minify --format=esm --target=es2020 \
  --legal-comments=eof --outfile=dist/assets/app.js
cp src/index.html dist/index.html
cp src/style.css dist/assets/app.css
node src/envmaps.mjs dist/assets/envmaps
ls -l dist dist/assets dist/assets/envmaps
