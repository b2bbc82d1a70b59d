// XzSource: streaming xz decoding with liblzma's stream decoder; concatenated xz streams and
// stream padding are accepted, as xz(1) does.
#pragma once

#include <lzma.h>

#include "core/logs/DecompressingSource.h"

namespace rgnav {

class XzSource : public DecompressingSource {
 public:
  explicit XzSource(std::unique_ptr<InputFile> file);
  ~XzSource() override;

 protected:
  DecodeStep decode(const unsigned char* in, std::size_t inSize, char* out, std::size_t outSize,
                    bool inputEnded) override;

 private:
  lzma_stream stream_ = LZMA_STREAM_INIT;
};

}  // namespace rgnav
