#!/usr/bin/env bash
# CI stage: Debian packages made from the tested build (build/, optimised with debug information,
# stripped into separate debug symbols as Debian's own tools do), installed on this machine (root),
# the installed programs run (help, a shipped scene, a screenshot, a bot match, the web spectator's
# page) and searched for any path of this checkout, the unit and desktop entry checked, then the
# packages purged and nothing of them left. Prints each step's time.
# Usage: scripts/ci-package.sh   (build folder: build/ or $POOL_BUILD_DIR, configured for the
# prefix /usr here if it was not; DDS domain of the match: $POOL_DOMAIN, default 11, over loopback
# with port base $POOL_DDS_PORT_BASE)
set -euo pipefail
unset POOL_SANITIZE  # the packages are made from the plain build
source "$(dirname "${BASH_SOURCE[0]}")/build-env.sh"
packages=(pool-common pool-server pool-client)
# It installs and purges packages on this machine (any pool packages installed before are purged).
if [[ $(id -u) -ne 0 ]]; then
  exec sudo -E "$0" "$@"
fi
"$root/scripts/deps.sh"

step() {
  local name=$1 start=$SECONDS
  shift
  echo "--- package: $name"
  "$@"
  echo "--- package: $name took $((SECONDS - start)) s"
}

purge() { apt-get purge -y -qq "${packages[@]}" >/dev/null 2>&1 || true; }

work=$(mktemp -d)
pids=()
cleanup() {
  kill "${pids[@]}" 2>/dev/null || true
  wait 2>/dev/null || true
  purge
  rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 1' INT TERM  # a timeout's signal runs the cleanup too

# 1. The tested build (RelWithDebInfo, warnings as errors) for the prefix /usr: nothing to do when
#    it was configured so before it was built (.ci/run does), else the programs are relinked.
build_programs() {
  configure_build -DCMAKE_INSTALL_PREFIX=/usr -DPOOL_WERROR=ON
  cmake --build "$build" -j "$(nproc)"
}

# 2. The three .deb files, their dependencies read off the binaries (dpkg-shlibdeps).
make_packages() {
  rm -rf "$build/packages"
  (cd "$build" && cpack -G DEB >/dev/null)
  for deb in "$build"/packages/*.deb; do
    echo "$(basename "$deb"): $(dpkg-deb -f "$deb" Depends)"
  done
  ls "$build"/packages/*.ddeb >/dev/null  # the separate debug symbols
  echo "debug symbols: $(cd "$build/packages" && echo *.ddeb)"
}

# 3. Installed the way a user would (apt resolves the dependencies), from a clean state.
install_packages() {
  purge
  apt-get install -y -qq "$build"/packages/*.deb >/dev/null
  dpkg-query -W "${packages[@]}"
}

# 4. The installed programs, from an empty folder: they find their assets in /usr/share/pool.
run_installed() {
  cd "$work"
  [[ $(command -v pool-server) == /usr/bin/pool-server ]]
  pool-server --help | head -n 1
  pool-sim /usr/share/pool/scenes/break.json --plot break.svg > break.json
  pool-sim bank > bank.json  # a bare scene name: looked up in the installed assets
  grep -q '"balls"' break.json
  grep -q '"events"' bank.json
  [[ -s break.svg ]]
  echo "pool-sim: break and bank scenes ran ($(wc -c < break.json) bytes of JSON)"
  # The game's renderer (EGL surfaceless without a display): the table, its font and assets.
  env -u DISPLAY pool-client --screenshot rack.png --frames 2 --scene rack > /dev/null
  [[ -s rack.png ]]
  echo "pool-client: rendered rack.png ($(wc -c < rack.png) bytes)"
  # Nothing installed names this checkout (no compiled-in source path, no debug information left).
  local named
  named=$(dpkg -L "${packages[@]}" | while IFS= read -r path; do
    [[ -f $path ]] && grep -lF "$root" "$path" || true
  done)
  if [[ -n $named ]]; then
    echo "installed files naming the checkout $root:" >&2
    echo "$named" >&2
    return 1
  fi
  echo "no installed file names the checkout"
}

# 5. A short match from the installed binaries: pool-server and two bots over loopback DDS on a
#    domain of its own; a winner within the bound, the server's status and an online backup
#    through its admin socket, then a clean stop of the server on SIGTERM.
bot_match() {
  cd "$work"
  export CYCLONEDDS_URI=file:///usr/share/pool/cyclone-lo.xml
  local domain=${POOL_DOMAIN:-11}
  pool-server --domain "$domain" --tables 1 --fast --log-level warn --db "$work/pool.db" &
  local server=$!
  pids+=("$server")
  # The installed web spectator beside the match, on a free port.
  pool-web --domain "$domain" --port 0 > web.out 2> web.err &
  local web=$!
  pids+=("$web")
  local bots=()
  for player in Ada:1 Bert:2; do
    timeout 150 pool-bot --domain "$domain" --name "${player%%:*}" --skill 0.8 \
      --seed "${player##*:}" --think 0 --timeout 120 --log-level warn > "${player%%:*}.out" &
    bots+=($!)
    pids+=($!)
  done
  local status=0
  for pid in "${bots[@]}"; do wait "$pid" || status=$?; done
  cat Ada.out Bert.out
  ((status == 0)) || { echo "a bot failed (exit $status)" >&2; return 1; }
  grep -q '^result: win' Ada.out Bert.out
  grep -q '^result: loss' Ada.out Bert.out
  # The operator's commands on the installed server: its counters, and an online backup.
  pool-server status --db "$work/pool.db" > status.txt
  cat status.txt
  grep -q '^health: ok$' status.txt
  if grep -q '^commands_accepted: 0$' status.txt; then echo "no command counted" >&2; return 1; fi
  pool-server admin --db "$work/pool.db" backup "$work/copy.db"
  [[ -s $work/copy.db ]]
  web_page "$web"
  kill -TERM "$server"
  status=0
  wait "$server" || status=$?
  ((status == 0)) || { echo "pool-server exit $status on SIGTERM" >&2; return 1; }
  echo "pool-server stopped cleanly on SIGTERM"
  unset CYCLONEDDS_URI
}

# The installed pool-web (started by bot_match, pid $1): its URL line, the page and three.js
# served from /usr/share/pool/web, then a clean stop on SIGTERM.
web_page() {
  local web=$1 port=""
  for _ in $(seq 100); do
    port=$(sed -n 's|^pool-web: http://127\.0\.0\.1:\([0-9]*\)/.*|\1|p' web.out)
    [[ -n $port ]] && break
    sleep 0.1
  done
  [[ -n $port ]] || { echo "pool-web printed no URL" >&2; cat web.err >&2; return 1; }
  fetch() {  # PATH: the body of GET PATH over plain HTTP/1.0 (no curl needed)
    exec 3<>"/dev/tcp/127.0.0.1/$port"
    printf 'GET %s HTTP/1.0\r\nHost: localhost\r\n\r\n' "$1" >&3
    cat <&3
    exec 3<&-
  }
  fetch / > page.http
  fetch /three.module.js > three.http
  fetch /../../etc/passwd > escape.http
  head -n 1 page.http | grep -q '200 OK'
  grep -q 'app.js' page.http
  head -n 1 three.http | grep -q '200 OK'
  grep -q 'three.core.js' three.http
  head -n 1 escape.http | grep -q '404'
  echo "pool-web: served the page ($(wc -c < page.http) bytes) and three.js ($(wc -c < three.http) bytes) on port $port"
  kill -TERM "$web"
  local status=0
  wait "$web" || status=$?
  ((status == 0)) || { echo "pool-web exit $status on SIGTERM" >&2; return 1; }
}

# 6. The unit and the desktop entry as installed.
check_files() {
  local unit=/lib/systemd/system/pool-server.service
  [[ -f $unit ]]
  systemd-analyze verify "$unit"
  echo "systemd-analyze verify: $unit ok"
  desktop-file-validate /usr/share/applications/pool.desktop
  echo "desktop-file-validate: pool.desktop ok"
  [[ -f /usr/share/icons/hicolor/scalable/apps/pool.svg && -f /etc/pool/pool-server.conf ]]
}

# 7. Purged: dpkg knows none of them and no file they installed is left (nor the database).
remove_packages() {
  local list=$work/installed.txt
  dpkg -L "${packages[@]}" | sort -u > "$list"
  # Enabled as an operator would: the purge must drop the boot-time links too.
  systemctl enable pool-server.service 2>/dev/null && echo "pool-server.service enabled before the purge"
  purge
  local left=()
  for p in "${packages[@]}"; do
    if dpkg -L "$p" >/dev/null 2>&1; then left+=("dpkg still lists $p"); fi
  done
  while IFS= read -r path; do
    [[ -e $path && ! -d $path ]] && left+=("$path")
  done < "$list"
  for dir in /usr/share/pool /usr/share/doc/pool /etc/pool /var/lib/pool; do
    [[ -e $dir ]] && left+=("$dir")
  done
  if compgen -G '/etc/systemd/system/*.wants/pool-server.service' > /dev/null; then
    left+=(/etc/systemd/system/*.wants/pool-server.service)
  fi
  if ((${#left[@]})); then
    printf 'left after purge: %s\n' "${left[@]}" >&2
    return 1
  fi
  echo "purged: $(wc -l < "$list") paths of ${packages[*]} gone"
}

step "programs" build_programs
step "packages" make_packages
step "install" install_packages
step "installed programs" run_installed
step "bot match" bot_match
step "unit and desktop entry" check_files
step "purge" remove_packages
