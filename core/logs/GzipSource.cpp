// GzipSource: one inflate() call per decoding step, with zlib's status mapped to DecodeStep.
#include "core/logs/GzipSource.h"

#include <algorithm>
#include <limits>

#include "core/common/Errors.h"

namespace rgnav {

namespace {
constexpr int kGzipWindowBits = 15 + 16;  // 32 KiB window, gzip header and trailer expected
constexpr std::size_t kMaxStep = std::numeric_limits<uInt>::max();
}  // namespace

GzipSource::GzipSource(std::unique_ptr<InputFile> file)
    : DecompressingSource(std::move(file), "gzip") {
  if (inflateInit2(&stream_, kGzipWindowBits) != Z_OK) {
    throw FileError(path() + ": cannot initialise the gzip decoder");
  }
}

GzipSource::~GzipSource() { inflateEnd(&stream_); }

DecodeStep GzipSource::decode(const unsigned char* in, std::size_t inSize, char* out,
                              std::size_t outSize, bool inputEnded) {
  if (memberDone_) {
    if (inSize == 0) {
      return {0, 0, inputEnded, {}};
    }
    inflateReset(&stream_);
    memberDone_ = false;
  }
  stream_.next_in = const_cast<Bytef*>(in);
  stream_.avail_in = static_cast<uInt>(std::min(inSize, kMaxStep));
  stream_.next_out = reinterpret_cast<Bytef*>(out);
  stream_.avail_out = static_cast<uInt>(std::min(outSize, kMaxStep));
  const uInt inBefore = stream_.avail_in;
  const uInt outBefore = stream_.avail_out;
  const int status = inflate(&stream_, Z_NO_FLUSH);
  DecodeStep step{inBefore - stream_.avail_in, outBefore - stream_.avail_out, false, {}};
  switch (status) {
    case Z_STREAM_END:
      memberDone_ = true;
      step.streamEnd = inputEnded && step.consumed == inSize;
      break;
    case Z_OK:
    case Z_BUF_ERROR:  // no progress possible now; the caller decides whether input is missing
      break;
    default:
      step.error = stream_.msg != nullptr ? stream_.msg : "inflate error " + std::to_string(status);
  }
  return step;
}

}  // namespace rgnav
