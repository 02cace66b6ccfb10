#!/usr/bin/env bash
# Fails when a file includes what its folder may not (docs/ARCHITECTURE.md): DDS and the generated
# wire types outside common/net, ODE outside common/physics, OpenGL outside client/render and
# client/ui, assimp outside common/table and client/render, HTTP (Boost.Beast, Asio) outside
# client/web, or a lower module reaching up; and when docs/ARCHITECTURE.md's module table and layers
# differ from the CMake graph (scripts/check-architecture.py).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

status=0
# fence NAME INCLUDED EXEMPT ALLOWED...: a tracked C/C++ file outside the ALLOWED folders whose
# #include names a path matching INCLUDED (and not EXEMPT) breaks the fence NAME.
fence() {
  local name=$1 included=$2 exempt=$3
  shift 3
  local file line path prefix allowed
  while IFS=: read -r file line path; do
    [[ -z $file ]] && continue
    allowed=0
    for prefix in "$@"; do
      [[ $file == "$prefix"* ]] && allowed=1
    done
    [[ -n $exempt && $path =~ ^($exempt)$ ]] && allowed=1
    if ((!allowed)); then
      echo "fence '$name': $file:$line includes $path" >&2
      status=1
    fi
  done < <(git grep -nE "^[[:space:]]*#[[:space:]]*include[[:space:]]*[<\"]($included)" \
             -- '*.c' '*.cpp' '*.h' '*.hpp' |
           sed -E 's/^([^:]*):([0-9]*):[[:space:]]*#[[:space:]]*include[[:space:]]*[<"]([^>"]*)[>"].*$/\1:\2:\3/')
}

# The net headers anyone may include: they show the protocol's domain types only.
net_public='net/(client_transport|server_transport|server_id_probe|incoming_command|dds_error)\.h'

fence dds 'dds/|pool\.h|net/' "$net_public" common/net/ tests/
fence opengl 'glad/|GLFW/|EGL/|GL/|backends/imgui_impl' '' client/render/ client/ui/ tests/
fence ode 'ode/' '' common/physics/ tests/physics/
fence assimp 'assimp/' '' common/table/ client/render/ tests/
fence http 'boost/(beast|asio)' '' client/web/ tests/
# One way: the shared modules never reach up into the protocol, the transport, the server or
# the clients; the protocol never reaches into the transport.
fence shared-modules 'protocol/|net/|client/|server/' '' common/protocol/ common/net/ \
  server/ client/ tests/
fence protocol 'net/|client/|server/' "$net_public" common/net/ server/ client/ tests/
# The window's model (client/app) takes its table and aim prediction from the game kit, never from
# the bot (client/bot, which the window's practice table uses from client/ui).
fence app-not-bot 'client/bot/' '' common/ server/ client/bot/ client/ui/ client/web/ \
  client/spectate/ client/render/ client/audio/ client/room/ client/net/ client/client_main.cpp \
  tests/
# The game kit (common/game) sits above the table, the physics and the rules, below the protocol.
fence game-kit 'game/' '' common/game/ common/scenario/ common/protocol/ common/net/ server/ \
  client/ tests/
# The admin channel (server/admin) knows nothing of matches, the store, the server or DDS: the
# server's desk uses it, never the other way.
while IFS= read -r hit; do
  echo "fence 'admin-channel': $hit" >&2
  status=1
done < <(git grep -nE '^[[:space:]]*#[[:space:]]*include[[:space:]]*"(server/(match|store|sim)/|server/[a-z_]+\.h|net/|dds/)' \
           -- 'server/admin/*' || true)

# The shot's limits have one home, common/physics/shot_limits.h: a literal 12 m/s speed, 89°
# elevation or its radians (1.553...) in the code anywhere else (comments aside; tests may state
# them) breaks the fence.
while IFS= read -r hit; do
  echo "fence 'shot-limits': $hit (use physics/shot_limits.h)" >&2
  status=1
done < <(git grep -nE '12|89|1\.55' -- '*.c' '*.cpp' '*.h' ':!common/physics/shot_limits.h' ':!tests/' |
           awk '{
             split($0, at, ":")
             code = substr($0, length(at[1]) + length(at[2]) + 3)
             sub(/\/\/.*/, "", code)
             if (code ~ /[Ss]peed[^;]*[^0-9.a-zA-Z_]12(\.0*)?([^0-9.]|$)/ ||
                 code ~ /(^|[^0-9.])89(\.0*)?([^0-9.]|$)/ || code ~ /1\.553/)
               print at[1] ":" at[2] ": " code
           }')

# docs/ARCHITECTURE.md's module table and layers follow the CMake graph: every target in both, and
# every link down the layers.
python3 scripts/check-architecture.py || status=1

if ((status)); then
  echo "check-fences: a fence is broken (docs/ARCHITECTURE.md)" >&2
  exit 1
fi
echo "fences hold: DDS only in common/net, ODE only in common/physics, OpenGL only in" \
  "client/render and client/ui, assimp only in common/table and client/render, HTTP only in" \
  "client/web, modules one way, client/app apart from client/bot, the game kit below its users," \
  "the shot's limits in physics/shot_limits.h, the architecture's layers as CMake links them"
