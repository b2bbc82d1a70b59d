// Atomic file replacement (see AtomicFile.h).
#include "core/common/AtomicFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

constexpr mode_t kFileMode = 0644;

// Writes all of `content` to `fd` and fsyncs it; closes `fd` in any case. Returns 0 or the errno
// of the step that failed, with that step's name in `step`.
int writeAllAndSync(int fd, const std::string& content, const char*& step) {
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      step = "write";
      return err;
    }
    written += static_cast<std::size_t>(n);
  }
  const int synced = ::fsync(fd) == 0 ? 0 : errno;
  const int closed = ::close(fd) == 0 ? 0 : errno;
  step = "sync";
  return synced != 0 ? synced : closed;
}

// fsyncs the directory that holds `path`, so that a rename into it survives a crash.
void syncDirectoryOf(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  const std::string dir = parent.empty() ? std::string(".") : parent.string();
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw FileError(dir + ": cannot open directory to sync: " + std::strerror(errno));
  const int synced = ::fsync(fd) == 0 ? 0 : errno;
  ::close(fd);
  if (synced != 0) throw FileError(dir + ": cannot sync directory: " + std::strerror(synced));
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& content) {
  std::string temp = path + ".tmp.XXXXXX";
  // mkostemp creates a new file under a fresh name (O_EXCL: never through an existing name or a
  // symbolic link planted there), readable like any other file the project writes.
  const int fd = ::mkostemp(temp.data(), O_CLOEXEC);
  if (fd < 0) throw FileError(path + ": cannot create a temporary file beside it: " + std::strerror(errno));
  if (::fchmod(fd, kFileMode) != 0) {
    const int err = errno;
    ::close(fd);
    ::unlink(temp.c_str());
    throw FileError(temp + ": cannot set its mode: " + std::strerror(err));
  }
  const char* step = "";
  if (const int err = writeAllAndSync(fd, content, step); err != 0) {
    ::unlink(temp.c_str());
    throw FileError(temp + ": cannot " + step + ": " + std::strerror(err));
  }
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const int renameErr = errno;
    ::unlink(temp.c_str());
    throw FileError(path + ": cannot replace: " + std::strerror(renameErr));
  }
  syncDirectoryOf(path);
}

void appendToFileDurably(const std::string& path, const std::string& content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | O_NOFOLLOW, kFileMode);
  if (fd < 0) throw FileError(path + ": cannot open for appending: " + std::strerror(errno));
  struct stat before {};
  if (::fstat(fd, &before) != 0) {
    const int err = errno;
    ::close(fd);
    throw FileError(path + ": cannot stat: " + std::strerror(err));
  }
  const char* step = "";
  if (const int err = writeAllAndSync(fd, content, step); err != 0) {
    // A part of `content` may have been written (a full disk, a file size limit): cut it off, so
    // that appending the whole content again later does not leave a broken line inside the file.
    if (const int again = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOFOLLOW); again >= 0) {
      if (::ftruncate(again, before.st_size) == 0) ::fsync(again);
      ::close(again);
    }
    throw FileError(path + ": cannot " + step + ": " + std::strerror(err));
  }
}

std::optional<std::string> readCheckpoint(const std::string& path) {
  if (path.empty() || !std::filesystem::exists(path)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in.is_open()) throw FileError(path + ": cannot open: " + std::strerror(errno));
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) throw FileError(path + ": cannot read");
  return bytes.str();
}

}  // namespace rgnav
