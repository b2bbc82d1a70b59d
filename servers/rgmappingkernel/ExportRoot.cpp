// The export directory tree of the kernel (see ExportRoot.h).
#include "servers/rgmappingkernel/ExportRoot.h"

#include <filesystem>

#include "core/common/Errors.h"
#include "servers/common/WireChecks.h"

namespace fs = std::filesystem;

namespace rgnav {

ExportRoot::ExportRoot(const std::string& root) : root_(fs::absolute(root).lexically_normal().string()) {
  while (root_.size() > 1 && root_.back() == '/') root_.pop_back();
}

std::string ExportRoot::directoryFor(const std::string& requested) const {
  const std::string text = wire::checkedName(requested.c_str(), "directory", true, wire::kMaxPathLength);
  fs::path relative = fs::path(text);
  if (relative.is_absolute()) {
    const fs::path inside = relative.lexically_normal().lexically_relative(root_);
    if (inside.empty() || *inside.begin() == "..")
      wire::refuse("directory", text + " is outside the export root " + root_);
    relative = inside;
  }
  for (const fs::path& part : relative)
    if (part == "..") wire::refuse("directory", text + " must not contain '..'");
  std::error_code error;
  fs::create_directories(root_, error);
  if (error) throw FileError(root_ + ": cannot create the export root: " + error.message());
  fs::path dir = root_;
  for (const fs::path& part : relative.lexically_normal()) {
    if (part.empty() || part == ".") continue;
    dir /= part;
    if (fs::is_symlink(dir)) wire::refuse("directory", dir.string() + " is a symbolic link");
    fs::create_directory(dir, error);
    if (error) throw FileError(dir.string() + ": cannot create: " + error.message());
  }
  return dir.string();
}

std::string defaultExportRoot(const std::string& stateDir) {
  if (stateDir.empty()) return "exports";
  return (fs::absolute(stateDir).lexically_normal().parent_path().parent_path() / "exports").string();
}

void requireFileName(const std::string& name, const char* field) {
  wire::checkedName(name.c_str(), field, false);
  if (name == "." || name == ".." || name.find('/') != std::string::npos)
    wire::refuse(field, name + " is no plain file name");
}

}  // namespace rgnav
