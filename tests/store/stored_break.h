// A seated match's break, accepted and stored: the record the store tests write and read.
#pragma once

#include <memory>

#include "server/match_fixture.h"
#include "server/store/match_store.h"

namespace pool::store::test {

/// A seated match (srv-1) with its break accepted (in motion), the answer kept.
struct BrokenMatch {
  std::unique_ptr<server::Match> match = server::test::seatedMatch();
  server::CommandAnswer answer = match->handleShot(server::test::breakShot(), 0.0);
};

/// Stores the break of `b` as shot 1 of srv-1 with the match as it leaves it; returns that match.
inline server::MatchSnapshot storeBreak(MatchStore& store, const BrokenMatch& b) {
  server::MatchSnapshot after = b.match->snapshot();
  after.number = 1;
  EXPECT_TRUE(b.answer.record);
  if (b.answer.record) {
    store.recordShot(*b.answer.record, rules::describe(b.answer.record->verdict), after);
  }
  return after;
}

}  // namespace pool::store::test
