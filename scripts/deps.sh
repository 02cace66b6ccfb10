#!/usr/bin/env bash
# Installs the Debian packages the build, the tests, the fuzzing (clang) and the packaging need, only those missing (idempotent).
set -euo pipefail
packages=(cmake ninja-build g++ pkg-config libode-dev cyclonedds-dev cyclonedds-tools
  libassimp-dev libeigen3-dev libglfw3-dev libglm-dev libimgui-dev libstb-dev python3-glad
  xvfb xauth libgl1-mesa-dri libgl-dev libegl-dev libfmt-dev libspdlog-dev libcli11-dev
  nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev libsqlite3-dev libsodium-dev
  fonts-dejavu-core libopenal-dev clang libclang-rt-14-dev clang-format
  dpkg-dev file systemd desktop-file-utils iproute2)
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
