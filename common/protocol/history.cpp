// The history request's signed encoding, its signature and the bounds the server answers within.
#include "protocol/history.h"

namespace pool::protocol {

std::vector<std::uint8_t> signedBytes(const HistoryRequest& r) {
  SignedEncoder e({MessageTag::History, r.match, -1, 0, r.request});
  e.u32(r.first_shot);
  e.u8(static_cast<std::uint8_t>(r.count));
  e.text(r.client, 40);
  return e.message();
}

void signHistory(HistoryRequest& request, const KeyPair& key) {
  request.public_key.assign(key.public_key.begin(), key.public_key.end());
  request.signature = signMessage(signedBytes(request), key);
}

SignatureCheck verifyHistory(const HistoryRequest& request) {
  if (request.signature.empty()) return SignatureCheck::Unsigned;
  return verifyMessage(signedBytes(request), request.signature, request.public_key);
}

Check<> checkHistoryRequest(const HistoryRequest& r) {
  auto refuse = [](const char* code, std::string sentence) {
    return Check<>::refuse(code, std::move(sentence));
  };
  if (r.client.empty() || r.client.size() > 40) return refuse("bad_client", "client: 1-40 bytes");
  if (r.match.empty() || r.match.size() > 40) return refuse("bad_match_id", "match: 1-40 bytes");
  if (r.first_shot < 1) return refuse("bad_shot", "first_shot: shots count from 1");
  if (r.count < 1 || r.count > kMaxHistoryShots) {
    return refuse("bad_count", "count: 1 to " + std::to_string(kMaxHistoryShots) + " shots");
  }
  return Check<>::pass();
}

}  // namespace pool::protocol
