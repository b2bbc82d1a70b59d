// HostPort: a "host:port" endpoint as written in options and config files.
#pragma once

#include <charconv>
#include <string>
#include <string_view>

#include "core/common/Errors.h"

namespace rgnav {

struct HostPort {
  std::string host;
  int port = 0;
  std::string str() const { return host + ":" + std::to_string(port); }
};

// Whether `host` can be a host name or address in a corbaloc URL: letters, digits and . - _ : [ ] %
// (an IPv6 literal in brackets, with a zone), nothing else (no space, slash or control character).
inline bool isHostText(const std::string& host) {
  for (const char c : host) {
    const bool alnum = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    if (!alnum && std::string_view(".-_:[]%").find(c) == std::string_view::npos) return false;
  }
  return true;
}

// Parses "host:port" with a port in 1..65535 and a host of isHostText; throws ConfigError naming
// the text.
inline HostPort parseHostPort(const std::string& text) {
  const auto colon = text.rfind(':');
  int port = 0;
  if (colon == std::string::npos || colon == 0)
    throw ConfigError("'" + text + "' is not host:port");
  const char* begin = text.data() + colon + 1;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(begin, end, port);
  if (ec != std::errc() || ptr != end || port < 1 || port > 65535)
    throw ConfigError("'" + text + "' has no valid port (1..65535)");
  if (!isHostText(text.substr(0, colon)))
    throw ConfigError("'" + text + "' has no valid host (letters, digits and . - _ : [ ] % only)");
  return {text.substr(0, colon), port};
}

}  // namespace rgnav
