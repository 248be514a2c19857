// SPDX-License-Identifier: LGPL-3.0-or-later
// Atomic file output (notation in atomic_file.h). Temporary names are
// DIR/.exbsp-RRRRRRRRRRRR.tmp (12 random letters): short, so a target name near the 255-byte
// limit still works. mkstemp is not used because it creates the file 0600 whatever the
// umask; open(O_CREAT|O_EXCL|O_NOFOLLOW, 0666) lets the kernel apply the umask.
//
// Signal cleanup: a fixed table of in-flight temporary paths. A slot is claimed (state 1),
// filled, then published (state 2); the handler unlinks only published slots, restores the
// default action and re-raises the signal. Everything the handler touches is a lock-free
// atomic or a char array, and unlink/sigaction/raise are async-signal-safe.
#include "core/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <memory>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <random>

#include <exbsp/core/errors.h>

namespace exbsp {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what, int err = 0) {
  throw output_error(
      path, "cannot write output: " + what + (err ? std::string(": ") + std::strerror(err) : ""));
}

// ---- in-flight temporary files, removed by the signal handler ----

constexpr std::size_t max_pending = 16;
struct pending_slot {
  std::atomic<int> state{0};  // 0 free, 1 being filled, 2 published
  char path[PATH_MAX + 1];
};
std::array<pending_slot, max_pending> pending;
// Every catchable signal whose default action ends the process without a fault (faults,
// SIGSEGV and the like, are left to the runtime and the sanitizers): a full disk under
// `ulimit -f` (SIGXFSZ), a closed pipe, Ctrl-\ (SIGQUIT), timers and the user signals.
constexpr int cleanup_signals[] = {SIGHUP,  SIGINT,  SIGQUIT, SIGPIPE, SIGALRM,   SIGTERM,
                                   SIGUSR1, SIGUSR2, SIGXCPU, SIGXFSZ, SIGVTALRM, SIGPROF};

extern "C" void remove_pending_and_reraise(int sig) {
  const int saved = errno;
  for (pending_slot& s : pending)
    if (s.state.load() == 2) ::unlink(s.path);
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  ::sigaction(sig, &dfl, nullptr);
  errno = saved;
  ::raise(sig);  // delivered when the handler returns (the signal is blocked until then)
}

// Installs the handler for the signals whose action is still the default (an application's
// own handler, or SIG_IGN, is left alone). Once per process.
void install_signal_cleanup() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : cleanup_signals) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) != 0 || (old.sa_flags & SA_SIGINFO) ||
          old.sa_handler != SIG_DFL)
        continue;
      struct sigaction act {};
      act.sa_handler = remove_pending_and_reraise;
      sigemptyset(&act.sa_mask);
      ::sigaction(sig, &act, nullptr);
    }
  });
}

// Registers `path` for removal on a signal; returns the slot or -1 when the table is full
// or the path too long (the write still works, only the signal cleanup is lost).
int register_pending(const std::string& path) {
  if (path.size() > PATH_MAX) return -1;
  for (std::size_t i = 0; i < max_pending; ++i) {
    int expected = 0;
    if (pending[i].state.compare_exchange_strong(expected, 1)) {
      std::memcpy(pending[i].path, path.c_str(), path.size() + 1);
      pending[i].state.store(2);
      return static_cast<int>(i);
    }
  }
  return -1;
}

void unregister_pending(int slot) {
  if (slot >= 0) pending[static_cast<std::size_t>(slot)].state.store(0);
}

// ---- writing ----

// Writes all of `bytes` to `fd`; returns 0 or the errno of the failure.
int write_all(int fd, std::string_view bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

using producer = std::function<void(const output_sink&)>;

// Non-regular targets ("-", devices, FIFOs): written in place, nothing to replace.
void write_directly(const std::string& path, const producer& produce) {
  if (path == "-") {
    std::fflush(stdout);  // keep the order of anything printed through stdio before
    produce([](std::string_view bytes) {
      if (const int err = write_all(STDOUT_FILENO, bytes))
        fail("(standard output)", "write failed", err);
    });
    return;
  }
  const int fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) fail(path, "cannot open", errno);
  try {
    produce([&](std::string_view bytes) {
      if (const int err = write_all(fd, bytes)) fail(path, "write failed", err);
    });
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
}

std::string random_letters(std::size_t n) {
  static const char alphabet[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  thread_local std::mt19937_64 gen{std::random_device{}() ^ (std::uint64_t(::getpid()) << 32)};
  std::string s(n, 'x');
  for (char& c : s) c = alphabet[gen() % (sizeof alphabet - 1)];
  return s;
}

std::string directory_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

}  // namespace

int pending_temporary_files() {
  int n = 0;
  for (const pending_slot& s : pending) n += s.state.load() != 0;
  return n;
}

void write_file_atomically(const std::string& path, std::string_view bytes) {
  write_file_atomically(path, [&](const output_sink& sink) { sink(bytes); });
}

void write_file_atomically(const std::string& path, const producer& produce) {
  if (path.empty()) throw output_error("(empty file name)", "cannot write output: empty file name");
  if (path == "-") return write_directly(path, produce);

  // What is there now: nothing, a regular file (maybe through a symlink), or something else.
  std::string target = path;
  struct stat existing {};
  bool exists = false;
  if (::stat(path.c_str(), &existing) == 0) {
    exists = true;
    if (S_ISDIR(existing.st_mode)) fail(path, "it is a directory");
    if (!S_ISREG(existing.st_mode)) return write_directly(path, produce);
    struct stat link {};
    if (::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
      // Replace the file the link points to and keep the link.
      char* real = ::realpath(path.c_str(), nullptr);
      if (!real) fail(path, "cannot resolve the symbolic link", errno);
      target = real;
      std::free(real);
    }
  } else if (errno != ENOENT) {
    fail(path, "cannot examine the target", errno);
  } else {
    struct stat link {};
    if (::lstat(path.c_str(), &link) == 0) fail(path, "it is a symbolic link to a missing file");
  }

  install_signal_cleanup();
  const std::string dir = directory_of(target);
  std::string tmp;
  int fd = -1;
  int slot = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    tmp = dir + "/.exbsp-" + random_letters(12) + ".tmp";
    slot = register_pending(tmp);
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0) {
      const int err = errno;
      unregister_pending(slot);
      if (err != EEXIST) fail(path, "cannot create a temporary file in " + dir, err);
    }
  }
  if (fd < 0) fail(path, "cannot create a temporary file in " + dir, EEXIST);
  bool discarded = false;  // the temporary file is gone (discard ran)
  const auto discard = [&](const char* what, int err) {
    if (fd >= 0) ::close(fd);
    fd = -1;
    ::unlink(tmp.c_str());
    unregister_pending(slot);
    discarded = true;
    fail(path, what, err);
  };
  try {
    produce([&](std::string_view bytes) {
      if (const int err = write_all(fd, bytes)) discard("write failed", err);
    });
  } catch (...) {
    if (!discarded) {  // the producer failed: nothing of it may stay
      ::close(fd);
      ::unlink(tmp.c_str());
      unregister_pending(slot);
    }
    throw;
  }
  if (exists) {
    // Keep the replaced file's owner (only root may give it away; failure is harmless) and mode.
    if (::fchown(fd, existing.st_uid, existing.st_gid) != 0) { /* not permitted: keep ours */
    }
    if (::fchmod(fd, existing.st_mode & 07777) != 0) discard("cannot set the file mode", errno);
  }
  if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) discard("fsync failed", errno);
  const int closed = ::close(fd);
  fd = -1;
  if (closed != 0) discard("close failed", errno);
  if (::rename(tmp.c_str(), target.c_str()) != 0) discard("cannot replace the file", errno);
  unregister_pending(slot);
  // Make the rename durable too (best effort: not every file system supports it).
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

removed_on_signal::removed_on_signal(std::string path) : path_(std::move(path)) {
  install_signal_cleanup();
  slot_ = register_pending(path_);
}

std::unique_ptr<removed_on_signal> removed_on_signal::create(const std::string& pattern) {
  // The name is registered before the file exists (a signal on any thread in between unlinks a
  // name that is not there yet, which is harmless), then created with O_EXCL, as mkstemp does.
  const std::string suffix = "XXXXXX";
  if (pattern.size() < suffix.size() ||
      pattern.compare(pattern.size() - suffix.size(), suffix.size(), suffix) != 0)
    throw output_error(pattern, "a temporary file pattern must end in XXXXXX");
  static const char letters[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  std::random_device random;
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string path = pattern.substr(0, pattern.size() - suffix.size());
    for (std::size_t k = 0; k < suffix.size(); ++k)
      path += letters[random() % (sizeof letters - 1)];
    auto file = std::make_unique<removed_on_signal>(path);
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd >= 0) {
      ::close(fd);
      return file;
    }
    const int err = errno;
    file->path_.clear();  // not ours: the destructor must not remove it
    if (err != EEXIST)
      throw output_error(pattern,
                         std::string("cannot make a temporary file: ") + std::strerror(err));
  }
  throw output_error(pattern, "cannot make a temporary file: 100 names taken");
}

removed_on_signal::~removed_on_signal() {
  unregister_pending(slot_);
  if (!path_.empty()) ::unlink(path_.c_str());
}

}  // namespace exbsp
