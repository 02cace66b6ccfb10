// A tournament as JSON text and back: field, options and the log of calls, replayed on reading.
#include "server/tournament/tournament.h"

#include <nlohmann/json.hpp>

#include <climits>
#include <stdexcept>

namespace pool::tournament {
namespace {

using nlohmann::json;

constexpr int kJsonVersion = 1;

/// A fault in the text; fromJson answers its message.
struct JsonFault : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const char* formatName(Format format) {
  switch (format) {
    case Format::SingleElimination:
      return "single_elimination";
    case Format::DoubleElimination:
      return "double_elimination";
    case Format::RoundRobin:
      return "round_robin";
  }
  return "?";
}

const char* stateName(MatchState state) {
  switch (state) {
    case MatchState::Waiting:
      return "waiting";
    case MatchState::Ready:
      return "ready";
    case MatchState::InPlay:
      return "in_play";
    case MatchState::Done:
      return "done";
  }
  return "?";
}

json matchesJson(const std::vector<Match>& matches) {
  json out = json::array();
  for (const Match& m : matches) {
    json j = {{"round", m.round}, {"a", m.a}, {"b", m.b}, {"state", stateName(m.state)}};
    if (m.state == MatchState::Done) {
      j["winner"] = m.winner;
      j["racks"] = {m.racksA, m.racksB};
      j["forfeit"] = m.forfeit;
    }
    out.push_back(std::move(j));
  }
  return out;
}

const json& member(const json& object, const char* key) {
  if (!object.is_object())
    throw JsonFault("expected an object holding \"" + std::string(key) + "\"");
  const auto it = object.find(key);
  if (it == object.end()) throw JsonFault("\"" + std::string(key) + "\" is missing");
  return *it;
}

int intOf(const json& value, const char* what) {
  if (value.is_number_unsigned()) {
    if (value.get<std::uint64_t>() <= static_cast<std::uint64_t>(INT_MAX)) return value.get<int>();
  } else if (value.is_number_integer()) {
    const auto v = value.get<std::int64_t>();
    if (v >= INT_MIN && v <= INT_MAX) return static_cast<int>(v);
  }
  throw JsonFault(std::string(what) + " must be an integer in range");
}

int intMember(const json& object, const char* key) {
  return intOf(member(object, key), key);
}

std::string stringMember(const json& object, const char* key) {
  const json& value = member(object, key);
  if (!value.is_string()) throw JsonFault("\"" + std::string(key) + "\" must be a string");
  return value.get<std::string>();
}

Format formatOf(const std::string& name) {
  for (const Format f :
       {Format::SingleElimination, Format::DoubleElimination, Format::RoundRobin}) {
    if (name == formatName(f)) return f;
  }
  throw JsonFault("unknown format \"" + name + "\"");
}

std::vector<Entrant> entrantsOf(const json& list) {
  if (!list.is_array()) throw JsonFault("\"entrants\" must be an array");
  std::vector<Entrant> entrants;
  for (const json& e : list) {
    const json& rating = member(e, "rating");
    const json& bot = member(e, "bot");
    if (!rating.is_number()) throw JsonFault("an entrant's \"rating\" must be a number");
    if (!bot.is_boolean()) throw JsonFault("an entrant's \"bot\" must be true or false");
    entrants.push_back({.id = stringMember(e, "id"),
                        .name = stringMember(e, "name"),
                        .rating = rating.get<double>(),
                        .bot = bot.get<bool>()});
  }
  return entrants;
}

/// Replays one logged call; throws its refusal.
void replay(Tournament& t, const json& call, std::size_t n) {
  const std::string kind = stringMember(call, "call");
  const std::string where = "call " + std::to_string(n) + " (" + kind + ")";
  std::string refusal;
  if (kind == "start") {
    if (const Check<> c = t.start(intMember(call, "match")); !c) refusal = c.error();
  } else if (kind == "report") {
    const json& racks = member(call, "racks");
    if (!racks.is_array() || racks.size() != 2) throw JsonFault("\"racks\" must hold two numbers");
    const Check<> c = t.report(intMember(call, "match"), intMember(call, "winner"),
                               intOf(racks[0], "racks"), intOf(racks[1], "racks"));
    if (!c) refusal = c.error();
  } else if (kind == "forfeit") {
    if (const auto r = t.forfeit(intMember(call, "entrant")); !r) refusal = r.error();
  } else if (kind == "cancel") {
    if (const auto r = t.cancel(); !r) refusal = r.error();
  } else {
    throw JsonFault(where + " is no known call");
  }
  if (!refusal.empty()) throw JsonFault(where + " does not replay: " + refusal);
}

Tournament parse(const std::string& text) {
  const json doc = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded()) throw JsonFault("not JSON");
  if (intMember(doc, "version") != kJsonVersion) {
    throw JsonFault("version " + std::to_string(intMember(doc, "version")) + " is not " +
                    std::to_string(kJsonVersion));
  }
  Options options;
  options.raceTo = intMember(member(doc, "options"), "raceTo");
  Result<Tournament> made = Tournament::create(formatOf(stringMember(doc, "format")),
                                               entrantsOf(member(doc, "entrants")), options);
  if (!made) throw JsonFault(made.error());
  Tournament t = std::move(made.value());
  const json& log = member(doc, "log");
  if (!log.is_array()) throw JsonFault("\"log\" must be an array");
  for (std::size_t n = 0; n < log.size(); ++n) replay(t, log[n], n);
  if (member(doc, "matches") != matchesJson(t.matches())) {
    throw JsonFault("\"matches\" differ from the ones its log replays to");
  }
  return t;
}

}  // namespace

std::string Tournament::toJson() const {
  json entrants = json::array();
  for (const Entrant& e : entrants_) {
    entrants.push_back({{"id", e.id}, {"name", e.name}, {"rating", e.rating}, {"bot", e.bot}});
  }
  json log = json::array();
  for (const Event& e : log_) {
    switch (e.kind) {
      case Event::Kind::Start:
        log.push_back({{"call", "start"}, {"match", e.match}});
        break;
      case Event::Kind::Report:
        log.push_back({{"call", "report"},
                       {"match", e.match},
                       {"winner", e.entrant},
                       {"racks", {e.racksA, e.racksB}}});
        break;
      case Event::Kind::Forfeit:
        log.push_back({{"call", "forfeit"}, {"entrant", e.entrant}});
        break;
      case Event::Kind::Cancel:
        log.push_back({{"call", "cancel"}});
        break;
    }
  }
  const json doc = {{"version", kJsonVersion},
                    {"format", formatName(format_)},
                    {"options", {{"raceTo", options_.raceTo}}},
                    {"entrants", std::move(entrants)},
                    {"log", std::move(log)},
                    {"matches", matchesJson(matches_)}};
  return doc.dump();
}

Result<Tournament> Tournament::fromJson(const std::string& text) {
  try {
    return Result<Tournament>::ok(parse(text));
  } catch (const std::exception& e) {  // JsonFault, or nlohmann's (a string not UTF-8, say)
    std::string why = e.what();
    for (char& c : why) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    return Result<Tournament>::fail("bad_json", "tournament JSON: " + why);
  }
}

}  // namespace pool::tournament
