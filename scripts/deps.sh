#!/usr/bin/env bash
# Installs the Debian packages the build, the tests, the fuzzing (clang) and the packaging need, only those missing, and the web page's JavaScript from npm (idempotent).
set -euo pipefail
packages=(cmake ninja-build g++ pkg-config libode-dev cyclonedds-dev cyclonedds-tools
  libassimp-dev libeigen3-dev libglfw3-dev libglm-dev libimgui-dev libstb-dev python3-glad
  xvfb xauth libgl1-mesa-dri libgl-dev libegl-dev libfmt-dev libspdlog-dev libcli11-dev
  nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev libsqlite3-dev libsodium-dev
  fonts-dejavu-core libopenal-dev clang libclang-rt-14-dev clang-format
  dpkg-dev file systemd desktop-file-utils iproute2
  libboost-dev chromium)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# The web page's JavaScript (three.js) at the versions package-lock.json pins, into node_modules/
# (the build copies it beside the page), when what is installed differs from the lockfile. npm
# from Debian when the machine has none (a Node.js installed otherwise is left alone).
if ! command -v npm >/dev/null; then
  echo "installing: npm"
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends npm
fi
cd "$(dirname "${BASH_SOURCE[0]}")/.."
locked=$(node -p "require('./package-lock.json').packages['node_modules/three'].version")
installed=$(node -p "try { require('./node_modules/three/package.json').version } catch (e) { '' }")
if [[ $locked != "$installed" ]]; then
  echo "installing the page's JavaScript: npm ci (three.js $locked, package-lock.json)"
  npm ci --no-audit --no-fund --ignore-scripts
fi
