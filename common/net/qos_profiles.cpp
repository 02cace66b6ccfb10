// The named QoS profiles' values.
#include "net/qos_profiles.h"

namespace pool::net::qos {

namespace {

QosProfile make(Reliability reliability, Durability durability, std::uint32_t depth) {
  QosProfile p;
  p.reliability = reliability;
  p.durability = durability;
  p.history_depth = depth;
  return p;
}

/// Reliable keep-all, liveliness `lease`, no autodispose: what a player's writers use.
QosProfile playerWriter(std::chrono::nanoseconds lease) {
  QosProfile p = make(Reliability::Reliable, Durability::Volatile, 0);
  p.liveliness_lease = lease;
  p.autodispose = false;
  return p;
}

}  // namespace

QosProfile lobby() {
  return make(Reliability::Reliable, Durability::TransientLocal, 1);
}

QosProfile joinReply() {
  return make(Reliability::Reliable, Durability::TransientLocal, 1);
}

QosProfile joinRequest(std::chrono::nanoseconds lease) {
  return playerWriter(lease);
}

QosProfile command(std::chrono::nanoseconds lease) {
  return playerWriter(lease);
}

QosProfile result() {
  return make(Reliability::Reliable, Durability::TransientLocal, 1);
}

QosProfile strayResult() {
  return make(Reliability::Reliable, Durability::Volatile, 1);
}

QosProfile snapshot() {
  return make(Reliability::BestEffort, Durability::Volatile, 1);
}

QosProfile aim() {
  return make(Reliability::BestEffort, Durability::Volatile, 1);
}

QosProfile aimReader() {
  return make(Reliability::BestEffort, Durability::Volatile, 64);
}

QosProfile state() {
  return make(Reliability::Reliable, Durability::TransientLocal, 1);
}

QosProfile history() {
  return make(Reliability::Reliable, Durability::Volatile, 32);
}

}  // namespace pool::net::qos
