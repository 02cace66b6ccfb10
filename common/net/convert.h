// Conversions between the wire types of pool.idl and domain types (physics balls and events, shot
// requests). The only place where both meet.
#pragma once

#include <span>
#include <vector>

#include "core/result.h"
#include "net/messages.h"
#include "net/sample.h"
#include "physics/ball.h"
#include "physics/events.h"
#include "protocol/shot_request.h"

namespace pool::net {

/// A ball on the wire. Exact: every double is copied bit for bit. A pocket name longer than 32
/// characters is cut (the physics' names are shorter).
pool_BallState toWire(const physics::Ball& ball);
/// A ball from the wire; fails on an id outside 0–21 or an unknown motion state. Values are not
/// range-checked (a snapshot's balls may be anywhere the physics put them).
Result<physics::Ball> fromWire(const pool_BallState& ball);

/// An event on the wire. Exact, except a `where` longer than 32 characters, which is cut.
pool_ShotEvent toWire(const physics::Event& event);
/// An event from the wire; fails on an unknown event type.
Result<physics::Event> fromWire(const pool_ShotEvent& event);

/// Fills a ball sequence (TableSnapshot::balls, MatchState::balls) with a buffer it owns. Returns
/// false when more than MAX_BALLS were given (the first MAX_BALLS are kept).
bool putBalls(dds_sequence_pool_BallState& seq, std::span<const physics::Ball> balls);
/// Every ball of a sequence; fails on the first bad one, naming its index.
Result<std::vector<physics::Ball>> getBalls(const dds_sequence_pool_BallState& seq);

/// Fills an event sequence (ShotResult::events) with a buffer it owns. Returns false when more
/// than MAX_EVENTS were given (the first MAX_EVENTS are kept).
bool putEvents(dds_sequence_pool_ShotEvent& seq, std::span<const physics::Event> events);
/// Every event of a sequence; fails on the first bad one, naming its index.
Result<physics::EventLog> getEvents(const dds_sequence_pool_ShotEvent& seq);

/// A shot request as a ShotCommand sample (the signature in a buffer the sample owns). Text that
/// does not fit its bound is cut; a signature longer than 64 bytes is cut.
Sample<pool_ShotCommand> toWire(const protocol::ShotRequest& request);
/// A ShotCommand as a shot request; fails only on what the domain type cannot hold (an unknown
/// option). Ranges are validateShotCommand's job (shot_command_check.h).
Result<protocol::ShotRequest> fromWire(const pool_ShotCommand& command);

/// Domain option <-> wire option (fails on a value that is no enumerator).
pool_ShotOption toWire(protocol::ShotOption option);
Result<protocol::ShotOption> fromWire(const pool_ShotOption& option);

}  // namespace pool::net
