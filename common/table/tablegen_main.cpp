// pool-tablegen: writes the collision mesh (Wavefront OBJ) of a table spec, to stdout or a file.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "table/table_geometry.h"
#include "table/table_spec.h"

namespace {

constexpr const char* kUsage = "usage: pool-tablegen SPEC_NAME_OR_PATH [-o OUT.obj]";

struct Args {
  std::string spec;
  std::string out;  ///< empty: stdout
};

/// Parses the command line; returns an error line or "".
std::string parseArgs(int argc, char** argv, Args& args) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-o") {
      if (i + 1 >= argc) return "-o needs a file name";
      args.out = argv[++i];
    } else if (!arg.empty() && arg[0] == '-' && arg != "-") {
      return "unknown option " + arg;
    } else if (args.spec.empty()) {
      args.spec = arg;
    } else {
      return "more than one spec given";
    }
  }
  return args.spec.empty() ? "no spec given" : "";
}

int fail(const std::string& reason) {
  std::fprintf(stderr, "pool-tablegen: %s\n", reason.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && (std::string(argv[1]) == "-h" || std::string(argv[1]) == "--help")) {
    std::printf("%s\n", kUsage);
    return 0;
  }
  Args args;
  if (const std::string error = parseArgs(argc, argv, args); !error.empty())
    return fail(error + " (" + kUsage + ")");
  const auto spec = pool::table::loadTableSpec(args.spec);
  if (!spec) return fail(spec.error());
  const std::string obj = pool::table::toObj(pool::table::buildTableGeometry(*spec));
  if (args.out.empty()) {
    std::cout << obj << std::flush;
    return std::cout ? 0 : 1;
  }
  std::ofstream file(args.out, std::ios::binary | std::ios::trunc);
  file << obj;
  file.close();
  if (!file) return fail("cannot write " + args.out);
  return 0;
}
