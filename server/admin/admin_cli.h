// `pool-server admin VERB ...` and `pool-server status`: the operator's command line.
#pragma once

#include <string>

namespace pool::admin {

/// True when argv names an operator command ("admin" or "status" as the first argument).
bool isAdminCommand(int argc, const char* const* argv);

/// The admin socket of the server keeping its matches in `db_path`: "<db_path>.sock".
std::string socketPathFor(const std::string& db_path);

/// Runs an operator command against the running server: parses argv, sends the request, prints
/// the reply (readable, or the JSON line with --json) on stdout and errors on stderr. `default_db`
/// is the database the socket is found beside when neither --socket nor --db is given. Exit code:
/// 0 done, 1 refused or no server, 2 bad command line.
int runAdminCommand(int argc, const char* const* argv, const std::string& default_db);

}  // namespace pool::admin
