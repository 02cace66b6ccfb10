// The contact pairs and the names of the models the physics implements for each.
#include "table/contact_models.h"

#include <algorithm>
#include <utility>

#include "core/text.h"

namespace pool::table {
namespace {

using Names = std::vector<std::string_view>;

struct PairModels {
  std::string_view pair;
  Names models;
  std::string ContactModels::*field;
};

const std::vector<PairModels>& table() {
  static const std::vector<PairModels> pairs = {
      {"ball_cloth", {"leckie_greenspan2005"}, &ContactModels::ball_cloth},
      {"ball_ball", {"alciatore"}, &ContactModels::ball_ball},
      {"ball_cushion",
       {"han2005", "mathavan2010", "stronge_compliant"},
       &ContactModels::ball_cushion},
      {"ball_slate", {"rigid_coulomb"}, &ContactModels::ball_slate},
      {"cue_ball", {"alciatore"}, &ContactModels::cue_ball},
  };
  return pairs;
}

const PairModels* find(std::string_view pair) {
  const auto& pairs = table();
  const auto it =
      std::find_if(pairs.begin(), pairs.end(), [&](const PairModels& p) { return p.pair == pair; });
  return it == pairs.end() ? nullptr : &*it;
}

std::string joined(const Names& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

}  // namespace

const std::vector<std::string_view>& contactPairs() {
  static const Names pairs = [] {
    Names out;
    for (const auto& p : table()) out.push_back(p.pair);
    return out;
  }();
  return pairs;
}

const std::vector<std::string_view>& knownModels(std::string_view pair) {
  static const Names none;
  const PairModels* p = find(pair);
  return p ? p->models : none;
}

Check<> setModel(ContactModels& models, std::string_view pair, std::string_view name) {
  const PairModels* p = find(pair);
  if (!p)
    return Check<>::refuse("unknown_pair",
                           "unknown contact pair (known: " + joined(contactPairs()) + ")");
  if (std::find(p->models.begin(), p->models.end(), name) == p->models.end()) {
    return Check<>::refuse("unknown_model", "unknown model '" + escapedForLog(name) +
                                                "' (known: " + joined(p->models) + ")");
  }
  models.*(p->field) = std::string(name);
  return Check<>::pass();
}

}  // namespace pool::table
