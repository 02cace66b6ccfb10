#!/usr/bin/env bash
# An emulated LAN: pool-server in one network namespace, two pool-bots and a spectator in another,
# joined by a veth pair, on Cyclone's default configuration (multicast discovery); a match to a
# winner. Runs with CI=true, as root: without CI=true it is skipped (exit 77, with the reason);
# with CI=true and not root it fails, for a CI that cannot run it must not pass unnoticed.
# Usage: netns_match.sh POOL_SERVER POOL_BOT POOL_CLIENT
set -euo pipefail
server_bin=$1 bot_bin=$2 client_bin=$3
if [[ ${CI:-} != true ]]; then
  echo "skipped: the LAN test makes network namespaces; it runs in CI (CI=true, as root)"
  exit 77
fi
if [[ $(id -u) -ne 0 ]]; then
  echo "FAILED: network namespaces need root, and with CI=true this test must run (run CI as root)"
  exit 1
fi

# Names of our own, unique to this run; a private subnet that exists only inside the pair.
tag=pool$$
srv=$tag-srv cli=$tag-cli
work=$(mktemp -d)
pids=()
cleanup() {
  kill "${pids[@]}" 2>/dev/null || true
  wait 2>/dev/null || true
  ip netns del "$srv" 2>/dev/null || true
  ip netns del "$cli" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 1' INT TERM  # a timeout's signal runs the cleanup too

ip netns add "$srv"
ip netns add "$cli"
ip link add "v$$s" netns "$srv" type veth peer name "v$$c" netns "$cli"
setup() {  # namespace interface address
  ip -n "$1" link set lo up
  ip -n "$1" link set "$2" up
  ip -n "$1" address add "$3/24" dev "$2"
  ip -n "$1" route add 224.0.0.0/4 dev "$2"  # multicast (Cyclone's discovery) over the pair
}
setup "$srv" "v$$s" 10.231.0.1
setup "$cli" "v$$c" 10.231.0.2

# Cyclone's defaults: no configuration file, multicast discovery on the veth interface.
unset CYCLONEDDS_URI
domain=0
ip netns exec "$srv" "$server_bin" --domain "$domain" --tables 1 --fast --log-level warn \
  --db "$work/pool.db" > "$work/server.log" 2>&1 &
pids+=($!)
bots=()
for player in Ada:1 Bert:2; do
  name=${player%%:*}
  ip netns exec "$cli" "$bot_bin" --domain "$domain" --name "$name" --skill 0.8 \
    --seed "${player##*:}" --think 0 --timeout 200 --log-level warn \
    > "$work/$name.out" 2> "$work/$name.log" &
  bots+=($!)
  pids+=($!)
done
ip netns exec "$cli" "$client_bin" --domain "$domain" --spectate any --no-window --json \
  --timeout 220 > "$work/spectator.out" 2> "$work/spectator.log" &
spectator=$!
pids+=("$spectator")

status=0
for pid in "${bots[@]}"; do wait "$pid" || status=$?; done
spectator_status=0
wait "$spectator" || spectator_status=$?
echo "Ada: $(cat "$work/Ada.out")"
echo "Bert: $(cat "$work/Bert.out")"
if ((status != 0)); then
  echo "a bot failed (exit $status)" >&2
  cat "$work/Ada.log" "$work/Bert.log" "$work/server.log" >&2
  exit 1
fi
grep -q '^result: win' "$work/Ada.out" "$work/Bert.out"
grep -q '^result: loss' "$work/Ada.out" "$work/Bert.out"
# The spectator, in the players' namespace too, followed the match to its end.
if ! grep -q '"phase":"over"' "$work/spectator.out"; then
  echo "the spectator did not see the match end (exit $spectator_status)" >&2
  tail -n 5 "$work/spectator.out" "$work/spectator.log" >&2
  exit 1
fi
echo "spectator: $(grep -c . "$work/spectator.out") lines, match over"
echo "a match over the veth pair, by multicast discovery, to a winner"
