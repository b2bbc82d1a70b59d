// Paths of shipped config files (see ShippedConfig.h).
#include "core/config/ShippedConfig.h"

#include <cstdlib>
#include <filesystem>

namespace rgnav {

std::string shippedConfigFile(const std::string& relative) {
  const char* root = std::getenv("RGNAV_ROOT");
  const std::filesystem::path base = root != nullptr && *root != '\0' ? std::filesystem::path(root) : ".";
  return std::filesystem::absolute(base / "config" / relative).string();
}

}  // namespace rgnav
