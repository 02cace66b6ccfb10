// Who is still there: a client the server answered is present while the DDS writer of its
// requests is alive (JoinRequest has no key, so a writer's liveliness and matching, not an
// instance per client id, is a client's presence).
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

namespace pool::server {

/// The clients the server answered, each tied to the join-request writer (a publication handle)
/// whose going ends its presence. Anyone may write under any client id, so a seated client stays
/// tied to the writer of the signed seat request that seated it: a stranger's requests under her
/// id neither move nor end her presence. What one writer brings is bounded: past
/// kClientsPerWriter, its oldest client that holds no seat is let go. Holds nothing DDS.
class Presence {
 public:
  /// Clients one writer may keep present (a program runs a handful; a flood of invented ids keeps
  /// this many).
  static constexpr std::size_t kClientsPerWriter = 64;

  /// A client let go: its id, and the DDS participant its last answered request came from.
  struct Gone {
    std::string client;
    std::string sender;
  };

  /// The server answered `client`'s request, read from `writer` of participant `sender`.
  /// `seated`: an accepted request that gives or keeps the client a seat (signed by the seat's
  /// key): the client is tied to `writer` from now on. Otherwise an untied client follows its
  /// latest writer, and a tied one stays where it is. Returns the clients let go to keep `writer`
  /// within its bound (they are gone).
  std::vector<Gone> answered(const std::string& client, std::uint64_t writer,
                             const std::string& sender, bool seated);
  /// Unties every tied client for which `holds_seat` is false (it left, or its seats were freed).
  void untieUnless(const std::function<bool(const std::string&)>& holds_seat);
  /// Lets go of, and returns, the clients whose writer is not among `alive` (ascending).
  std::vector<Gone> sweep(const std::vector<std::uint64_t>& alive);

  /// Whether a client was tied to a writer since the last sweep (its writer may already be gone).
  bool fresh() const { return fresh_; }
  /// Clients present now.
  std::size_t size() const { return clients_.size(); }
  /// Whether `client` is present.
  bool present(const std::string& client) const { return clients_.count(client) > 0; }

 private:
  struct Client {
    std::uint64_t writer = 0;
    std::string sender;
    bool tied = false;  ///< to the writer of its seat request
  };
  struct Writer {
    std::deque<std::string> order;  ///< clients in the order they came (some may have moved on)
    std::size_t count = 0;          ///< those still the writer's
  };
  /// Lets go of `writer`'s oldest untied clients while it has more than kClientsPerWriter.
  std::vector<Gone> trim(std::uint64_t writer);
  /// Drops from `w.order` the ids no longer `writer`'s, and repeats.
  void compact(std::uint64_t writer, Writer& w);

  std::unordered_map<std::string, Client> clients_;
  std::unordered_map<std::uint64_t, Writer> writers_;
  bool fresh_ = false;
};

}  // namespace pool::server
