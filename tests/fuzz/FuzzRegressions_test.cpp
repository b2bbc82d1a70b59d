// Replays every saved input of an earlier fuzz finding (tests/fuzz/regressions/<target>/<file>)
// through its fuzz target in the normal build: each must now end in a typed error or be read,
// never escape with another exception (or crash). Every folder must name a target.
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

std::string fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

class FuzzRegressionsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(FuzzRegressionsTest);
  CPPUNIT_TEST(everyFolderNamesATarget);
  CPPUNIT_TEST(savedFindingsAreHandled);
  CPPUNIT_TEST_SUITE_END();

 public:
  void everyFolderNamesATarget() {
    CPPUNIT_ASSERT(fs::is_directory(kRegressions));
    for (const auto& folder : fs::directory_iterator(kRegressions)) {
      CPPUNIT_ASSERT_NO_THROW_MESSAGE(folder.path().string(),
                                      rgnav::fuzz::fuzzTarget(folder.path().filename().string()));
    }
  }

  void savedFindingsAreHandled() {
    std::size_t replayed = 0;
    for (const auto& target : rgnav::fuzz::fuzzTargets()) {
      const fs::path folder = kRegressions / target.name;
      if (!fs::is_directory(folder)) continue;
      for (const auto& input : fs::directory_iterator(folder)) {
        const std::string bytes = fileBytes(input.path());
        CPPUNIT_ASSERT_NO_THROW_MESSAGE(
            input.path().string(),
            target.run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
        ++replayed;
      }
    }
    CPPUNIT_ASSERT(replayed > 0);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(FuzzRegressionsTest);
