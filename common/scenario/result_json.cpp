// The result JSON of SIM-CONTRACT.md: a line per event, ball and sample; round-trip numbers.
#include <algorithm>
#include <nlohmann/json.hpp>

#include "scenario/scenario.h"

namespace pool::scenario {
namespace {

using Json = nlohmann::ordered_json;  // keeps the contract's key order

// -0.0 prints as "-0.0"; the output says 0.0 for every zero.
double clean(double x) {
  return x == 0.0 ? 0.0 : x;
}

Json eventJson(const physics::Event& e) {
  Json j;
  j["t"] = clean(e.t);
  j["type"] = physics::toString(e.type);
  j["balls"] = e.ball_b >= 0 ? Json::array({e.ball_a, e.ball_b}) : Json::array({e.ball_a});
  if (e.type == physics::EventType::BallCushion) j["cushion"] = e.where;
  if (e.type == physics::EventType::Pocket) j["pocket"] = e.where;
  if (e.type == physics::EventType::Respot && !e.where.empty()) j["reason"] = e.where;
  return j;
}

Json positionJson(const physics::Ball& b) {
  Json j;
  j["id"] = b.id;
  j["x"] = clean(b.pos.x());
  j["y"] = clean(b.pos.y());
  j["z"] = clean(b.pos.z());
  return j;
}

std::vector<physics::Ball> sortedById(std::vector<physics::Ball> balls) {
  std::stable_sort(balls.begin(), balls.end(),
                   [](const auto& a, const auto& b) { return a.id < b.id; });
  return balls;
}

Json sampleJson(const physics::Sample& sample) {
  Json balls = Json::array();
  for (const auto& b : sortedById(sample.balls)) balls.push_back(positionJson(b));
  Json j;
  j["t"] = clean(sample.t);
  j["balls"] = std::move(balls);
  return j;
}

// `"key": [` with one compact element per line, then `]`.
void appendArray(std::string& out, const char* key, const std::vector<Json>& items) {
  out += ",\n  \"" + std::string(key) + "\": [";
  for (std::size_t i = 0; i < items.size(); ++i) {
    out += (i == 0 ? "\n    " : ",\n    ") + items[i].dump();
  }
  out += items.empty() ? "]" : "\n  ]";
}

std::vector<Json> eventsJson(const physics::EventLog& log) {
  physics::EventLog events = log;
  std::stable_sort(events.begin(), events.end(),
                   [](const auto& a, const auto& b) { return a.t < b.t; });
  std::vector<Json> out;
  for (const auto& e : events) out.push_back(eventJson(e));
  return out;
}

std::vector<Json> finalBallsJson(const std::vector<physics::Ball>& balls) {
  std::vector<Json> out;
  for (const auto& b : sortedById(balls)) {
    Json j = positionJson(b);
    j["state"] = physics::toString(b.state);
    out.push_back(std::move(j));
  }
  return out;
}

}  // namespace

std::string resultJson(const Scenario& scenario, const physics::ShotOutcome& outcome) {
  std::string out = "{\n  \"version\": 1";
  const Json t_rest =
      outcome.t_rest && !outcome.truncated ? Json(clean(*outcome.t_rest)) : Json(nullptr);
  out += ",\n  \"t_rest\": " + t_rest.dump();
  if (outcome.truncated) out += ",\n  \"truncated\": true";
  appendArray(out, "events", eventsJson(outcome.events));
  appendArray(out, "balls", finalBallsJson(outcome.balls));
  if (scenario.options.sample_hz > 0.0) {
    std::vector<Json> samples;
    for (const auto& s : outcome.trajectory) samples.push_back(sampleJson(s));
    appendArray(out, "trajectory", samples);
  }
  return out + "\n}\n";
}

}  // namespace pool::scenario
