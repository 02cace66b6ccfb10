// A bounded pool of slots shared fairly among keys (a connection's source address): when it is
// full, a key holding fewer than the heaviest key takes a slot from it, so one address flooding
// the pool never locks out another.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace pool::web {

class FairSlots {
 public:
  explicit FairSlots(std::size_t capacity) : capacity_(capacity) {}

  struct Admission {
    bool admitted = false;
    /// A slot taken back to make room (admitted only): its holder must be closed by the caller.
    std::optional<std::uint64_t> evicted;
  };

  /// Asks for a slot for `id` (ids grow: a smaller id is older) held under `key`. Admitted while
  /// the pool has room; when full, admitted only when `key` holds at least two slots fewer than
  /// the key holding the most, whose oldest slot is then released and named to be evicted.
  Admission admit(const std::string& key, std::uint64_t id) {
    Admission answer;
    if (owner_.size() >= capacity_) {
      const auto mine = by_key_.find(key);
      const std::size_t held = mine == by_key_.end() ? 0 : mine->second.size();
      auto heaviest = by_key_.end();
      for (auto it = by_key_.begin(); it != by_key_.end(); ++it) {
        if (heaviest == by_key_.end() || it->second.size() > heaviest->second.size()) heaviest = it;
      }
      if (heaviest == by_key_.end() || heaviest->second.size() < held + 2) return answer;
      answer.evicted = *heaviest->second.begin();
      release(*answer.evicted);
    }
    owner_[id] = key;
    by_key_[key].insert(id);
    answer.admitted = true;
    return answer;
  }

  /// Gives back the slot of `id` (nothing when it holds none).
  void release(std::uint64_t id) {
    const auto it = owner_.find(id);
    if (it == owner_.end()) return;
    const auto key = by_key_.find(it->second);
    key->second.erase(id);
    if (key->second.empty()) by_key_.erase(key);
    owner_.erase(it);
  }

  std::size_t size() const { return owner_.size(); }
  std::size_t capacity() const { return capacity_; }
  /// Slots held under `key`.
  std::size_t held(const std::string& key) const {
    const auto it = by_key_.find(key);
    return it == by_key_.end() ? 0 : it->second.size();
  }

 private:
  std::size_t capacity_;
  std::map<std::uint64_t, std::string> owner_;
  std::map<std::string, std::set<std::uint64_t>> by_key_;
};

}  // namespace pool::web
