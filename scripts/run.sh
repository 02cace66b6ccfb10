#!/usr/bin/env bash
# Builds everything and runs the main job: a local pool-server with a match between two bots,
# followed live by a spectator in this terminal (the graphical client comes with its issue).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${POOL_BUILD_DIR:-$root/build}
"$root/scripts/build.sh"
bin=$build/bin

# Local only: loopback DDS on its own domain, so nothing reaches (or comes from) the LAN.
export CYCLONEDDS_URI=${CYCLONEDDS_URI:-file://$root/assets/cyclone-lo.xml}
domain=${POOL_DOMAIN:-7}

# The demo match is kept in a database of its own, gone afterwards (pool-server's default is the
# user's data folder, where unfinished matches are resumed).
data=$(mktemp -d)
pids=()
cleanup() { kill "${pids[@]}" 2>/dev/null || true; wait 2>/dev/null || true; rm -rf "$data"; }
trap cleanup EXIT INT TERM

"$bin/pool-server" --domain "$domain" --tables 1 --log-level warn --db "$data/pool.db" &
pids+=($!)
"$bin/pool-bot" --domain "$domain" --name Ada --skill 0.8 --seed 1 > /dev/null &
pids+=($!)
"$bin/pool-bot" --domain "$domain" --name Bert --skill 0.8 --seed 2 &
bot=$!
pids+=($bot)
echo "A match between two bots on a local pool-server; watching it (Ctrl+C to stop):" >&2
"$bin/pool-client" --domain "$domain" --spectate any --no-window --json &
pids+=($!)
wait "$bot"
