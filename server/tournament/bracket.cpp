// Elimination brackets built by pairing nodes (entrant, winner, loser, bye) round by round.
#include "server/tournament/bracket.h"

#include "server/tournament/seeding.h"

#include <algorithm>
#include <string>

namespace pool::tournament {
namespace {

/// What stands in one place of a bracket's round.
struct BracketNode {
  enum class Kind : std::uint8_t { Bye, Entrant, Winner, Loser };
  Kind kind = Kind::Bye;
  int index = -1;  ///< entrant index (Entrant) or match index (Winner, Loser)
};

class BracketBuilder {
 public:
  /// x against y: a new match, or the one that is there when the other is a bye.
  BracketNode pair(BracketNode x, BracketNode y, const std::string& round, int stage,
                   MatchKind kind = MatchKind::Regular) {
    if (x.kind == BracketNode::Kind::Bye) return y;
    if (y.kind == BracketNode::Kind::Bye) return x;
    Match m;
    m.index = static_cast<int>(matches_.size());
    m.round = round;
    m.kind = kind;
    m.stage = stage;
    matches_.push_back(m);
    attach(x, m.index, 0);
    attach(y, m.index, 1);
    return {BracketNode::Kind::Winner, m.index};
  }

  /// One round: places 2i and 2i+1 of `nodes` paired. `losers` gets each pair's loser (a bye when
  /// no match was played).
  std::vector<BracketNode> round(const std::vector<BracketNode>& nodes, const std::string& name,
                                 int stage, std::vector<BracketNode>* losers = nullptr) {
    std::vector<BracketNode> next;
    for (std::size_t i = 0; i + 1 < nodes.size(); i += 2) {
      const std::size_t before = matches_.size();
      next.push_back(pair(nodes[i], nodes[i + 1], name, stage));
      if (losers) {
        losers->push_back(matches_.size() > before
                              ? BracketNode{BracketNode::Kind::Loser, next.back().index}
                              : BracketNode{});
      }
    }
    return next;
  }

  std::vector<Match> finish() {
    for (Match& m : matches_)
      m.state = m.a >= 0 && m.b >= 0 ? MatchState::Ready : MatchState::Waiting;
    return std::move(matches_);
  }

 private:
  void attach(BracketNode node, int match, int side) {
    switch (node.kind) {
      case BracketNode::Kind::Entrant:
        (side == 0 ? matches_[match].a : matches_[match].b) = node.index;
        break;
      case BracketNode::Kind::Winner:
        matches_[node.index].winnerTo = {match, side};
        break;
      case BracketNode::Kind::Loser:
        matches_[node.index].loserTo = {match, side};
        break;
      case BracketNode::Kind::Bye:
        break;
    }
  }

  std::vector<Match> matches_;
};

/// The first round's places: the entrant of each seed, a bye past the field.
std::vector<BracketNode> seededPlaces(const std::vector<int>& bySeed) {
  const int count = static_cast<int>(bySeed.size());
  std::vector<BracketNode> places;
  for (const int seed : bracketOrder(bracketSize(count))) {
    places.push_back(seed <= count ? BracketNode{BracketNode::Kind::Entrant, bySeed[seed - 1]}
                                   : BracketNode{});
  }
  return places;
}

/// log2 of a power of two.
int roundsOf(int size) {
  int rounds = 0;
  while ((1 << rounds) < size) ++rounds;
  return rounds;
}

std::string singleRoundName(int round, int rounds) {
  switch (rounds - round) {
    case 0:
      return "F";
    case 1:
      return "SF";
    case 2:
      return "QF";
    default:
      return "R" + std::to_string(round);
  }
}

}  // namespace

std::vector<Match> buildSingleElimination(const std::vector<int>& bySeed) {
  BracketBuilder builder;
  std::vector<BracketNode> nodes = seededPlaces(bySeed);
  const int rounds = roundsOf(static_cast<int>(nodes.size()));
  for (int r = 1; r <= rounds; ++r) nodes = builder.round(nodes, singleRoundName(r, rounds), r);
  return builder.finish();
}

std::vector<Match> buildDoubleElimination(const std::vector<int>& bySeed) {
  BracketBuilder builder;
  std::vector<BracketNode> winners = seededPlaces(bySeed);
  const int rounds = roundsOf(static_cast<int>(winners.size()));
  const auto wbName = [](int r) { return "WB R" + std::to_string(r); };
  const auto lbName = [](int r) { return "LB R" + std::to_string(r); };
  // Built in about the order they can be played: WB R1, WB R2, LB R1, LB R2, WB R3, LB R3, ...
  std::vector<BracketNode> dropped;
  winners = builder.round(winners, wbName(1), 0, &dropped);
  std::vector<BracketNode> losers;
  for (int r = 2; r <= rounds; ++r) {
    std::vector<BracketNode> dropping;
    winners = builder.round(winners, wbName(r), 0, &dropping);
    // The odd LB round: LB R1 pairs WB R1's losers; later ones pair the losers' bracket.
    const int odd = 2 * r - 3;
    losers = builder.round(r == 2 ? dropped : losers, lbName(odd), odd);
    // The even LB round: the survivors meet this WB round's losers.
    if (r % 2 == 0) std::reverse(dropping.begin(), dropping.end());
    std::vector<BracketNode> met;
    for (std::size_t i = 0; i < losers.size(); ++i) {
      met.push_back(builder.pair(losers[i], dropping[i], lbName(odd + 1), odd + 1));
    }
    losers = std::move(met);
  }
  builder.pair(winners.front(), losers.front(), "GF", 2 * rounds - 1, MatchKind::GrandFinal);
  return builder.finish();
}

}  // namespace pool::tournament
