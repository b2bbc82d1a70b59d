// LineReader: splits decoded chunks at '\n'; a line inside one chunk is handed out in place,
// one spanning chunks is gathered up to the cap and dropped beyond it.
#include "core/logs/LineReader.h"

#include <cstring>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

constexpr std::size_t kChunk = 1 << 16;

std::string_view withoutCarriageReturn(std::string_view text) {
  return !text.empty() && text.back() == '\r' ? text.substr(0, text.size() - 1) : text;
}

}  // namespace

LineReader::LineReader(const std::string& path, std::size_t maxLineLength)
    : path_(path), maxLineLength_(maxLineLength) {
  if (maxLineLength == 0) {
    throw InvalidArgumentError("LineReader: maximum line length must be positive");
  }
  source_ = openByteSource(path);
  buffer_.resize(kChunk);
}

bool LineReader::fill() {
  if (ended_) {
    return false;
  }
  const ReadResult chunk = source_->read(buffer_.data(), buffer_.size());
  if (!chunk.error.empty()) {
    ended_ = true;
    throw FormatError(path_, lineNumber_ + 1, chunk.error);
  }
  pos_ = 0;
  end_ = chunk.bytes;
  ended_ = chunk.bytes == 0;
  return !ended_;
}

std::optional<LineReader::Line> LineReader::next() {
  pending_.clear();
  bool started = false;
  bool overLong = false;
  for (;;) {
    if (pos_ == end_ && !fill()) {
      if (!started) {
        return std::nullopt;
      }
      break;  // the last line has no line end
    }
    const char* start = buffer_.data() + pos_;
    const std::size_t available = end_ - pos_;
    const auto* newline = static_cast<const char*>(std::memchr(start, '\n', available));
    const std::size_t length =
        newline != nullptr ? static_cast<std::size_t>(newline - start) : available;
    pos_ += newline != nullptr ? length + 1 : length;
    started = true;
    if (!overLong && pending_.size() + length > maxLineLength_) {
      overLong = true;
      pending_.clear();
      pending_.shrink_to_fit();
    }
    if (newline != nullptr && !overLong && pending_.empty()) {
      return Line{withoutCarriageReturn({start, length}), ++lineNumber_, false};
    }
    if (!overLong) {
      pending_.append(start, length);
    }
    if (newline != nullptr) {
      break;
    }
  }
  if (overLong) {
    return Line{{}, ++lineNumber_, true};
  }
  return Line{withoutCarriageReturn(pending_), ++lineNumber_, false};
}

}  // namespace rgnav
