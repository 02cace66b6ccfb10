// pool-tablegen: writes the collision mesh (Wavefront OBJ) of a table spec, to stdout or a file.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "core/check.h"
#include "table/table_geometry.h"
#include "table/table_spec.h"

namespace {

constexpr const char* kUsage = "usage: pool-tablegen SPEC_NAME_OR_PATH [-o OUT.obj]";

struct Args {
  std::string spec;
  std::string out;  ///< empty: stdout
};

/// Parses the command line, or refuses it with an error line.
pool::Check<> parseArgs(int argc, char** argv, Args& args) {
  using pool::Check;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-o") {
      if (i + 1 >= argc) return Check<>::refuse("missing_value", "-o needs a file name");
      args.out = argv[++i];
    } else if (!arg.empty() && arg[0] == '-' && arg != "-") {
      return Check<>::refuse("unknown_option", "unknown option " + arg);
    } else if (args.spec.empty()) {
      args.spec = arg;
    } else {
      return Check<>::refuse("two_specs", "more than one spec given");
    }
  }
  if (args.spec.empty()) return Check<>::refuse("no_spec", "no spec given");
  return Check<>::pass();
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
  if (auto ok = parseArgs(argc, argv, args); !ok) return fail(ok.error() + " (" + kUsage + ")");
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
