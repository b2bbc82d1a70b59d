// ByteSource: magic-byte detection, the plain (uncompressed) source and whole-file reading.
#include "core/logs/ByteSource.h"

#include <algorithm>

#include "core/common/Errors.h"
#include "core/logs/GzipSource.h"
#include "core/logs/InputFile.h"
#include "core/logs/XzSource.h"

namespace rgnav {

namespace {

constexpr unsigned char kGzipMagic[] = {0x1f, 0x8b};
constexpr unsigned char kXzMagic[] = {0xfd, '7', 'z', 'X', 'Z', 0x00};

template <std::size_t N>
bool startsWith(const unsigned char* head, std::size_t size, const unsigned char (&magic)[N]) {
  return size >= N && std::equal(magic, magic + N, head);
}

class PlainSource : public ByteSource {
 public:
  explicit PlainSource(std::unique_ptr<InputFile> file) : file_(std::move(file)) {}
  ReadResult read(char* dst, std::size_t capacity) override {
    return {file_->read(reinterpret_cast<unsigned char*>(dst), capacity), {}};
  }

 private:
  std::unique_ptr<InputFile> file_;
};

std::size_t countNewlines(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

}  // namespace

Compression detectCompression(const unsigned char* head, std::size_t size) {
  if (startsWith(head, size, kGzipMagic)) {
    return Compression::Gzip;
  }
  if (startsWith(head, size, kXzMagic)) {
    return Compression::Xz;
  }
  return Compression::None;
}

std::unique_ptr<ByteSource> openByteSource(const std::string& path) {
  auto file = std::make_unique<InputFile>(path);
  unsigned char head[sizeof kXzMagic];
  const std::size_t size = file->peekHead(head, sizeof head);
  switch (detectCompression(head, size)) {
    case Compression::Gzip:
      return std::make_unique<GzipSource>(std::move(file));
    case Compression::Xz:
      return std::make_unique<XzSource>(std::move(file));
    case Compression::None:
      break;
  }
  return std::make_unique<PlainSource>(std::move(file));
}

std::string readDecoded(const std::string& path, std::size_t maxBytes) {
  constexpr std::size_t kChunk = 1 << 16;
  const auto source = openByteSource(path);
  std::string text;
  for (;;) {
    const std::size_t used = text.size();
    text.resize(used + kChunk);
    const ReadResult chunk = source->read(text.data() + used, kChunk);
    text.resize(used + chunk.bytes);
    if (!chunk.error.empty()) {
      throw FormatError(path, countNewlines(text) + 1, chunk.error);
    }
    if (text.size() > maxBytes) {
      throw FormatError(path, countNewlines(text) + 1,
                        "decoded data larger than " + std::to_string(maxBytes) + " bytes");
    }
    if (chunk.bytes == 0) {
      return text;
    }
  }
}

}  // namespace rgnav
