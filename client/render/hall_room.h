// The pool hall around the table as named meshes: floor, panelled and papered walls, ceiling,
// bar stools, a cue rack with its cues, a scoreboard and framed pictures. Pure (no GL): the
// generator writes it to assets/hall/room.obj and the renderer reads that file.
#pragma once

#include <string>
#include <vector>

#include "client/render/mesh.h"

namespace pool::render {

/// The hall's parts (hall_layout.h places them); part names say what they are made of
/// (palette.h's hallPartLook). The same parts every call.
std::vector<NamedMesh> hallRoom();

/// Whether `part_name` is one of the hall's shell (floor, walls, ceiling): faces counter-clockwise
/// seen from inside the room.
bool isHallShell(const std::string& part_name);

}  // namespace pool::render
