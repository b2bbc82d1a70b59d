// fork + exec of a supervised command. Everything the child needs is prepared before fork; the
// child itself only calls async-signal-safe functions (the watchdog is multi-threaded) and
// reports a failure through a close-on-exec pipe, which closes without data when exec succeeds.
#include "watchdog/Spawn.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <string_view>
#include <system_error>

#include "core/common/Errors.h"
#include "watchdog/ProcessError.h"
#include "watchdog/UniqueFd.h"

extern char** environ;

namespace rgnav {
namespace {

enum class Stage : int { Redirect = 1, Chdir = 2, Exec = 3 };

struct ChildFailure {
  Stage stage;
  int error;
};

std::string errnoText(int error) { return std::system_category().message(error); }

// Moves a descriptor to a number above 2, so that dup2 onto 0..2 in the child never meets it.
UniqueFd aboveStdio(UniqueFd fd) {
  if (fd.get() > 2) return fd;
  const int moved = fcntl(fd.get(), F_DUPFD_CLOEXEC, 3);
  if (moved < 0) throw ProcessError("fcntl(F_DUPFD_CLOEXEC): " + errnoText(errno));
  return UniqueFd(moved);
}

UniqueFd openOrThrow(const std::string& path, int flags, const char* purpose) {
  UniqueFd fd(open(path.c_str(), flags | O_CLOEXEC, 0644));
  if (!fd.valid()) throw FileError(std::string("cannot open ") + purpose + " " + path + ": " + errnoText(errno));
  return aboveStdio(std::move(fd));
}

std::vector<std::string> environmentWith(const std::map<std::string, std::string>& extra) {
  std::vector<std::string> out;
  for (char** entry = environ; *entry != nullptr; ++entry) {
    const std::string_view text(*entry);
    if (!extra.count(std::string(text.substr(0, text.find('='))))) out.emplace_back(text);
  }
  for (const auto& [name, value] : extra) out.push_back(name + "=" + value);
  return out;
}

std::vector<char*> pointersTo(std::vector<std::string>& strings) {
  std::vector<char*> out;
  for (std::string& s : strings) out.push_back(s.data());
  out.push_back(nullptr);
  return out;
}

struct ChildSetup {
  char* const* argv;
  char* const* envp;
  const char* cwd;  // nullptr: keep
  int stdinFd;
  int logFd;
  int reportFd;
  int parentDeathSignal;
  struct sigaction defaultAction;
};

[[noreturn]] void failInChild(int reportFd, Stage stage) {
  const ChildFailure failure{stage, errno};
  while (write(reportFd, &failure, sizeof failure) < 0 && errno == EINTR) {
  }
  _exit(127);
}

[[noreturn]] void runChild(const ChildSetup& s) {
  setpgid(0, 0);
  if (s.parentDeathSignal != 0) prctl(PR_SET_PDEATHSIG, s.parentDeathSignal);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  for (int sig = 1; sig < NSIG; ++sig) sigaction(sig, &s.defaultAction, nullptr);  // undo SIG_IGN
  if (dup2(s.stdinFd, 0) < 0 || dup2(s.logFd, 1) < 0 || dup2(s.logFd, 2) < 0) failInChild(s.reportFd, Stage::Redirect);
  if (s.cwd != nullptr && chdir(s.cwd) != 0) failInChild(s.reportFd, Stage::Chdir);
  // The watchdog's other descriptors (listening sockets above all) must not leak into modules.
  if (s.reportFd > 3) close_range(3, static_cast<unsigned>(s.reportFd) - 1, 0);
  close_range(static_cast<unsigned>(s.reportFd) + 1, ~0U, 0);
  execvpe(s.argv[0], s.argv, s.envp);
  failInChild(s.reportFd, Stage::Exec);
}

const char* stageText(Stage stage) {
  switch (stage) {
    case Stage::Redirect:
      return "cannot redirect output of";
    case Stage::Chdir:
      return "cannot change to the working directory of";
    case Stage::Exec:
      return "cannot exec";
  }
  return "cannot start";
}

}  // namespace

pid_t spawnProcess(const SpawnSpec& spec) {
  if (spec.argv.empty() || spec.argv.front().empty()) throw InvalidArgumentError("spawn: empty command");
  std::vector<std::string> argvStrings = spec.argv;
  std::vector<std::string> envStrings = environmentWith(spec.env);
  const std::vector<char*> argv = pointersTo(argvStrings);
  const std::vector<char*> envp = pointersTo(envStrings);
  const UniqueFd devNull = openOrThrow("/dev/null", O_RDONLY, "input");
  const UniqueFd log = openOrThrow(spec.logFile, O_WRONLY | O_CREAT | O_APPEND, "log file");
  int ends[2];
  if (pipe2(ends, O_CLOEXEC) != 0) throw ProcessError("pipe2: " + errnoText(errno));
  UniqueFd readEnd = aboveStdio(UniqueFd(ends[0]));
  UniqueFd writeEnd = aboveStdio(UniqueFd(ends[1]));

  ChildSetup setup{argv.data(), envp.data(), spec.cwd.empty() ? nullptr : spec.cwd.c_str(),
                   devNull.get(), log.get(), writeEnd.get(), spec.parentDeathSignal, {}};
  setup.defaultAction.sa_handler = SIG_DFL;
  sigemptyset(&setup.defaultAction.sa_mask);

  const pid_t pid = fork();
  if (pid < 0) throw ProcessError("fork for '" + spec.argv.front() + "': " + errnoText(errno));
  if (pid == 0) runChild(setup);
  writeEnd.reset();
  setpgid(pid, pid);  // also done by the child; whichever runs first wins, the other may fail

  ChildFailure failure{};
  ssize_t n = 0;
  do {
    n = read(readEnd.get(), &failure, sizeof failure);
  } while (n < 0 && errno == EINTR);
  if (n == 0) return pid;
  discardChild(pid);
  if (n == static_cast<ssize_t>(sizeof failure)) {
    throw ProcessError(std::string(stageText(failure.stage)) + " '" + spec.argv.front() + "': " +
                       errnoText(failure.error));
  }
  throw ProcessError("cannot start '" + spec.argv.front() + "': lost contact with the child");
}

void discardChild(pid_t pid) {
  if (pid <= 1) return;
  kill(pid, SIGKILL);
  while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
  }
}

}  // namespace rgnav
