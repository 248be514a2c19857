// SPDX-License-Identifier: LGPL-3.0-or-later
// exbsp error hierarchy: the library reports every failure by throwing one of these;
// it never aborts or exits. The command line maps them to exit codes (docs/contract.md "Command
// line"): input_error, scene_error, usage_error and output_error -> 2, limit_error (and
// std::bad_alloc) -> 3.
#pragma once
#include <stdexcept>
#include <string>
#include <exbsp/core/export.h>

namespace exbsp {

/// Base of all exbsp errors. what() is a complete, user-facing message.
class EXBSP_EXPORT error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Bad input file: unreadable, syntax error, NaN/Inf, index out of range, count mismatch.
/// The message names the file and, where there is one, the line ("FILE:LINE: ...").
class EXBSP_EXPORT input_error : public error {
 public:
  input_error(const std::string& file, std::size_t line, const std::string& what)
      : error(line ? file + ":" + std::to_string(line) + ": " + what : file + ": " + what),
        file_(file),
        line_(line) {}
  const std::string& file() const { return file_; }
  /// 1-based line number, or 0 when the problem has no line (binary files, missing file).
  std::size_t line() const { return line_; }

 private:
  std::string file_;
  std::size_t line_;
};

/// Bad scene: a missing or wrongly typed key, an impossible camera or projection.
/// The message names the scene file and the key (JSON pointer style, e.g. /projection/near).
class EXBSP_EXPORT scene_error : public error {
 public:
  scene_error(const std::string& file, const std::string& key, const std::string& what)
      : error(file + ": " + (key.empty() ? std::string() : key + ": ") + what),
        file_(file),
        key_(key) {}
  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }

 private:
  std::string file_, key_;
};

/// A resource limit was reached (e.g. --max-fragments); nothing partial is returned.
class EXBSP_EXPORT limit_error : public error {
 public:
  using error::error;
};

/// An output file could not be written (directory missing, disk full, permission, rename).
/// The message names the file ("FILE: cannot write output: ..."); nothing partial is left.
class EXBSP_EXPORT output_error : public error {
 public:
  output_error(const std::string& file, const std::string& what)
      : error(file + ": " + what), file_(file) {}
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

/// The caller cancelled a build by throwing this from build_options::progress (bsp/engine.h);
/// bsp::build lets it through unchanged and keeps nothing of the partial tree.
class EXBSP_EXPORT build_cancelled : public error {
 public:
  build_cancelled() : error("build cancelled") {}
  using error::error;
};

/// A caller broke a documented precondition (e.g. a zero direction vector).
class EXBSP_EXPORT usage_error : public error {
 public:
  using error::error;
};

}  // namespace exbsp
