// DecompressingSource: the read loop shared by the streaming decoders. It feeds compressed input
// from the file to one decoding step at a time and turns "input ended but the stream did not" or
// "the decoder makes no progress" into a truncation error, so a bad file can never hang a reader.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "core/logs/ByteSource.h"
#include "core/logs/InputFile.h"

namespace rgnav {

// What one decoding step did.
struct DecodeStep {
  std::size_t consumed = 0;  // compressed bytes used
  std::size_t produced = 0;  // decoded bytes written
  bool streamEnd = false;    // the compressed data ended cleanly
  std::string error;         // non-empty: the compressed data is corrupt
};

class DecompressingSource : public ByteSource {
 public:
  ReadResult read(char* dst, std::size_t capacity) final;

 protected:
  // `format` names the compression in error messages ("gzip", "xz").
  DecompressingSource(std::unique_ptr<InputFile> file, std::string format);

  const std::string& path() const { return file_->path(); }

  // Decodes from `in` into `out`. `inputEnded` is true once the file has no bytes beyond `in`.
  virtual DecodeStep decode(const unsigned char* in, std::size_t inSize, char* out,
                            std::size_t outSize, bool inputEnded) = 0;

 private:
  std::unique_ptr<InputFile> file_;
  std::string format_;
  std::vector<unsigned char> input_;
  std::size_t inputPos_ = 0;
  std::size_t inputEnd_ = 0;
  bool inputEnded_ = false;
  bool finished_ = false;
  std::string pendingError_;
};

}  // namespace rgnav
