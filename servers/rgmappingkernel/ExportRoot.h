// ExportRoot: the one directory tree RGMappingKernel::exportMap may write into (the kernel's
// --export-root). A call names a directory relative to it, or an absolute one inside it; anything
// that could lead outside - an absolute path elsewhere, a ".." part, a symbolic link among the
// directories below the root - is refused with InvalidArgument naming the field, before anything
// is created. The files themselves are written with writeFileAtomically (never through a link).
#pragma once

#include <string>

namespace rgnav {

class ExportRoot {
 public:
  // `root` is made absolute and created when first used.
  explicit ExportRoot(const std::string& root);

  const std::string& path() const { return root_; }
  // The directory to write into for a requested one ("" is the root itself), created if needed.
  std::string directoryFor(const std::string& requested) const;

 private:
  std::string root_;
};

// The default root: <run dir>/exports of the server set, the run dir being the parent of the
// state directories (<run dir>/state/<module>); "exports" in the working directory without one.
std::string defaultExportRoot(const std::string& stateDir);

// Refuses a name that is not a plain file name (empty, ".", "..", a '/', over-long).
void requireFileName(const std::string& name, const char* field);

}  // namespace rgnav
