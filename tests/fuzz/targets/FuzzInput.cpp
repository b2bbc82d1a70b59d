// The process's fuzz input file.
#include "tests/fuzz/targets/FuzzInput.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace rgnav::fuzz {

namespace {

namespace fs = std::filesystem;

// A folder of this process, removed with the process's static objects.
class InputFolder {
 public:
  InputFolder() {
    const fs::path base = fs::is_directory("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
    path_ = base / ("rgnav-fuzz-" + std::to_string(::getpid()));
    fs::create_directories(path_);
  }
  ~InputFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  InputFolder(const InputFolder&) = delete;
  InputFolder& operator=(const InputFolder&) = delete;

  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

}  // namespace

std::string fuzzInputFile(const std::uint8_t* data, std::size_t size) {
  static const InputFolder folder;
  const std::string path = (folder.path() / "input").string();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out.flush()) {
    throw std::runtime_error("cannot write the fuzz input file " + path);
  }
  return path;
}

}  // namespace rgnav::fuzz
