// Server-set loading with the standard variables (see SetLoading.h).
#include "watchdog/SetLoading.h"

#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;

namespace rgnav {

namespace {
std::string envOr(const char* name, const std::string& fallback) {
  const char* value = std::getenv(name);
  return value && *value ? value : fallback;
}
}  // namespace

std::string defaultProjectRoot() { return envOr("RGNAV_ROOT", fs::current_path().string()); }

SetConfig loadSet(const std::string& setFile, const std::string& root) {
  const std::string bin = fs::canonical("/proc/self/exe").parent_path().string();
  const ConfigVars vars{
      {"RGNAV_BIN", envOr("RGNAV_BIN", bin)},
      {"RGNAV_ROOT", root},
      {"RGNAV_SHARED", envOr("RGNAV_SHARED", (fs::path(root) / ".." / "shared").lexically_normal().string())}};
  return loadSetConfig(setFile, vars, root);
}

}  // namespace rgnav
