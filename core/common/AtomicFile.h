// writeFileAtomically: replaces a file's content so that readers see either the old or the new
// content, never a part, also after a crash (DESIGN.md "State survives": a temporary file under a
// fresh name beside it (mkostemp: never opened through a symbolic link), fsync, rename, fsync of
// the directory). The one atomic write of the project: checkpoints, exports, the watchdog's state.
// A symbolic link at `path` itself is replaced, not followed.
// appendToFileDurably: adds to the end of a journal and fsyncs (a crash may leave a part of the
// last append, which the journal's reader must ignore; an append that fails is cut off again, so
// the caller may append the same content later; a symbolic link is refused);
// readCheckpoint reads such a file back.
#pragma once

#include <optional>
#include <string>

namespace rgnav {

// Throws FileError naming the path if any step fails.
void writeFileAtomically(const std::string& path, const std::string& content);
// Creates the file if it does not exist. Throws FileError naming the path if any step fails.
void appendToFileDurably(const std::string& path, const std::string& content);

// The whole content of `path`; nullopt for an empty path or a file that does not exist. Throws
// FileError if it exists but cannot be read.
std::optional<std::string> readCheckpoint(const std::string& path);

}  // namespace rgnav
