// Typed errors that cross the boundaries of core libraries. Every error carries a message that
// names what failed; library code throws these and never writes to stderr.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace rgnav {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file that cannot be opened, read or written.
class FileError : public Error {
 public:
  using Error::Error;
};

// Malformed content at a known place in a file.
class FormatError : public Error {
 public:
  FormatError(const std::string& file, std::size_t line, const std::string& what)
      : Error(file + ":" + std::to_string(line) + ": " + what), file_(file), line_(line) {}
  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }

 private:
  std::string file_;
  std::size_t line_;
};

// A configuration that is missing a key, has an unknown key or a value out of range.
class ConfigError : public Error {
 public:
  using Error::Error;
};

// A request for data that is not (or no longer) held, e.g. an ID outside the buffer.
class NotAvailableError : public Error {
 public:
  using Error::Error;
};

// An argument that can never be valid, e.g. a zero count.
class InvalidArgumentError : public Error {
 public:
  using Error::Error;
};

// The operation is not supported by this implementation (e.g. driving a log playback).
class NotSupportedError : public Error {
 public:
  using Error::Error;
};

}  // namespace rgnav
