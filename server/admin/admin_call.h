// The operator's end of the admin channel: one request line to the server's socket, one reply.
#pragma once

#include <chrono>
#include <string>

#include "core/result.h"

namespace pool::admin {

/// Sends `request` (one line) to the server listening at `socket_path` and returns its reply line.
/// Fails with a one-line reason when nobody listens there, the socket may not be used, or no
/// reply comes within `timeout`.
Result<std::string> call(const std::string& socket_path, const std::string& request,
                         std::chrono::milliseconds timeout = std::chrono::seconds(30));

}  // namespace pool::admin
