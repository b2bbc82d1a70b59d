// writeFileAtomically: replaces a file's content so that readers see either the old or the new
// content, never a part (DESIGN.md "State survives": write a temporary file, fsync, rename).
#pragma once

#include <string>

namespace rgnav {

// Throws FileError naming the path if any step fails.
void writeFileAtomically(const std::string& path, const std::string& content);

}  // namespace rgnav
