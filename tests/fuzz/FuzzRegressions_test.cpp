// Replays every saved input of an earlier fuzz finding (tests/fuzz/regressions/<target>/<file>)
// through its fuzz target in the normal build, and a few hostile inputs through every target:
// each must end in a typed error or be read, never escape with another exception (or crash).
// Every folder of tests/fuzz/regressions must name a target.
#include <cppunit/extensions/HelperMacros.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/common/Errors.h"
#include "tests/fuzz/targets/FuzzTargets.h"

namespace {

namespace fs = std::filesystem;

const fs::path kRegressions = "tests/fuzz/regressions";

void run(rgnav::fuzz::FuzzTarget target, const std::string& bytes) {
  target(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

std::string fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

class FuzzRegressionsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(FuzzRegressionsTest);
  CPPUNIT_TEST(everyFolderNamesATarget);
  CPPUNIT_TEST(savedFindingsAreHandled);
  CPPUNIT_TEST(hostileInputsAreHandled);
  CPPUNIT_TEST_SUITE_END();

 public:
  void everyFolderNamesATarget() {
    CPPUNIT_ASSERT(fs::is_directory(kRegressions));
    for (const auto& folder : fs::directory_iterator(kRegressions)) {
      if (!folder.is_directory()) continue;
      CPPUNIT_ASSERT_NO_THROW_MESSAGE(folder.path().string(),
                                      rgnav::fuzz::fuzzTarget(folder.path().filename().string()));
    }
  }

  void savedFindingsAreHandled() {
    for (const auto& target : rgnav::fuzz::fuzzTargets()) {
      const fs::path folder = kRegressions / target.name;
      if (!fs::is_directory(folder)) continue;
      for (const auto& input : fs::directory_iterator(folder)) {
        CPPUNIT_ASSERT_NO_THROW_MESSAGE(input.path().string(), run(target.run, fileBytes(input.path())));
      }
    }
  }

  // Empty, a NUL, truncated gzip and xz headers, deep nesting, a huge count, a bad UTF-8 key.
  void hostileInputsAreHandled() {
    const std::vector<std::string> inputs = {
        "", std::string(1, '\0'), "\x1f\x8b\x08", std::string("\xfd" "7zXZ\0", 6), std::string(5000, '['),
        std::string(5000, '{'), "models 18446744073709551615\n", "{\"map\": {\"\xff\": {\"range\": [1e999]}}}"};
    for (const auto& target : rgnav::fuzz::fuzzTargets()) {
      for (const std::string& input : inputs) {
        CPPUNIT_ASSERT_NO_THROW_MESSAGE(std::string(target.name), run(target.run, input));
      }
    }
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(FuzzRegressionsTest);
