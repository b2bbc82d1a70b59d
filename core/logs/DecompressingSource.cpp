// DecompressingSource: input buffering, progress checks and error hand-over for the decoders.
#include "core/logs/DecompressingSource.h"

#include <utility>

namespace rgnav {

namespace {
constexpr std::size_t kInputChunk = 1 << 16;
}  // namespace

DecompressingSource::DecompressingSource(std::unique_ptr<InputFile> file, std::string format)
    : file_(std::move(file)), format_(std::move(format)), input_(kInputChunk) {}

ReadResult DecompressingSource::read(char* dst, std::size_t capacity) {
  if (!pendingError_.empty()) {
    finished_ = true;
    return {0, std::exchange(pendingError_, {})};
  }
  if (finished_ || capacity == 0) {
    return {};
  }
  for (;;) {
    if (inputPos_ == inputEnd_ && !inputEnded_) {
      inputPos_ = 0;
      inputEnd_ = file_->read(input_.data(), input_.size());
      inputEnded_ = inputEnd_ == 0;
    }
    const DecodeStep step =
        decode(input_.data() + inputPos_, inputEnd_ - inputPos_, dst, capacity, inputEnded_);
    inputPos_ += step.consumed;
    // No progress although the decoder had input, or could get no more: the data is cut short.
    const bool stalled = step.consumed == 0 && step.produced == 0 && !step.streamEnd &&
                         (inputEnded_ || inputPos_ < inputEnd_);
    std::string error;
    if (!step.error.empty()) {
      error = "corrupt " + format_ + " data: " + step.error;
    } else if (stalled) {
      error = format_ + " data ends early (truncated file?)";
    }
    if (!error.empty() && step.produced == 0) {
      finished_ = true;
      return {0, std::move(error)};
    }
    pendingError_ = std::move(error);  // the bytes decoded before the damage go out first
    finished_ = step.streamEnd;
    if (step.produced > 0 || step.streamEnd) {
      return {step.produced, {}};
    }
  }
}

}  // namespace rgnav
