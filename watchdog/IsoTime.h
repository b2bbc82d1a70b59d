// ISO-8601 UTC timestamps with milliseconds, e.g. 2024-05-01T12:34:56.789Z.
#pragma once

#include <chrono>
#include <string>

namespace rgnav {

std::string formatIsoUtcMillis(std::chrono::system_clock::time_point time);

}  // namespace rgnav
