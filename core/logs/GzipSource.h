// GzipSource: streaming gzip decoding with zlib's inflate; concatenated gzip members are read
// one after the other, as gzip(1) does.
#pragma once

#include <zlib.h>

#include "core/logs/DecompressingSource.h"

namespace rgnav {

class GzipSource : public DecompressingSource {
 public:
  explicit GzipSource(std::unique_ptr<InputFile> file);
  ~GzipSource() override;

 protected:
  DecodeStep decode(const unsigned char* in, std::size_t inSize, char* out, std::size_t outSize,
                    bool inputEnded) override;

 private:
  z_stream stream_{};
  bool memberDone_ = false;
};

}  // namespace rgnav
