// pool-cuegen: writes the cue's mesh (assets/cue/cue.obj) from its lathe profile.
#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>

#include "client/render/cue_profile.h"

int main(int argc, char** argv) {
  CLI::App app{"pool-cuegen: write the cue's mesh as a Wavefront OBJ"};
  std::string out_path;
  int segments = 20;
  app.add_option("-o,--output", out_path, "OBJ file to write (default: standard output)");
  app.add_option("--segments", segments, "facets around the cue's axis")->check(CLI::Range(6, 128));
  CLI11_PARSE(app, argc, argv);
  const std::string obj = pool::render::cueObj(segments);
  if (out_path.empty()) {
    std::cout << obj;
    return 0;
  }
  std::ofstream out(out_path);
  out << obj;
  if (!out) {
    std::cerr << "could not write " << out_path << '\n';
    return 1;
  }
  return 0;
}
