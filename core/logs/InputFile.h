// InputFile: a regular file opened read-only for sequential raw byte reads. Opening checks that
// the path exists, is not a directory and is readable, and throws FileError naming the path.
#pragma once

#include <cstddef>
#include <string>

namespace rgnav {

class InputFile {
 public:
  explicit InputFile(const std::string& path);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  // Reads up to `capacity` bytes; returns 0 only at end of file. Throws FileError on I/O errors.
  std::size_t read(unsigned char* dst, std::size_t capacity);

  // Reads up to `capacity` bytes from the start of the file without moving the read position.
  std::size_t peekHead(unsigned char* dst, std::size_t capacity) const;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace rgnav
