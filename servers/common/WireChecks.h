// WireChecks: the checks every servant runs on the arguments a call brings from the wire,
// before any of them reaches a module's state (Common.idl: how operations fail). Each failed
// check throws RGNav::InvalidArgument naming the argument. The bounds are stated here: strings
// are bounded in length; counts are capped by each server's --max-batch; the one sequence a
// client sends, LowLevelDrive::setChain's segments, is bounded by MAX_CHAIN_SEGMENTS (the ORB
// itself bounds a message by omniORB's giopMaxMsgSize).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "Common.hh"

namespace rgnav::wire {

// Longest consumer, follower, module, region and object name a call may carry.
constexpr std::size_t kMaxNameLength = 256;
// Longest path a call may carry (exportMap's directory).
constexpr std::size_t kMaxPathLength = 1024;

[[noreturn]] void refuse(const char* field, const std::string& why);

void requireFinite(double value, const char* field);
void requireFinite(const RGNav::Point2D& point, const char* field);
void requireFinite(const RGNav::Pose2D& pose, const char* field);
// nsec below 10^9.
void requireValid(const RGNav::Time& stamp, const char* field);
// IDs start at 1: 0 names nothing.
void requireId(std::uint64_t id, const char* field);
// 1 <= first <= last.
void requireIdRange(std::uint64_t first, std::uint64_t last, const char* firstField, const char* lastField);
// At least 1; more than `cap` asks for `cap` (IDL counts are unsigned: a negative count sent as
// one is a huge count and is capped too).
std::size_t cappedCount(std::uint32_t requested, std::uint32_t cap, const char* field);
// At most maxLength bytes, no control characters; empty only where `mayBeEmpty`.
std::string checkedName(const char* name, const char* field, bool mayBeEmpty = true,
                        std::size_t maxLength = kMaxNameLength);

}  // namespace rgnav::wire
