// How a supervised process ended: an exit code, a killing signal, "lost" (an adopted process
// that is not our child vanished, so its status cannot be known), or "not started" (it could not
// be spawned; the cause, e.g. "cannot exec 'x': No such file or directory", is kept).
#pragma once

#include <string>
#include <utility>

namespace rgnav {

class ExitStatus {
 public:
  enum class Kind { Exited, Signaled, Lost, NotStarted };

  static ExitStatus exited(int code) { return ExitStatus(Kind::Exited, code); }
  static ExitStatus signaled(int signal) { return ExitStatus(Kind::Signaled, signal); }
  static ExitStatus lost() { return ExitStatus(Kind::Lost, 0); }
  static ExitStatus notStarted(std::string cause) { return ExitStatus(Kind::NotStarted, 0, std::move(cause)); }

  Kind kind() const { return kind_; }
  int code() const { return kind_ == Kind::Exited ? value_ : -1; }
  int signal() const { return kind_ == Kind::Signaled ? value_ : 0; }
  // Anything but exit code 0; a lost process cannot prove it exited cleanly.
  bool abnormal() const { return !(kind_ == Kind::Exited && value_ == 0); }
  std::string describe() const;

  bool operator==(const ExitStatus&) const = default;

 private:
  ExitStatus(Kind kind, int value, std::string cause = {})
      : kind_(kind), value_(value), cause_(std::move(cause)) {}
  Kind kind_;
  int value_;
  std::string cause_;  // of NotStarted
};

}  // namespace rgnav
