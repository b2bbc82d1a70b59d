// readGrayImage / writeImage: the file-system checks that give typed errors, around OpenCV's
// codecs (which only say "empty image" or throw cv::Exception).
#include "core/raster/ImageFile.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "core/common/AtomicFile.h"
#include "core/common/Errors.h"

namespace rgnav {
namespace {

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

cv::Mat readGrayImage(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw FileError(path + ": is a directory");
  if (!std::ifstream(path, std::ios::binary)) throw FileError(path + ": cannot open: " + std::strerror(errno));
  cv::Mat image;
  try {
    image = cv::imread(path, cv::IMREAD_GRAYSCALE);
  } catch (const cv::Exception& e) {
    throw FormatError(path, 0, std::string("not a readable image: ") + e.what());
  }
  if (image.empty()) throw FormatError(path, 0, "not a readable image (damaged, truncated or of an unknown format)");
  return image;
}

void writeImage(const std::string& path, const cv::Mat& image) {
  const bool png = endsWith(path, ".png"), pgm = endsWith(path, ".pgm");
  if (!png && !pgm) throw InvalidArgumentError(path + ": an image file name must end in .png or .pgm");
  if (image.empty()) throw InvalidArgumentError(path + ": cannot write an empty image");
  if (image.type() != CV_8UC1 && !(png && image.type() == CV_8UC3))
    throw InvalidArgumentError(path + ": only 8-bit gray (PNG, PGM) or BGR (PNG) images are written");
  std::vector<unsigned char> bytes;
  try {
    if (!cv::imencode(png ? ".png" : ".pgm", image, bytes)) throw FileError(path + ": the image could not be encoded");
  } catch (const cv::Exception& e) {
    throw FileError(path + ": the image could not be encoded: " + e.what());
  }
  writeFileAtomically(path, std::string(bytes.begin(), bytes.end()));
}

}  // namespace rgnav
