// Reading join requests and shot commands off the wire, refusing what cannot be read.
#include "wire_requests.h"

#include "net/convert.h"
#include "net/wire_fields.h"
#include "wire_enums.h"

namespace pool::server {

Result<JoinCommand> joinCommand(const pool_JoinRequest& r) {
  const auto action = joinActionFromWire(r.action);
  if (!action) return Result<JoinCommand>::fail("action: not a known join action");
  if (!net::terminated(r.client) || !net::terminated(r.match) || !net::terminated(r.name)) {
    return Result<JoinCommand>::fail("client, match, name: text must fit its bound");
  }
  JoinCommand c;
  c.client = std::string(net::textOf(r.client));
  c.request = r.request;
  c.protocol_version = r.protocol_version;
  c.match = std::string(net::textOf(r.match));
  c.action = *action;
  c.seat = r.seat;
  c.name = std::string(net::textOf(r.name));
  c.token = r.seat_token;
  const auto key = net::elementsOf(r.public_key);
  c.public_key.assign(key.begin(), key.end());
  c.seq = r.seq;
  const auto signature = net::elementsOf(r.signature);
  c.signature.assign(signature.begin(), signature.end());
  return Result<JoinCommand>::ok(std::move(c));
}

pool_JoinReply unreadableJoinReply(const pool_JoinRequest& r, const std::string& reason,
                                   const std::string& server_id) {
  pool_JoinReply reply{};
  net::setText(reply.client, net::textOf(r.client));
  reply.request = r.request;
  net::setText(reply.server, server_id);
  net::setText(reply.match, net::textOf(r.match));
  // The action itself may be what could not be read, so it is not echoed.
  reply.action = pool_JOIN_SEAT;
  reply.outcome = pool_JOIN_NOT_ALLOWED;
  net::setText(reply.reason, reason);
  reply.seat = -1;
  return reply;
}

protocol::CommandLimits commandLimits(const table::TableSpec& spec) {
  protocol::CommandLimits limits;
  limits.miscue_limit = spec.params.miscue_limit;
  limits.half_length = spec.length / 2;
  limits.half_width = spec.width / 2;
  return limits;
}

ReadCommand readCommand(const pool_ShotCommand& command, const protocol::CommandLimits& limits) {
  ReadCommand out;
  out.refusal.seat = command.seat;
  out.refusal.seq = command.seq;
  const net::CommandCheck check = net::validateShotCommand(command, limits);
  if (!check.ok()) {
    const bool signature = check.problem == net::CommandProblem::BadSignature;
    out.refusal.rejection = {signature ? Reject::BadSignature : Reject::Malformed, check.text};
    return out;
  }
  auto request = net::fromWire(command);
  if (!request) {
    out.refusal.rejection = {Reject::Malformed, request.error()};
    return out;
  }
  out.request = std::move(*request);
  return out;
}

}  // namespace pool::server
