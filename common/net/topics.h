// The DDS topic names of the protocol, in one place.
#pragma once

#include <string_view>

namespace pool::net::topics {

inline constexpr std::string_view kMatchInfo = "pool/MatchInfo";              ///< lobby, key match
inline constexpr std::string_view kJoinRequest = "pool/JoinRequest";          ///< no key
inline constexpr std::string_view kJoinReply = "pool/JoinReply";              ///< key client
inline constexpr std::string_view kShotCommand = "pool/ShotCommand";          ///< no key
inline constexpr std::string_view kShotResult = "pool/ShotResult";            ///< key match + seat
inline constexpr std::string_view kTableSnapshot = "pool/TableSnapshot";      ///< key match
inline constexpr std::string_view kMatchState = "pool/MatchState";            ///< key match
inline constexpr std::string_view kPracticeCommand = "pool/PracticeCommand";  ///< no key
inline constexpr std::string_view kAimCommand = "pool/AimCommand";            ///< no key
inline constexpr std::string_view kCueAim = "pool/CueAim";                    ///< key match
inline constexpr std::string_view kPlayerStats = "pool/PlayerStats";  ///< key server, player, game
inline constexpr std::string_view kHistoryRequest = "pool/HistoryRequest";  ///< no key
inline constexpr std::string_view kHistoryShot = "pool/HistoryShot";        ///< no key
inline constexpr std::string_view kTournamentInfo = "pool/TournamentInfo";  ///< key tournament

}  // namespace pool::net::topics
