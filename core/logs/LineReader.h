// LineReader: yields the lines of a plain, gzip or xz file one at a time (the compression is
// detected from the magic bytes), with 1-based line numbers. Lines longer than a cap are skipped
// without being held in memory and handed out flagged as over-long, so the caller can count them.
// A truncated or corrupt compressed stream throws FormatError naming the line being read.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/logs/ByteSource.h"

namespace rgnav {

class LineReader {
 public:
  static constexpr std::size_t kDefaultMaxLineLength = std::size_t{1} << 20;

  struct Line {
    std::string_view text;  // without the line end ("\n" or "\r\n"); empty if over-long
    std::size_t number = 0; // 1-based
    bool overLong = false;  // longer than the cap: skipped, `text` is empty
  };

  // Throws FileError if the file is missing, unreadable or a directory, InvalidArgumentError if
  // `maxLineLength` is 0.
  explicit LineReader(const std::string& path, std::size_t maxLineLength = kDefaultMaxLineLength);

  // The next line, or nullopt at the end of the file. The text stays valid until the next call.
  // Throws FormatError(path, line being read, ...) if the compressed data is truncated or corrupt.
  std::optional<Line> next();

  const std::string& path() const { return path_; }
  std::size_t maxLineLength() const { return maxLineLength_; }

 private:
  bool fill();

  std::string path_;
  std::size_t maxLineLength_;
  std::unique_ptr<ByteSource> source_;
  std::vector<char> buffer_;
  std::size_t pos_ = 0;
  std::size_t end_ = 0;
  bool ended_ = false;
  std::string pending_;  // a line that spans buffer refills
  std::size_t lineNumber_ = 0;
};

}  // namespace rgnav
