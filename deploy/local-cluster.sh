#!/usr/bin/env bash
# The scaled-out topology of deploy/compose.yaml from local processes, for a machine without
# Docker: one PostgreSQL server (Debian's binaries), one S3-compatible server (moto's server mode),
# two API processes and three workers, each with its own data dir, all on loopback.
#
#   deploy/local-cluster.sh start DIR     # starts everything; writes DIR/cluster.env
#   deploy/local-cluster.sh stop DIR      # stops everything started in DIR
#
# DIR/cluster.env names the two API addresses (API_1, API_2), the workers' health addresses
# (WORKER_1..3) and the pid files of every process (DIR/pids/NAME.pid). Needs: the phygap-api
# binary (PHYGAP_API_BIN, default target/release/phygap-api), PostgreSQL's server binaries
# (`apt-get install postgresql`), moto (`pip install 'moto[server]'`), python3 and curl.
# PHYGAP_LEASE_SECONDS (default 5 here) sets how soon a dead worker's job is taken over.
set -euo pipefail

usage() { echo "usage: $0 start|stop DIR" >&2; exit 2; }
[ $# -eq 2 ] || usage
action=$1
dir=$(mkdir -p "$2" && cd "$2" && pwd)
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${PHYGAP_API_BIN:-$root/target/release/phygap-api}
lease=${PHYGAP_LEASE_SECONDS:-5}

free_port() {
  python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

pg_bin() {
  local found
  found=$(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -1)
  [ -n "$found" ] && [ -x "$found/initdb" ] || { echo "PostgreSQL is not installed" >&2; exit 1; }
  echo "$found"
}

# Runs a PostgreSQL binary as the postgres user when we are root (PostgreSQL refuses root).
as_postgres() {
  if [ "$(id -u)" = 0 ]; then runuser -u postgres -- "$@"; else "$@"; fi
}

wait_http() { # URL
  for _ in $(seq 1 300); do
    curl -fsS -o /dev/null "$1" 2>/dev/null && return 0
    sleep 0.2
  done
  echo "no answer from $1" >&2
  return 1
}

start() {
  [ -x "$bin" ] || { echo "no phygap-api binary at $bin (cargo build --release -p phygap-api)" >&2; exit 1; }
  mkdir -p "$dir/pids" "$dir/logs"
  local pg db_port s3_port
  pg=$(pg_bin)
  db_port=$(free_port)
  s3_port=$(free_port)

  mkdir -p "$dir/postgres"
  if [ "$(id -u)" = 0 ]; then chmod a+x "$dir"; chown postgres:postgres "$dir/postgres"; fi
  as_postgres "$pg/initdb" -D "$dir/postgres/data" -U phygap --auth=trust --no-sync \
    --encoding=UTF8 --locale=C >"$dir/logs/initdb.log"
  as_postgres "$pg/pg_ctl" -D "$dir/postgres/data" -l "$dir/postgres/server.log" -w -t 60 \
    -o "-c listen_addresses=127.0.0.1 -p $db_port -k $dir/postgres -c fsync=off" start >/dev/null

  if command -v moto_server >/dev/null; then moto=(moto_server); else moto=(python3 -m moto.server); fi
  setsid "${moto[@]}" -H 127.0.0.1 -p "$s3_port" >"$dir/logs/s3.log" 2>&1 &
  echo $! >"$dir/pids/s3.pid"
  wait_http "http://127.0.0.1:$s3_port/"
  curl -fsS -X PUT -o /dev/null "http://127.0.0.1:$s3_port/phygap"

  export PHYGAP_DATABASE_URL="postgres://phygap@127.0.0.1:$db_port/postgres"
  export PHYGAP_ARTIFACT_URL="s3://phygap/cluster"
  export AWS_ENDPOINT_URL="http://127.0.0.1:$s3_port" AWS_ALLOW_HTTP=true
  export AWS_ACCESS_KEY_ID=local AWS_SECRET_ACCESS_KEY=local AWS_REGION=us-east-1
  export PHYGAP_LEASE_SECONDS=$lease

  local env_file="$dir/cluster.env"
  {
    echo "DATABASE_URL=$PHYGAP_DATABASE_URL"
    echo "S3_ENDPOINT=$AWS_ENDPOINT_URL"
    echo "ARTIFACT_URL=$PHYGAP_ARTIFACT_URL"
  } >"$env_file"
  local name port
  for i in 1 2; do
    name=api_$i port=$(free_port)
    setsid "$bin" serve --bind "127.0.0.1:$port" --data-dir "$dir/$name" --workers 0 \
      >"$dir/logs/$name.log" 2>&1 &
    echo $! >"$dir/pids/$name.pid"
    echo "API_$i=http://127.0.0.1:$port" >>"$env_file"
  done
  for i in 1 2 3; do
    name=worker_$i port=$(free_port)
    setsid "$bin" worker --bind "127.0.0.1:$port" --data-dir "$dir/$name" --workers 1 \
      >"$dir/logs/$name.log" 2>&1 &
    echo $! >"$dir/pids/$name.pid"
    echo "WORKER_$i=http://127.0.0.1:$port" >>"$env_file"
  done
  # shellcheck disable=SC1090
  . "$env_file"
  for url in "$API_1" "$API_2" "$WORKER_1" "$WORKER_2" "$WORKER_3"; do
    wait_http "$url/healthz"
  done
  echo "cluster up: $API_1 $API_2 (workers: $WORKER_1 $WORKER_2 $WORKER_3)"
}

stop() {
  local pidfile
  for pidfile in "$dir"/pids/*.pid; do
    [ -e "$pidfile" ] || continue
    kill -TERM "$(cat "$pidfile")" 2>/dev/null || true
  done
  sleep 1
  for pidfile in "$dir"/pids/*.pid; do
    [ -e "$pidfile" ] || continue
    kill -KILL "$(cat "$pidfile")" 2>/dev/null || true
    rm -f "$pidfile"
  done
  if [ -d "$dir/postgres/data" ]; then
    as_postgres "$(pg_bin)/pg_ctl" -D "$dir/postgres/data" -m immediate -w stop >/dev/null 2>&1 || true
  fi
}

case $action in
  start) start ;;
  stop) stop ;;
  *) usage ;;
esac
