// Tests ExportRoot: directories below the root (relative, or absolute inside it) are created and
// used; an absolute path elsewhere, a ".." part and a symbolic link below the root are refused
// naming the field, and so are names that are not plain file names.
#include <cppunit/extensions/HelperMacros.h>

#include <stdlib.h>

#include <filesystem>

#include "servers/common/RefusedField.h"
#include "servers/rgmappingkernel/ExportRoot.h"

namespace fs = std::filesystem;
using namespace rgnav;

class ExportRootTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ExportRootTest);
  CPPUNIT_TEST(directoriesBelowTheRoot);
  CPPUNIT_TEST(nothingOutsideTheRoot);
  CPPUNIT_TEST(plainFileNamesOnly);
  CPPUNIT_TEST(theDefaultLiesInTheRunDirectory);
  CPPUNIT_TEST_SUITE_END();

 public:
  void setUp() override {
    std::string pattern = (fs::temp_directory_path() / "exportroot.XXXXXX").string();
    CPPUNIT_ASSERT(::mkdtemp(pattern.data()) != nullptr);
    dir_ = pattern;
  }
  void tearDown() override { fs::remove_all(dir_); }

  void directoriesBelowTheRoot() {
    const ExportRoot root((dir_ / "exports").string());
    CPPUNIT_ASSERT_EQUAL(root.path(), root.directoryFor(""));
    CPPUNIT_ASSERT(fs::is_directory(root.path()));
    CPPUNIT_ASSERT_EQUAL((dir_ / "exports" / "a" / "b").string(), root.directoryFor("a/./b/"));
    CPPUNIT_ASSERT(fs::is_directory(dir_ / "exports" / "a" / "b"));
    CPPUNIT_ASSERT_EQUAL((dir_ / "exports" / "c").string(), root.directoryFor((dir_ / "exports" / "c").string()));
    CPPUNIT_ASSERT_EQUAL(root.path(), root.directoryFor(root.path()));
  }

  void nothingOutsideTheRoot() {
    const ExportRoot root((dir_ / "exports").string());
    CPPUNIT_ASSERT_EQUAL(std::string("directory"), refusedField([&] { root.directoryFor("/etc"); }));
    CPPUNIT_ASSERT_EQUAL(std::string("directory"), refusedField([&] { root.directoryFor("../elsewhere"); }));
    CPPUNIT_ASSERT_EQUAL(std::string("directory"), refusedField([&] { root.directoryFor("a/../../elsewhere"); }));
    CPPUNIT_ASSERT_EQUAL(std::string("directory"),
                         refusedField([&] { root.directoryFor((dir_ / "exports-not").string()); }));
    CPPUNIT_ASSERT(!fs::exists(dir_ / "elsewhere"));
    fs::create_directories(dir_ / "outside");
    fs::create_directories(root.path());
    fs::create_directory_symlink(dir_ / "outside", dir_ / "exports" / "link");
    CPPUNIT_ASSERT_EQUAL(std::string("directory"), refusedField([&] { root.directoryFor("link/maps"); }));
    CPPUNIT_ASSERT(!fs::exists(dir_ / "outside" / "maps"));
    const std::string tooLong(5000, 'a');
    CPPUNIT_ASSERT_EQUAL(std::string("directory"), refusedField([&] { root.directoryFor(tooLong); }));
  }

  void plainFileNamesOnly() {
    for (const std::string bad : {"", ".", "..", "a/b", "../map"})
      CPPUNIT_ASSERT_EQUAL(std::string("name"), refusedField([&] { requireFileName(bad, "name"); }));
    CPPUNIT_ASSERT_EQUAL(std::string("(accepted)"), refusedField([] { requireFileName("demo", "name"); }));
  }

  void theDefaultLiesInTheRunDirectory() {
    CPPUNIT_ASSERT_EQUAL((dir_ / "run" / "exports").string(),
                         defaultExportRoot((dir_ / "run" / "state" / "RGMappingKernel").string()));
  }

 private:
  fs::path dir_;
};

CPPUNIT_TEST_SUITE_REGISTRATION(ExportRootTest);
