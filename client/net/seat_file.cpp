// JSON seat files, written atomically.
#include "client/net/seat_file.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>

namespace pool::client {

Result<std::optional<SeatRecord>> readSeatFile(const std::filesystem::path& path) {
  using Out = Result<std::optional<SeatRecord>>;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return Out::ok(std::nullopt);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const auto json = nlohmann::json::parse(text.str(), nullptr, false);
  if (json.is_discarded() || !json.is_object()) return Out::fail(path.string() + ": not JSON");
  try {
    SeatRecord record;
    record.match = json.at("match").get<std::string>();
    record.seat = json.at("seat").get<int>();
    // The token is written as a string: JSON numbers do not carry 64 bits everywhere.
    record.token = std::stoull(json.at("token").get<std::string>());
    record.last_seq = json.value("last_seq", 0u);
    return Out::ok(record);
  } catch (const std::exception& e) {
    return Out::fail(path.string() + ": " + e.what());
  }
}

bool takesBackKeptSeat(const SeatRecord& kept, const std::string& wanted) {
  return wanted.empty() || wanted == kept.match;
}

std::filesystem::path keyFileFor(const std::filesystem::path& seat_file) {
  return seat_file.string() + ".key";
}

std::string writeSeatFile(const std::filesystem::path& path, const SeatRecord& record) {
  const nlohmann::json json = {{"match", record.match},
                               {"seat", record.seat},
                               {"token", std::to_string(record.token)},
                               {"last_seq", record.last_seq}};
  const auto temporary = std::filesystem::path(path.string() + ".tmp");
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << json.dump() << "\n";
    if (!out) return "cannot write " + temporary.string();
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  return ec ? "cannot rename to " + path.string() + ": " + ec.message() : std::string();
}

}  // namespace pool::client
