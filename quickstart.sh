#!/usr/bin/env bash
# The main job in one command: build everything, render a sample capture with the project's own
# renderer, start the reconstruction service (embedded SQLite store under ./phygap-data), upload the
# capture, train it, and print a summary (state, test PSNR, time, the artifacts, the page's
# address). The service keeps running afterwards (Ctrl-C stops it), and its web page (the jobs, the
# reconstructed object in 3D, relighting) is at the address printed last.
#
# Settings (environment): PHYGAP_PORT (8080), PHYGAP_DATA_DIR (./phygap-data),
# PHYGAP_QUICKSTART_ITERATIONS (default: the default training schedule's).
set -euo pipefail
cd "$(dirname "$0")"
port=${PHYGAP_PORT:-8080}
data=${PHYGAP_DATA_DIR:-./phygap-data}
iterations=${PHYGAP_QUICKSTART_ITERATIONS:-}
base="http://127.0.0.1:$port"

started=$SECONDS
cargo build --release --workspace --bins
bin=${CARGO_TARGET_DIR:-target}/release

mkdir -p "$data"
sample="$data/sample-capture"
rm -rf "$sample"
"$bin/phygap" synth --out "$sample" --shape sphere --views 24 --size 96
(cd "$sample" && tar -cf ../sample-capture.tar -- *)

# The service's log goes to a file, so that its lines do not break the progress line below.
log="$data/service.log"
"$bin/phygap-api" serve --bind "127.0.0.1:$port" --data-dir "$data" >"$log" 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null || true' EXIT INT TERM
up=
for _ in $(seq 1 100); do
  curl -fsS "$base/healthz" >/dev/null 2>&1 && { up=1; break; }
  kill -0 "$server" 2>/dev/null || break
  sleep 0.2
done
if [ -z "$up" ]; then
  echo "the service did not start; its log ($log) ends:" >&2
  tail -n 20 "$log" >&2
  exit 1
fi
echo "service started at $base; its log: $log (tail -f it to follow)"

json_field() { sed -n "s/.*\"$1\":\"\\([^\"]*\\)\".*/\\1/p"; }
capture=$(curl -fsS --data-binary @"$data/sample-capture.tar" "$base/v1/captures" | json_field id)
echo "uploaded capture $capture"
config=${iterations:+"\"iterations\":$iterations"}
job=$(curl -fsS -H 'content-type: application/json' \
  -d "{\"capture_id\":\"$capture\",\"config\":{$config}}" \
  "$base/v1/jobs" | json_field id)
echo "submitted job $job (iterations: ${iterations:-auto}); progress:"
while true; do
  status=$(curl -fsS "$base/v1/jobs/$job")
  state=$(echo "$status" | json_field state)
  iteration=$(echo "$status" | sed -n 's/.*"iteration":\([0-9]*\).*/\1/p')
  # The job's first "iterations" (its config's may be "auto").
  total=$(echo "$status" | grep -o '"iterations":[0-9]*' | head -n 1 | cut -d: -f2)
  eta=$(echo "$status" | sed -n 's/.*"eta_seconds":\([0-9]*\).*/\1/p')
  printf '\r  %-10s iteration %s/%s  eta %ss   ' "$state" "${iteration:-0}" "${total:-?}" "${eta:-?}"
  case "$state" in succeeded|failed|cancelled) echo; break ;; esac
  sleep 2
done
# A short summary; the job and its artifacts as JSON are one curl away (printed below).
psnr=$(echo "$status" | sed -n 's/.*"test_psnr":\([0-9.]*\).*/\1/p')
elapsed=$((SECONDS - started))
echo "job $job $state in $((elapsed / 60)) min $((elapsed % 60)) s; test PSNR ${psnr:-?} dB"
listing=$(curl -fsS "$base/v1/jobs/$job/artifacts")
echo "artifacts (bytes):"
{ echo "$listing" | grep -o '"name":"[^"]*","size":[0-9]*' | grep -v '"name":"renders/' || true; } |
  sed 's/"name":"\([^"]*\)","size":\([0-9]*\)/  \1  \2/'
renders=$({ echo "$listing" | grep -o '"name":"renders/' || true; } | wc -l)
[ "$renders" -gt 0 ] && echo "  renders/  $renders images"
echo "the job as JSON:        curl $base/v1/jobs/$job"
echo "its artifacts as JSON:  curl $base/v1/jobs/$job/artifacts"
echo "download one, e.g.:     curl -o model.glb $base/v1/jobs/$job/artifacts/model.glb"
echo
echo "Open the web page to see the reconstructed object: $base/#/jobs/$job"
echo "The service keeps running (data in $data); Ctrl-C stops it."
wait "$server"
