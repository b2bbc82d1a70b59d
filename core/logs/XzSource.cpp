// XzSource: one lzma_code() call per decoding step, with liblzma's status mapped to DecodeStep.
#include "core/logs/XzSource.h"

#include "core/common/Errors.h"

namespace rgnav {

namespace {

// Far above what xz presets need (-9 uses 65 MiB), low enough to refuse absurd headers.
constexpr std::uint64_t kMemoryLimit = 512ull << 20;

std::string describe(lzma_ret status) {
  switch (status) {
    case LZMA_FORMAT_ERROR:
      return "not in xz format";
    case LZMA_OPTIONS_ERROR:
      return "unsupported compression options";
    case LZMA_DATA_ERROR:
      return "compressed data is corrupt";
    case LZMA_MEM_ERROR:
      return "out of memory";
    case LZMA_MEMLIMIT_ERROR:
      return "needs more than " + std::to_string(kMemoryLimit >> 20) + " MiB to decode";
    default:
      return "lzma error " + std::to_string(static_cast<int>(status));
  }
}

}  // namespace

XzSource::XzSource(std::unique_ptr<InputFile> file) : DecompressingSource(std::move(file), "xz") {
  const lzma_ret status = lzma_stream_decoder(&stream_, kMemoryLimit, LZMA_CONCATENATED);
  if (status != LZMA_OK) {
    throw FileError(path() + ": cannot initialise the xz decoder: " + describe(status));
  }
}

XzSource::~XzSource() { lzma_end(&stream_); }

DecodeStep XzSource::decode(const unsigned char* in, std::size_t inSize, char* out,
                            std::size_t outSize, bool inputEnded) {
  stream_.next_in = in;
  stream_.avail_in = inSize;
  stream_.next_out = reinterpret_cast<uint8_t*>(out);
  stream_.avail_out = outSize;
  const lzma_ret status = lzma_code(&stream_, inputEnded ? LZMA_FINISH : LZMA_RUN);
  DecodeStep step{inSize - stream_.avail_in, outSize - stream_.avail_out, false, {}};
  switch (status) {
    case LZMA_STREAM_END:
      step.streamEnd = true;
      break;
    case LZMA_OK:
    case LZMA_BUF_ERROR:  // no progress possible now; the caller decides whether input is missing
      break;
    default:
      step.error = describe(status);
  }
  return step;
}

}  // namespace rgnav
