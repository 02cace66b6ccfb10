#!/usr/bin/env bash
# Builds everything and runs the main job on a local pool-server and the web spectator pool-web
# (its URL printed; POOL_WEB_PORT, default 8080). With a display: the game window,
# you against a bot (--hotseat: two players on this screen; --watch: watch two bots). Without a
# display (or with --headless): two bots play and a spectator prints the match in this terminal.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${POOL_BUILD_DIR:-$root/build}

mode=play
for arg in "$@"; do
  case $arg in
    --hotseat) mode=hotseat ;;
    --watch) mode=watch ;;
    --headless) mode=headless ;;
    *) echo "usage: $0 [--hotseat | --watch | --headless]" >&2; exit 2 ;;
  esac
done
if [[ $mode != headless && -z ${DISPLAY:-} && -z ${WAYLAND_DISPLAY:-} ]]; then
  echo "no display: running headless (two bots, followed in this terminal)" >&2
  mode=headless
fi

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

# The web spectator on loopback: any browser on this machine can watch at its URL.
web_port=${POOL_WEB_PORT:-8080}
"$bin/pool-web" --domain "$domain" --port "$web_port" > /dev/null &
pids+=($!)
echo "Watch from a browser: http://127.0.0.1:$web_port/ (pool-web; --bind 0.0.0.0 for the LAN)" >&2

bot() {  # name seed [more flags]
  "$bin/pool-bot" --domain "$domain" --name "$1" --level club --seed "$2" --think 0.8 \
    --log-level warn "${@:3}" > /dev/null &
  pids+=($!)
}

case $mode in
  play)
    bot Bert 2 --stay  # plays rematches (R) until you leave
    echo "You against the bot Bert: aim with the arrows, hold Space to shoot (keys: README.md)" >&2
    "$bin/pool-client" --domain "$domain" --play --name "${USER:-Player}"
    ;;
  hotseat)
    echo "Two players on this screen: the HUD says whose turn it is (keys: README.md)" >&2
    "$bin/pool-client" --domain "$domain" --play --hotseat
    ;;
  watch)
    bot Ada 1
    bot Bert 2
    "$bin/pool-client" --domain "$domain" --spectate any
    ;;
  headless)
    "$bin/pool-bot" --domain "$domain" --name Ada --level club --seed 1 > /dev/null &
    pids+=($!)
    "$bin/pool-bot" --domain "$domain" --name Bert --level club --seed 2 &
    last_bot=$!
    pids+=($last_bot)
    echo "A match between two bots on a local pool-server; watching it (Ctrl+C to stop):" >&2
    "$bin/pool-client" --domain "$domain" --spectate any --no-window --json &
    pids+=($!)
    wait "$last_bot"
    ;;
esac
