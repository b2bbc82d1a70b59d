// PGM (Netpbm P5/P2) decoding with line-numbered errors, and encoding.
#include "core/sim/world/PgmIo.h"

#include <algorithm>
#include <cctype>
#include <cstdint>

#include "core/common/AtomicFile.h"
#include "core/common/Errors.h"

namespace rgnav {
namespace {

constexpr long kMaxValue = 65535;
constexpr long kMaxDimension = 1 << 16;
constexpr std::size_t kAsciiValuesPerLine = 17;  // plain PGM lines stay within 70 characters

// Reads whitespace-separated decimal numbers, skipping '#' comments, and knows its line.
class PgmScanner {
 public:
  PgmScanner(const std::string& bytes, const std::string& path) : bytes_(bytes), path_(path) {}

  [[noreturn]] void fail(const std::string& what) const {
    const auto line = std::count(bytes_.begin(), bytes_.begin() + static_cast<long>(position_), '\n');
    throw FormatError(path_, static_cast<std::size_t>(line) + 1, what);
  }

  long number(const char* what, long min, long max) {
    skipSpaceAndComments();
    if (position_ >= bytes_.size() || !std::isdigit(static_cast<unsigned char>(bytes_[position_]))) {
      fail(std::string("expected ") + what);
    }
    long value = 0;
    while (position_ < bytes_.size() && std::isdigit(static_cast<unsigned char>(bytes_[position_]))) {
      value = value * 10 + (bytes_[position_++] - '0');
      if (value > max) fail(std::string(what) + " too large");
    }
    if (value < min) fail(std::string(what) + " out of range");
    return value;
  }

  // After the maxval exactly one whitespace character precedes binary pixel data.
  void skipSingleWhitespace() {
    if (position_ >= bytes_.size() || !std::isspace(static_cast<unsigned char>(bytes_[position_]))) {
      fail("expected whitespace after maxval");
    }
    ++position_;
  }

  std::size_t position() const { return position_; }
  void advance(std::size_t count) { position_ += count; }

 private:
  void skipSpaceAndComments() {
    while (position_ < bytes_.size()) {
      const char c = bytes_[position_];
      if (c == '#') {
        while (position_ < bytes_.size() && bytes_[position_] != '\n') ++position_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++position_;
      } else {
        return;
      }
    }
  }

  const std::string& bytes_;
  const std::string& path_;
  std::size_t position_ = 0;
};

std::uint8_t toEightBit(long value, long maxValue) {
  return static_cast<std::uint8_t>((value * 255 + maxValue / 2) / maxValue);
}

}  // namespace

bool isPgm(const std::string& bytes) {
  return bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '5' || bytes[1] == '2');
}

GrayImage decodePgm(const std::string& bytes, const std::string& path) {
  PgmScanner scanner(bytes, path);
  if (!isPgm(bytes)) scanner.fail("not a PGM file (magic number P5 or P2 expected)");
  const bool binary = bytes[1] == '5';
  scanner.advance(2);
  const int width = static_cast<int>(scanner.number("width", 1, kMaxDimension));
  const int height = static_cast<int>(scanner.number("height", 1, kMaxDimension));
  const long maxValue = scanner.number("maxval", 1, kMaxValue);
  GrayImage image(width, height);
  std::vector<std::uint8_t>& pixels = image.pixels();
  if (!binary) {
    for (std::uint8_t& pixel : pixels) pixel = toEightBit(scanner.number("pixel value", 0, maxValue), maxValue);
    return image;
  }
  scanner.skipSingleWhitespace();
  const std::size_t bytesPerValue = maxValue < 256 ? 1 : 2;
  if (bytes.size() - scanner.position() < pixels.size() * bytesPerValue) {
    scanner.fail("pixel data truncated: " + std::to_string(pixels.size() * bytesPerValue) + " bytes expected, " +
                 std::to_string(bytes.size() - scanner.position()) + " present");
  }
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data() + scanner.position());
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const long value = bytesPerValue == 1 ? data[i] : (long{data[2 * i]} << 8) | data[2 * i + 1];
    if (value > maxValue) scanner.fail("pixel value " + std::to_string(value) + " above maxval");
    pixels[i] = toEightBit(value, maxValue);
  }
  return image;
}

void writePgm(const std::string& path, const GrayImage& image, PgmEncoding encoding) {
  if (image.width() <= 0) throw InvalidArgumentError(path + ": cannot write an empty image");
  const bool binary = encoding == PgmEncoding::Binary;
  std::string out = std::string(binary ? "P5" : "P2") + "\n" + std::to_string(image.width()) + " " +
                    std::to_string(image.height()) + "\n255\n";
  const std::vector<std::uint8_t>& pixels = image.pixels();
  if (binary) {
    out.append(pixels.begin(), pixels.end());
  } else {
    for (std::size_t i = 0; i < pixels.size(); ++i) {
      out += std::to_string(pixels[i]);
      out += (i + 1) % kAsciiValuesPerLine == 0 || i + 1 == pixels.size() ? '\n' : ' ';
    }
  }
  writeFileAtomically(path, out);
}

}  // namespace rgnav
