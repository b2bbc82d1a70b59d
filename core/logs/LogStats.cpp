// LogStats: counting skipped lines, keeping the bounded problem list and describing the skips.
#include "core/logs/LogStats.h"

namespace rgnav {

namespace {

std::string located(const std::string& file, std::size_t line, const std::string& what) {
  return file + ":" + std::to_string(line) + ": " + what;
}

}  // namespace

void LogStats::addProblem(const std::string& file, std::size_t line, const std::string& what) {
  if (problems.size() < kMaxProblems) {
    problems.push_back(located(file, line, what));
  }
}

void LogStats::addMalformed(const std::string& file, std::size_t line, const std::string& what) {
  ++malformedLines;
  if (firstMalformed.empty()) firstMalformed = located(file, line, what);
  addProblem(file, line, what);
}

void LogStats::addOverLong(const std::string& file, std::size_t line, std::size_t maxLineLength) {
  ++overLongLines;
  const std::string what = "line longer than " + std::to_string(maxLineLength) + " bytes, skipped";
  if (firstOverLong.empty()) firstOverLong = located(file, line, what);
  addProblem(file, line, what);
}

void LogStats::addTruncation(const std::string& where) {
  truncated = true;
  truncation = where;
  if (problems.size() < kMaxProblems) problems.push_back(where);
}

std::vector<std::string> describeSkips(const LogStats& stats) {
  std::vector<std::string> lines;
  if (stats.malformedLines > 0)
    lines.push_back(std::to_string(stats.malformedLines) + " malformed lines skipped, the first " + stats.firstMalformed);
  if (stats.overLongLines > 0)
    lines.push_back(std::to_string(stats.overLongLines) + " over-long lines skipped, the first " + stats.firstOverLong);
  if (stats.truncated) lines.push_back("the log ends early, the rest is lost: " + stats.truncation);
  return lines;
}

std::string skipFigures(const LogStats& stats) {
  return "skipped_lines=" + std::to_string(stats.skippedLines()) + " truncated=" + (stats.truncated ? "yes" : "no");
}

}  // namespace rgnav
