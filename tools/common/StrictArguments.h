// Strict parsing of the numbers RG Nav's command-line tools take (region IDs, coordinates,
// counts, timeouts): the whole text must be the number, or the tool refuses with an
// ArgumentError that names the argument and the text ("region ID '3x' is not a whole number"),
// before it contacts any server. std::stoull and friends, and Boost's lexical_cast, accept
// "3x" as 3, "-5" as 2^64-5 or "nan"; these never do.
#pragma once

#include <boost/program_options.hpp>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>

#include "core/common/Errors.h"

namespace rgnav {

// A command-line argument that is not what it has to be: which one, the text given, and why.
class ArgumentError : public InvalidArgumentError {
 public:
  ArgumentError(const std::string& argument, const std::string& text, const std::string& problem);
  const std::string& argument() const { return argument_; }
  const std::string& text() const { return text_; }

 private:
  std::string argument_;
  std::string text_;
};

// A whole number from 0 to `max` (decimal digits only: no sign, no spaces).
std::uint64_t parseWholeNumber(std::string_view text, const std::string& argument,
                               std::uint64_t max = std::numeric_limits<std::uint64_t>::max());
// An ID: a whole number from 1 (0 is no ID).
std::uint64_t parseId(std::string_view text, const std::string& argument);
// A finite decimal number ("1.5", "-2", "1e3"; not "nan", "inf", "+1" or "1.5m").
double parseFiniteNumber(std::string_view text, const std::string& argument);

// A Boost option read as text and parsed strictly into `*target` when the options are notified
// (a whole number for an integer type, a finite number for a floating-point type); give its
// default as text: strictOption(&after, "--after")->default_value("0").
template <class T>
boost::program_options::typed_value<std::string>* strictOption(T* target, const std::string& argument) {
  return boost::program_options::value<std::string>()->notifier([target, argument](const std::string& text) {
    if constexpr (std::is_floating_point_v<T>) {
      *target = static_cast<T>(parseFiniteNumber(text, argument));
    } else {
      static_assert(std::is_integral_v<T>, "strictOption parses numbers");
      *target = static_cast<T>(parseWholeNumber(text, argument, static_cast<std::uint64_t>(std::numeric_limits<T>::max())));
    }
  });
}

}  // namespace rgnav
