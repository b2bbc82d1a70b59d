// InputFile: POSIX open/read with every failure turned into a FileError that names the path.
#include "core/logs/InputFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

FileError fileError(const std::string& path, const std::string& what, int err) {
  return FileError(path + ": " + what + ": " + std::strerror(err));
}

// Runs a read call again while it is interrupted by a signal; returns the bytes read.
template <typename ReadCall>
std::size_t retryingRead(const std::string& path, ReadCall readCall) {
  for (;;) {
    const ssize_t n = readCall();
    if (n >= 0) {
      return static_cast<std::size_t>(n);
    }
    if (errno != EINTR) {
      throw fileError(path, "read error", errno);
    }
  }
}

}  // namespace

InputFile::InputFile(const std::string& path) : path_(path) {
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) {
    throw fileError(path, "cannot open", errno);
  }
  struct stat info {};
  if (::fstat(fd_, &info) != 0) {
    const int err = errno;
    ::close(fd_);
    throw fileError(path, "cannot stat", err);
  }
  if (!S_ISREG(info.st_mode)) {
    ::close(fd_);
    throw FileError(path + (S_ISDIR(info.st_mode) ? ": is a directory" : ": not a regular file"));
  }
}

InputFile::~InputFile() { ::close(fd_); }

std::size_t InputFile::read(unsigned char* dst, std::size_t capacity) {
  return retryingRead(path_, [&] { return ::read(fd_, dst, capacity); });
}

std::size_t InputFile::peekHead(unsigned char* dst, std::size_t capacity) const {
  return retryingRead(path_, [&] { return ::pread(fd_, dst, capacity, 0); });
}

}  // namespace rgnav
