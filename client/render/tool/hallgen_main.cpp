// pool-hallgen: writes the pool hall's mesh (assets/hall/room.obj) or a table's dressing
// (assets/hall/<table>.obj) from their builders.
#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>

#include "client/render/hall_assets.h"

int main(int argc, char** argv) {
  CLI::App app{"pool-hallgen: write the pool hall or a table's dressing as a Wavefront OBJ"};
  std::string what;
  std::string out_path;
  app.add_option("what", what, "room, or a table spec's name or path (e.g. wpa-9ft)")->required();
  app.add_option("-o,--output", out_path, "OBJ file to write (default: standard output)");
  CLI11_PARSE(app, argc, argv);
  const auto obj = what == "room" ? pool::render::roomObj() : pool::render::dressingObj(what);
  if (!obj) {
    std::cerr << obj.error() << '\n';
    return 2;
  }
  if (out_path.empty()) {
    std::cout << *obj;
    return 0;
  }
  std::ofstream out(out_path);
  out << *obj;
  if (!out) {
    std::cerr << "could not write " << out_path << '\n';
    return 1;
  }
  return 0;
}
