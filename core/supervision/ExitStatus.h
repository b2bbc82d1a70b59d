// How a supervised process ended: an exit code, a killing signal, or "lost" (an adopted process
// that is not our child vanished, so its status cannot be known).
#pragma once

#include <string>

namespace rgnav {

class ExitStatus {
 public:
  enum class Kind { Exited, Signaled, Lost };

  static ExitStatus exited(int code) { return ExitStatus(Kind::Exited, code); }
  static ExitStatus signaled(int signal) { return ExitStatus(Kind::Signaled, signal); }
  static ExitStatus lost() { return ExitStatus(Kind::Lost, 0); }

  Kind kind() const { return kind_; }
  int code() const { return kind_ == Kind::Exited ? value_ : -1; }
  int signal() const { return kind_ == Kind::Signaled ? value_ : 0; }
  // Anything but exit code 0; a lost process cannot prove it exited cleanly.
  bool abnormal() const { return !(kind_ == Kind::Exited && value_ == 0); }
  std::string describe() const;

  bool operator==(const ExitStatus&) const = default;

 private:
  ExitStatus(Kind kind, int value) : kind_(kind), value_(value) {}
  Kind kind_;
  int value_;
};

}  // namespace rgnav
