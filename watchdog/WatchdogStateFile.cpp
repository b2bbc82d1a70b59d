// Text format, one process a line after a header:
//   rgnav-watchdog-state 1
//   <module> <pid> <start time>
#include "watchdog/WatchdogStateFile.h"

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/common/AtomicFile.h"
#include "core/common/Errors.h"

namespace rgnav {
namespace {

const std::string kHeader = "rgnav-watchdog-state 1";

[[noreturn]] void throwFileError(const std::string& what, const std::string& path) {
  throw FileError(what + " " + path + ": " + std::system_category().message(errno));
}

std::string serialize(const std::vector<ProcessRecord>& records) {
  std::ostringstream text;
  text << kHeader << '\n';
  for (const ProcessRecord& r : records) {
    const bool ok = !r.module.empty() && r.module.find_first_of(" \t\r\n") == std::string::npos;
    if (!ok) throw InvalidArgumentError("state file: bad module name \"" + r.module + "\"");
    text << r.module << ' ' << r.pid << ' ' << r.startTime << '\n';
  }
  return text.str();
}

}  // namespace

WatchdogStateFile::WatchdogStateFile(std::string path) : path_(std::move(path)) {}

void WatchdogStateFile::write(const std::vector<ProcessRecord>& records) const {
  writeFileAtomically(path_, serialize(records));
}

std::vector<ProcessRecord> WatchdogStateFile::read() const {
  std::ifstream in(path_);
  if (!in) {
    std::error_code ec;
    if (!std::filesystem::exists(path_, ec) && !ec) return {};
    throw FileError("cannot open " + path_);
  }
  std::string line;
  if (!std::getline(in, line) || line != kHeader) throw FormatError(path_, 1, "not a watchdog state file");
  std::vector<ProcessRecord> records;
  for (std::size_t lineNo = 2; std::getline(in, line); ++lineNo) {
    std::istringstream fields(line);
    ProcessRecord r;
    std::string extra;
    if (!(fields >> r.module >> r.pid >> r.startTime) || (fields >> extra) || r.pid <= 1) {
      throw FormatError(path_, lineNo, "expected \"<module> <pid> <start time>\", got \"" + line + "\"");
    }
    records.push_back(r);
  }
  if (in.bad()) throwFileError("cannot read", path_);
  return records;
}

}  // namespace rgnav
