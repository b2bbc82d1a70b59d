// ByteSource: the decompressed bytes of a log file, read in chunks. openByteSource() picks plain,
// gzip or xz decoding from the file's magic bytes (never from its extension).
#pragma once

#include <cstddef>
#include <memory>
#include <string>

namespace rgnav {

// One chunk of decoded bytes. `bytes == 0` with an empty `error` is the clean end of the data; a
// non-empty `error` says why the data cannot continue (truncated or corrupt compressed stream).
struct ReadResult {
  std::size_t bytes = 0;
  std::string error;
};

class ByteSource {
 public:
  virtual ~ByteSource() = default;
  // Fills up to `capacity` bytes of `dst`. Throws FileError on I/O errors of the underlying file.
  virtual ReadResult read(char* dst, std::size_t capacity) = 0;
};

enum class Compression { None, Gzip, Xz };

// The compression announced by the first bytes of a file (fewer than 6 bytes is allowed).
Compression detectCompression(const unsigned char* head, std::size_t size);

// Opens `path` for decoded reading. Throws FileError if it is missing, unreadable or a directory.
std::unique_ptr<ByteSource> openByteSource(const std::string& path);

// All decoded bytes of `path`. Throws FormatError (line = the line reached) if the compressed data
// is corrupt or the decoded size exceeds `maxBytes`, FileError as openByteSource().
std::string readDecoded(const std::string& path, std::size_t maxBytes);

}  // namespace rgnav
