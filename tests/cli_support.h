// Helpers of the tests that run the exbsp command line (EXBSP_CLI) as a separate process:
// whole-file reads and writes, shell quoting, and one run with stdout and stderr captured.
#pragma once
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace exbsp_test {

/// The bytes of file `p` (empty when it cannot be read).
inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Writes `text` to file `p` (created or truncated).
inline void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

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
/// environment assignment or `prlimit ...`) in `dir`, stdin from /dev/null.
inline cli_result run_cli(const std::filesystem::path& dir, const std::string& args, const std::string& prefix = "") {
  const std::filesystem::path out = dir / ".stdout", err = dir / ".stderr";
  const std::string cmd = "cd " + quoted(dir.string()) + " && " + prefix + " " + quoted(EXBSP_CLI) + " " + args +
                          " >" + quoted(out.string()) + " 2>" + quoted(err.string()) + " </dev/null";
  const int raw = std::system(cmd.c_str());
  cli_result r;
  r.status = raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_file(out);
  r.err = read_file(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

}  // namespace exbsp_test
