// An integer identity that only compares with, and converts to, identities of the same concept.
// The kernel's regions and gateways, the detector's gateways and the passage tracker's tracks are
// all numbered from 1, and each module's number means nothing in another module's table: giving a
// detector gateway ID where a kernel gateway ID is expected is a bug the compiler now refuses.
// 0 means "none"; construction from a bare integer is explicit (wire, file and test boundaries).
#pragma once

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <ostream>

namespace rgnav {

template <class Concept>
class TypedId {
 public:
  using Value = std::uint64_t;

  constexpr TypedId() = default;
  constexpr explicit TypedId(Value value) : value_(value) {}

  constexpr Value value() const { return value_; }
  constexpr bool isNone() const { return value_ == 0; }

  // Numbering: `next++` hands out the current ID and advances the counter.
  constexpr TypedId& operator++() {
    ++value_;
    return *this;
  }
  constexpr TypedId operator++(int) {
    const TypedId before = *this;
    ++value_;
    return before;
  }

  friend constexpr auto operator<=>(const TypedId&, const TypedId&) = default;
  friend std::ostream& operator<<(std::ostream& out, const TypedId& id) { return out << id.value_; }

 private:
  Value value_ = 0;
};

}  // namespace rgnav

template <class Concept>
struct std::hash<rgnav::TypedId<Concept>> {
  std::size_t operator()(const rgnav::TypedId<Concept>& id) const noexcept { return std::hash<std::uint64_t>{}(id.value()); }
};
