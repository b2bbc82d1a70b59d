// writeFileAtomically: replaces a file's content so that readers see either the old or the new
// content, never a part (DESIGN.md "State survives": write a temporary file, fsync, rename);
// readCheckpoint reads such a file back.
#pragma once

#include <optional>
#include <string>

namespace rgnav {

// Throws FileError naming the path if any step fails.
void writeFileAtomically(const std::string& path, const std::string& content);

// The whole content of `path`; nullopt for an empty path or a file that does not exist. Throws
// FileError if it exists but cannot be read.
std::optional<std::string> readCheckpoint(const std::string& path);

}  // namespace rgnav
