// The operator's command line: verbs and their arguments to a request, the reply printed.
#include "server/admin/admin_cli.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <iostream>
#include <numeric>

#include "server/admin/admin_call.h"
#include "server/admin/admin_request.h"

namespace pool::admin {

namespace {

using Json = nlohmann::json;

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : " ") + w;
  return out;
}

std::string scalar(const Json& v) {
  return v.is_string() ? v.get<std::string>()
                       : v.dump(-1, ' ', false, Json::error_handler_t::replace);
}

/// A reply as lines: "key: value" for each scalar, one indented line per array item.
void print(const Json& reply) {
  for (const auto& [key, value] : reply.items()) {
    if (key == "ok") continue;
    if (!value.is_array()) {
      std::cout << key << ": " << scalar(value) << "\n";
      continue;
    }
    std::cout << key << ": " << value.size() << "\n";
    for (const auto& item : value) {
      std::string line;
      if (item.is_object()) {
        for (const auto& [k, v] : item.items()) {
          if (v.is_array()) {
            for (const auto& sub : v)
              line += "\n    " + k + " " + sub.dump(-1, ' ', false, Json::error_handler_t::replace);
          } else {
            line += (line.empty() ? "" : " ") + k + "=" + scalar(v);
          }
        }
      } else {
        line = scalar(item);
      }
      std::cout << "  " << line << "\n";
    }
  }
}

}  // namespace

bool isAdminCommand(int argc, const char* const* argv) {
  if (argc < 2) return false;
  const std::string first = argv[1];
  return first == "admin" || first == "status";
}

std::string socketPathFor(const std::string& db_path) {
  return db_path + ".sock";
}

int runAdminCommand(int argc, const char* const* argv, const std::string& default_db) {
  CLI::App app{"pool-server admin: operate a running pool-server over its local socket"};
  std::string socket;
  std::string db;
  bool json = false;
  app.add_option("--socket", socket, "the server's admin socket (default: <db>.sock)");
  app.add_option("--db", db, "the server's database, to find its socket beside it");
  app.add_flag("--json", json, "print the reply as one JSON line");
  app.require_subcommand(1);
  std::vector<std::string> words;
  AdminRequest request;
  auto* status = app.add_subcommand("status", "health and counters");
  auto* admin = app.add_subcommand("admin", "an operator's order (see VERB)");
  admin
      ->add_option("verb", words,
                   "status | list | close MATCH REASON... | ban KEY REASON... | unban KEY | "
                   "bans | backup PATH | tournament-create NAME... | tournament-start ID | "
                   "tournament-cancel ID | tournaments")
      ->required();
  // tournament-create's settings; the other verbs take none of them.
  std::string format = "single";
  int game = 8, race = 1, entrants = 8;
  bool handicap = false;
  const std::array<CLI::Option*, 5> tournament_options{
      admin->add_option("--format", format,
                        "tournament-create: single | double | round-robin (default single)"),
      admin->add_option("--game", game,
                        "tournament-create: 8, 9, 10, 3 (three-cushion) or 22 (snooker); "
                        "default 8"),
      admin->add_option("--race", race, "tournament-create: each match a race to 1-15 (default 1)"),
      admin->add_option("--entrants", entrants,
                        "tournament-create: the entrants it takes, 3-32 (default 8); it starts "
                        "when full or when started"),
      admin->add_flag("--handicap", handicap,
                      "tournament-create: the lower-rated player of each match starts with racks "
                      "on the wire (the spot that makes the race closest to even by the ratings)"),
  };
  for (auto* sub : {status, admin}) {
    sub->fallthrough();
    sub->footer(
        "Also: --db PATH (the server's database; its socket is PATH.sock), --socket PATH, --json "
        "(docs/OPERATING.md)\n");
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;  // help, or a bad command line
  }
  Json doc;
  if (status->parsed()) {
    doc["verb"] = "status";
  } else {
    const std::string verb = words.front();
    doc["verb"] = verb;
    const std::vector<std::string> rest(words.begin() + 1, words.end());
    auto need = [&](std::size_t at_least, const char* usage) {
      if (rest.size() >= at_least) return true;
      std::cerr << "pool-server admin " << verb << ": usage: " << usage << "\n";
      return false;
    };
    if (verb != "tournament-create") {
      for (const auto* option : tournament_options) {
        if (option->count() == 0) continue;
        std::cerr << "pool-server admin " << verb << ": " << option->get_name()
                  << " is for tournament-create\n";
        return 2;
      }
    }
    if (verb == "close") {
      if (!need(2, "close MATCH REASON...")) return 2;
      doc["match"] = rest[0];
      doc["reason"] = joined({rest.begin() + 1, rest.end()});
    } else if (verb == "ban") {
      if (!need(2, "ban KEY REASON...")) return 2;
      doc["key"] = rest[0];
      doc["reason"] = joined({rest.begin() + 1, rest.end()});
    } else if (verb == "unban") {
      if (!need(1, "unban KEY")) return 2;
      doc["key"] = rest[0];
    } else if (verb == "backup") {
      if (!need(1, "backup PATH")) return 2;
      // A relative path is the operator's, not the server's working directory.
      std::error_code ec;
      doc["path"] = std::filesystem::absolute(rest[0], ec).lexically_normal().string();
    } else if (verb == "tournament-create") {
      if (!need(1,
                "tournament-create NAME... [--format single|double|round-robin] [--game N] "
                "[--race N] [--entrants N] [--handicap]")) {
        return 2;
      }
      doc["name"] = joined(rest);
      doc["format"] = format;
      doc["game"] = game;
      doc["race"] = race;
      doc["entrants"] = entrants;
      if (handicap) doc["handicap"] = true;
    } else if (verb == "tournament-start" || verb == "tournament-cancel") {
      if (!need(1, verb == "tournament-start" ? "tournament-start ID" : "tournament-cancel ID")) {
        return 2;
      }
      if (rest.size() > 1) {
        std::cerr << "pool-server admin " << verb << ": takes one tournament id\n";
        return 2;
      }
      doc["tournament"] = rest[0];
    } else if (rest.size() > 0) {
      std::cerr << "pool-server admin " << verb << ": takes no arguments\n";
      return 2;
    }
  }
  const std::string line = doc.dump(-1, ' ', false, Json::error_handler_t::replace);
  // Checked here too: a mistyped order is explained without bothering the server.
  if (auto checked = parseRequest(line); !checked) {
    std::cerr << "pool-server admin: " << checked.error() << "\n";
    return 2;
  }
  const std::string path = !socket.empty() ? socket : socketPathFor(db.empty() ? default_db : db);
  auto reply = call(path, line);
  if (!reply) {
    std::cerr << "pool-server admin: " << reply.error() << "\n";
    return 1;
  }
  const Json answer = Json::parse(*reply, nullptr, false);
  if (answer.is_discarded() || !answer.is_object()) {
    std::cerr << "pool-server admin: unreadable reply: " << *reply << "\n";
    return 1;
  }
  if (!answer.value("ok", false)) {
    std::cerr << "pool-server admin: refused: " << answer.value("error", std::string("?")) << "\n";
    return 1;
  }
  if (json) {
    std::cout << *reply << "\n";
  } else {
    print(answer);
  }
  return 0;
}

}  // namespace pool::admin
