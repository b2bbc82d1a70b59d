// Event log: file appends with O_APPEND (one write per line) and a bounded in-memory buffer.
#include "watchdog/EventLog.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/common/Errors.h"
#include "watchdog/IsoTime.h"

namespace rgnav {
namespace {

// Only the file's tail is read to find the last ID; a line is far shorter than this.
constexpr std::streamoff kTailBytes = 64 * 1024;

std::string oneWord(const std::string& text) {
  if (text.empty()) return "-";
  std::string out = text;
  std::replace_if(out.begin(), out.end(), [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }, '_');
  return out;
}

std::string oneLine(const std::string& text) {
  std::string out = text;
  std::replace_if(out.begin(), out.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return out;
}

std::string formatLine(const Event& e) {
  return formatIsoUtcMillis(e.time) + ' ' + std::to_string(e.id) + ' ' + e.module + ' ' + e.event + ' ' +
         e.detail + '\n';
}

// The largest ID among the complete lines at the end of an existing log, 0 if there is none.
std::uint64_t lastIdInFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return 0;
  const std::streamoff size = in.tellg();
  const std::streamoff start = std::max<std::streamoff>(0, size - kTailBytes);
  in.seekg(start);
  std::string line;
  if (start > 0) std::getline(in, line);  // starts mid-line
  std::uint64_t last = 0;
  while (std::getline(in, line)) {
    if (in.eof()) break;  // no newline: an incomplete last line
    std::istringstream fields(line);
    std::string time;
    std::uint64_t id = 0;
    if (fields >> time >> id) last = std::max(last, id);
  }
  return last;
}

}  // namespace

EventLog::EventLog(const std::string& path, std::size_t capacity)
    : path_(path), capacity_(capacity), lastId_(lastIdInFile(path)) {
  if (capacity_ == 0) throw InvalidArgumentError("event log " + path + ": capacity must be positive");
  fd_ = UniqueFd(open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644));
  if (!fd_.valid()) {
    throw FileError("cannot open event log " + path + ": " + std::system_category().message(errno));
  }
}

std::uint64_t EventLog::record(const std::string& module, const std::string& event, const std::string& detail) {
  const std::lock_guard<std::mutex> lock(mutex_);
  const Event e{++lastId_, std::chrono::system_clock::now(), oneWord(module), oneWord(event), oneLine(detail)};
  events_.push_back(e);
  if (events_.size() > capacity_) events_.pop_front();
  const std::string line = formatLine(e);
  ssize_t n = 0;
  do {
    n = ::write(fd_.get(), line.data(), line.size());
  } while (n < 0 && errno == EINTR);
  if (n != static_cast<ssize_t>(line.size())) {
    const std::string why = n < 0 ? std::system_category().message(errno) : "short write";
    throw FileError("cannot append to event log " + path_ + ": " + why);
  }
  return e.id;
}

EventsSince EventLog::since(std::uint64_t id) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  EventsSince out;
  out.missed = id < lastId_ && (events_.empty() || id + 1 < events_.front().id);
  for (const Event& e : events_) {
    if (e.id > id) out.events.push_back(e);
  }
  return out;
}

std::uint64_t EventLog::lastId() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return lastId_;
}

}  // namespace rgnav
