// LogStats: what a log reader has read and skipped so far, with the first few problems spelled
// out as "file:line: what" for people, the first of each kind kept apart, and whether the log
// ended early (a compressed stream cut short or corrupt: the rest of the log is lost).
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
  std::string firstMalformed;        // "file:line: what" of the first malformed line, or empty
  std::string firstOverLong;         // "file:line: what" of the first over-long line, or empty
  bool truncated = false;            // reading stopped at damaged compressed data
  std::string truncation;            // "file:line: what" where it stopped, or empty

  // Lines the reader read past without using them: malformed and over-long ones.
  std::size_t skippedLines() const { return malformedLines + overLongLines; }
  // Whether every line of the file was read and used (unknown message types aside).
  bool wholeLog() const { return skippedLines() == 0 && !truncated; }

  // Records "file:line: what" while fewer than kMaxProblems are held.
  void addProblem(const std::string& file, std::size_t line, const std::string& what);
  // Counts a skipped malformed line and records why.
  void addMalformed(const std::string& file, std::size_t line, const std::string& what);
  // Counts a skipped over-long line and records it.
  void addOverLong(const std::string& file, std::size_t line, std::size_t maxLineLength);
  // Records that reading stopped because the compressed data is damaged; `where` is
  // "file:line: what" (a FormatError's message).
  void addTruncation(const std::string& where);
};

// For people: one line per kind of skip ("76 malformed lines, the first file:line: what"; "the log
// ends early: file:line: what"), none for a whole log.
std::vector<std::string> describeSkips(const LogStats& stats);
// The counts as "skipped_lines=N truncated=yes|no".
std::string skipFigures(const LogStats& stats);

}  // namespace rgnav
