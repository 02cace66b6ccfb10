// Endpoints kept per match, each match's under a publisher or subscriber of its own partition:
// the one way every per-match topic (states, results, frames, and any later one) is scoped.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "core/result.h"
#include "net/match_partition.h"
#include "net/participant.h"
#include "net/partition.h"

namespace pool::net {

/// A set of endpoints (`Set`, built from a `Scope`: Publisher for writers, Subscriber for
/// readers) per match, in the match's partition (matchPartition). The sets are destroyed before
/// their scope.
template <class Scope, class Set>
class MatchScopes {
 public:
  /// The set of `match`; when it has none, `make(const Scope&)` builds one (a
  /// std::unique_ptr<Set>) under a new scope in the match's partition. Fails, making nothing,
  /// for an id that names no partition or when `limit` sets are open already.
  template <class Make>
  Result<Set*> open(const Participant& participant, const std::string& match, std::size_t limit,
                    Make&& make) {
    if (auto it = entries_.find(match); it != entries_.end()) {
      return Result<Set*>::ok(it->second->set.get());
    }
    auto partition = matchPartition(match);
    if (!partition) return Result<Set*>::fail(partition.error());
    if (entries_.size() >= limit) {
      return Result<Set*>::fail("no partition for match " + match + ": " + std::to_string(limit) +
                                " matches followed already");
    }
    auto entry = std::make_unique<Entry>(participant, *partition);
    entry->set = make(std::as_const(entry->scope));
    Set* set = entry->set.get();
    entries_.emplace(match, std::move(entry));
    return Result<Set*>::ok(set);
  }

  /// The set of `match`, or null.
  Set* find(const std::string& match) const {
    const auto it = entries_.find(match);
    return it == entries_.end() ? nullptr : it->second->set.get();
  }

  /// Deletes `match`'s set and its scope (nothing when it has none).
  void close(const std::string& match) { entries_.erase(match); }

  /// Calls `each(const std::string& match, Set&)` on every set, in match order.
  template <class F>
  void forEach(F&& each) const {
    for (const auto& [match, entry] : entries_) each(match, *entry->set);
  }

  std::size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    Entry(const Participant& participant, const std::string& partition)
        : scope(participant, {partition}) {}
    Scope scope;               ///< declared first: destroyed after the set
    std::unique_ptr<Set> set;  ///< the endpoints under `scope`
  };
  std::map<std::string, std::unique_ptr<Entry>> entries_;
};

}  // namespace pool::net
