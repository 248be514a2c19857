// SPDX-License-Identifier: LGPL-3.0-or-later
// Helpers of the tests that run the exbsp command line (EXBSP_CLI) as a separate process:
// shell quoting, one run with stdout and stderr captured, and a GoogleTest fixture with a
// fresh temporary directory per test, the CLI run inside it.
#pragma once
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "support/test_helpers.h"

namespace exbsp_test {

/// `s` quoted for /bin/sh.
inline std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// What one run of the command line did.
struct cli_result {
  int status = -1;  ///< exit status, -1 if the process did not exit normally
  std::string out, err;
};

/// Runs `PREFIX exbsp ARGS` (args already shell-quoted where needed; prefix e.g. an
/// environment assignment or `prlimit ...`) in `dir`, stdin from `input` (default /dev/null).
inline cli_result run_cli(const std::filesystem::path& dir, const std::string& args,
                          const std::string& prefix = "", const std::string& input = "/dev/null") {
  const std::filesystem::path out = dir / ".stdout", err = dir / ".stderr";
  const std::string cmd = "cd " + quoted(dir.string()) + " && " + prefix + " " + quoted(EXBSP_CLI) +
                          " " + args + " >" + quoted(out.string()) + " 2>" + quoted(err.string()) +
                          " <" + quoted(input);
  const int raw = std::system(cmd.c_str());
  cli_result r;
  r.status = raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_file(out);
  r.err = read_file(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

/// Fixture: `dir` is a fresh temporary directory, removed after the test.
class cli_fixture : public ::testing::Test {
 protected:
  void SetUp() override { dir = make_temp_dir("cli"); }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
  /// Runs `PREFIX exbsp ARGS` in dir (arguments already shell-quoted where needed).
  cli_result run(const std::string& args, const std::string& prefix = "") {
    return run_cli(dir, args, prefix);
  }
  /// Same, with standard input read from the file `input`.
  cli_result run_with_input(const std::string& args, const std::string& input) {
    return run_cli(dir, args, "", input);
  }
  void write(const std::string& name, const std::string& text) { write_file(dir / name, text); }
  /// Names of the files in dir, sorted.
  std::vector<std::string> file_names() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir))
      names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  std::size_t file_count() const { return file_names().size(); }
  std::filesystem::path dir;
};

}  // namespace exbsp_test
