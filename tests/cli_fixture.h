// Shared by the test files that run the exbsp command line (EXBSP_CLI) as a separate process:
// a GoogleTest fixture with a fresh temporary directory per test, the CLI run inside it.
#pragma once
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

namespace exbsp_test {

/// Exit status (-1 when the process did not exit normally), standard output and error.
struct run_result {
  int status;
  std::string out, err;
};

/// The whole file (empty when it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Fixture: `dir` is a fresh temporary directory, removed after the test.
class cli_fixture : public ::testing::Test {
protected:
  void SetUp() override {
    std::string tmpl = (std::filesystem::temp_directory_path() / "exbsp_cli_XXXXXX").string();
    ASSERT_NE(::mkdtemp(tmpl.data()), nullptr);
    dir = tmpl;
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
  /// Runs `exbsp ARGS` in dir (arguments already shell-quoted where needed).
  run_result run(const std::string& args) {
    const std::string cmd = "cd '" + dir.string() + "' && '" + EXBSP_CLI + "' " + args + " >.out 2>.err </dev/null";
    const int raw = std::system(cmd.c_str());
    run_result r{raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(dir / ".out"), slurp(dir / ".err")};
    std::filesystem::remove(dir / ".out");
    std::filesystem::remove(dir / ".err");
    return r;
  }
  void write(const std::string& name, const std::string& text) { std::ofstream(dir / name) << text; }
  /// Number of entries in dir.
  std::size_t file_count() const {
    return static_cast<std::size_t>(
        std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()));
  }
  std::filesystem::path dir;
};

}  // namespace exbsp_test
