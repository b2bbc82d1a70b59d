// LogStats: counting skipped lines and keeping the bounded problem list.
#include "core/logs/LogStats.h"

namespace rgnav {

void LogStats::addProblem(const std::string& file, std::size_t line, const std::string& what) {
  if (problems.size() < kMaxProblems) {
    problems.push_back(file + ":" + std::to_string(line) + ": " + what);
  }
}

void LogStats::addMalformed(const std::string& file, std::size_t line, const std::string& what) {
  ++malformedLines;
  addProblem(file, line, what);
}

void LogStats::addOverLong(const std::string& file, std::size_t line, std::size_t maxLineLength) {
  ++overLongLines;
  addProblem(file, line, "line longer than " + std::to_string(maxLineLength) + " bytes, skipped");
}

}  // namespace rgnav
