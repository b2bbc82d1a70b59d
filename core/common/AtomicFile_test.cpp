// Tests writeFileAtomically: the content replaces the old one, a stale temporary file of a
// crashed writer does not stop the next write, a symbolic link at the path is replaced and its
// target left alone, and a failed write keeps the old content and leaves no temporary file; an
// append that fails halfway (here at a file size limit) leaves the journal as it was, so that
// appending the same lines again does not put a broken line inside it.
#include <cppunit/extensions/HelperMacros.h>

#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>

#include "core/common/AtomicFile.h"
#include "core/common/Errors.h"

namespace fs = std::filesystem;
using namespace rgnav;

class AtomicFileTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(AtomicFileTest);
  CPPUNIT_TEST(replacesTheContent);
  CPPUNIT_TEST(aStaleTemporaryFileDoesNotStopTheWrite);
  CPPUNIT_TEST(aSymbolicLinkIsReplacedNotFollowed);
  CPPUNIT_TEST(aFailedWriteKeepsTheOldFile);
  CPPUNIT_TEST(aFailedAppendLeavesTheJournalAsItWas);
  CPPUNIT_TEST_SUITE_END();

 public:
  void setUp() override {
    std::string pattern = (fs::temp_directory_path() / "atomicfile.XXXXXX").string();
    CPPUNIT_ASSERT(::mkdtemp(pattern.data()) != nullptr);
    dir_ = pattern;
  }
  void tearDown() override { fs::remove_all(dir_); }

  void replacesTheContent() {
    const std::string path = (dir_ / "state").string();
    writeFileAtomically(path, "one");
    writeFileAtomically(path, "two");
    CPPUNIT_ASSERT_EQUAL(std::string("two"), readCheckpoint(path).value());
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, entries());
  }

  void aStaleTemporaryFileDoesNotStopTheWrite() {
    const std::string path = (dir_ / "state").string();
    for (const std::string& stale : {path + ".tmp", path + ".tmp." + std::to_string(::getpid())})
      fs::create_directory(stale);
    writeFileAtomically(path, "new");
    CPPUNIT_ASSERT_EQUAL(std::string("new"), readCheckpoint(path).value());
  }

  void aSymbolicLinkIsReplacedNotFollowed() {
    const std::string target = (dir_ / "elsewhere").string(), path = (dir_ / "map.json").string();
    writeFileAtomically(target, "precious");
    fs::create_symlink(target, path);
    writeFileAtomically(path, "map");
    CPPUNIT_ASSERT(!fs::is_symlink(path));
    CPPUNIT_ASSERT_EQUAL(std::string("map"), readCheckpoint(path).value());
    CPPUNIT_ASSERT_EQUAL(std::string("precious"), readCheckpoint(target).value());
  }

  void aFailedWriteKeepsTheOldFile() {
    const fs::path taken = dir_ / "taken";
    fs::create_directories(taken / "inside");  // a non-empty directory cannot be replaced
    CPPUNIT_ASSERT_THROW(writeFileAtomically(taken.string(), "x"), FileError);
    CPPUNIT_ASSERT(fs::is_directory(taken / "inside"));
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, entries());
    CPPUNIT_ASSERT_THROW(writeFileAtomically((dir_ / "missing" / "state").string(), "x"), FileError);
  }

  void aFailedAppendLeavesTheJournalAsItWas() {
    const std::string path = (dir_ / "journal").string(), lines(80, 'a');
    appendToFileDurably(path, lines);
    // Past 100 bytes writes fail (EFBIG, SIGXFSZ ignored): the next append gets 20 bytes in.
    const auto previous = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit{};
    CPPUNIT_ASSERT_EQUAL(0, ::getrlimit(RLIMIT_FSIZE, &limit));
    const rlimit small{100, limit.rlim_max};
    CPPUNIT_ASSERT_EQUAL(0, ::setrlimit(RLIMIT_FSIZE, &small));
    bool failed = false;
    try {
      appendToFileDurably(path, std::string(50, 'b'));
    } catch (const FileError&) {
      failed = true;
    }
    ::setrlimit(RLIMIT_FSIZE, &limit);
    std::signal(SIGXFSZ, previous);
    CPPUNIT_ASSERT(failed);
    CPPUNIT_ASSERT_EQUAL(lines, readCheckpoint(path).value());
  }

 private:
  std::size_t entries() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
  }

  fs::path dir_;
};

CPPUNIT_TEST_SUITE_REGISTRATION(AtomicFileTest);
