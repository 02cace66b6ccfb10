// An owned Cyclone DDS entity handle, deleted (with its children) when the owner goes.
#pragma once

#include <cstdint>

namespace pool::net {

/// Owns one DDS entity (participant, topic, reader, writer, condition, waitset). Move-only.
/// Destruction order between owners does not matter: deleting a participant deletes its children,
/// and deleting an already deleted entity is harmless.
class Entity {
 public:
  Entity() = default;
  /// Takes ownership of `handle` (> 0).
  explicit Entity(std::int32_t handle) : handle_(handle) {}
  ~Entity();
  Entity(const Entity&) = delete;
  Entity& operator=(const Entity&) = delete;
  Entity(Entity&& other) noexcept : handle_(other.handle_) { other.handle_ = 0; }
  Entity& operator=(Entity&& other) noexcept;

  /// The dds_entity_t; 0 when empty.
  std::int32_t handle() const { return handle_; }

 private:
  void reset();
  std::int32_t handle_ = 0;
};

}  // namespace pool::net
