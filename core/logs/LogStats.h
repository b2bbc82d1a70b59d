// LogStats: what a log reader has read and skipped so far, with the first few problems spelled
// out as "file:line: what" for people.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rgnav {

struct LogStats {
  static constexpr std::size_t kMaxProblems = 20;

  std::size_t lines = 0;             // text lines read
  std::size_t scans = 0;             // laser scans yielded
  std::size_t odometryReadings = 0;  // odometry readings yielded
  std::size_t malformedLines = 0;    // lines or entries skipped because they could not be parsed
  std::size_t overLongLines = 0;     // lines skipped because they exceed the line length cap
  std::size_t unknownMessages = 0;   // lines of a message type the reader does not know
  std::size_t droppedRanges = 0;     // beams the source gave as NaN, infinity or negative
  std::size_t noReturnRanges = 0;    // beams at or beyond the maximum range
  std::vector<std::string> problems; // the first kMaxProblems problems, "file:line: what"

  // Records "file:line: what" while fewer than kMaxProblems are held.
  void addProblem(const std::string& file, std::size_t line, const std::string& what);
  // Counts a skipped malformed line and records why.
  void addMalformed(const std::string& file, std::size_t line, const std::string& what);
  // Counts a skipped over-long line and records it.
  void addOverLong(const std::string& file, std::size_t line, std::size_t maxLineLength);
};

}  // namespace rgnav
