// Text format, one process a line after a header:
//   rgnav-watchdog-state 1
//   <module> <pid> <start time>
#include "watchdog/WatchdogStateFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/common/Errors.h"
#include "watchdog/UniqueFd.h"

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

void writeAll(int fd, const std::string& data, const std::string& path) {
  std::size_t done = 0;
  while (done < data.size()) {
    const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throwFileError("cannot write", path);
    done += static_cast<std::size_t>(n);
  }
}

void syncDirectoryOf(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  const std::string dir = parent.empty() ? std::filesystem::current_path().string() : parent.string();
  const UniqueFd fd(open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (!fd.valid() || fsync(fd.get()) != 0) throwFileError("cannot sync directory", dir);
}

}  // namespace

WatchdogStateFile::WatchdogStateFile(std::string path) : path_(std::move(path)) {}

void WatchdogStateFile::write(const std::vector<ProcessRecord>& records) const {
  const std::string data = serialize(records);
  const std::string tmp = path_ + ".tmp";
  {
    const UniqueFd fd(open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
    if (!fd.valid()) throwFileError("cannot create", tmp);
    try {
      writeAll(fd.get(), data, tmp);
      if (fsync(fd.get()) != 0) throwFileError("cannot sync", tmp);
    } catch (const FileError&) {
      unlink(tmp.c_str());
      throw;
    }
  }
  if (rename(tmp.c_str(), path_.c_str()) != 0) {
    const int error = errno;
    unlink(tmp.c_str());
    errno = error;
    throwFileError("cannot rename " + tmp + " to", path_);
  }
  syncDirectoryOf(path_);
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
