// ReplayMode: how fast a log is replayed (real time scaled by a factor, or as fast as consumers
// take records), and its text form in configuration: "realtime", "x100" / "100", "max" / "asfast".
#pragma once

#include <string>
#include <string_view>

namespace rgnav {

struct ReplayMode {
  enum class Kind { RealTime, AsFastAsConsumed };

  Kind kind = Kind::RealTime;
  double speed = 1.0;  // RealTime: log seconds per wall second (1 = real time, 100 = 100x faster)

  friend bool operator==(const ReplayMode&, const ReplayMode&) = default;
};

// "realtime" -> speed 1; "x<k>" or "<k>" -> speed k (a positive finite number, e.g. "x100",
// "x0.5"); "max" or "asfast" -> AsFastAsConsumed. Letter case is ignored. Throws ConfigError on
// anything else.
ReplayMode parseReplayMode(std::string_view text);

// "realtime" for speed 1, "x<k>" for other speeds, "asfast"; parseReplayMode() reads it back.
std::string formatReplayMode(const ReplayMode& mode);

}  // namespace rgnav
