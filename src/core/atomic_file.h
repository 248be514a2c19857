// SPDX-License-Identifier: LGPL-3.0-or-later
// Output files, the one writer every exbsp output goes through (order JSON, PNG, SVG, ...).
// A regular file is replaced atomically: the bytes go to a fresh temporary file in the
// target's directory (created O_CREAT|O_EXCL|O_NOFOLLOW under a short random name, so a
// planted file or symlink is never followed or overwritten), which is fsynced and renamed
// over the target. A failed or interrupted run never leaves a partial, truncated or
// clobbered file. It lives in exbsp_core, below every other module.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <exbsp/core/export.h>

namespace exbsp {

/// Writes `bytes` to `path`:
/// - "-": standard output, directly;
/// - an existing non-regular file (a device such as /dev/null, a FIFO): opened and written
///   directly (never replaced by a regular file);
/// - otherwise (a new or existing regular file, also through a symbolic link, which is kept):
///   temporary file + fsync + rename. A new file gets mode 0666 minus the umask; an existing
///   file keeps its mode (and, where permitted, its owner).
/// The temporary file is removed on error and, while it exists, on SIGINT, SIGTERM and SIGHUP
/// (when those signals have their default action; the signal is then re-raised).
/// Throws output_error naming `path` (empty name, missing directory, a directory, permission,
/// disk full, ...); any existing file at `path` is then left untouched.
EXBSP_EXPORT void write_file_atomically(const std::string& path, std::string_view bytes);

/// Receives an output's bytes piece by piece.
using output_sink = std::function<void(std::string_view)>;

/// The same for output made in pieces: `produce(sink)` passes the bytes to `sink` in order, so
/// a large output (a whole order document) is never held in memory at once. The same rules;
/// if `produce` throws, the temporary file is removed and the exception passes on (for "-"
/// and non-regular targets, the pieces written so far stay written).
EXBSP_EXPORT void write_file_atomically(const std::string& path,
                                        const std::function<void(const output_sink&)>& produce);

/// A temporary file made by the caller (for a library that writes only to a file name, such
/// as dxflib): removed when this object is destroyed and, while it exists, by the signal
/// handler of write_file_atomically's own temporary files (the same signals). The file
/// itself is the caller's to create.
class EXBSP_EXPORT removed_on_signal {
 public:
  explicit removed_on_signal(std::string path);
  /// Creates a new empty file (mode 0600) from `pattern`, whose XXXXXX becomes a random suffix
  /// as with mkstemp. The name is registered before the file is created, so a signal at any
  /// moment leaves nothing behind. Throws output_error naming the pattern when it cannot be
  /// created.
  static std::unique_ptr<removed_on_signal> create(const std::string& pattern);
  ~removed_on_signal();
  removed_on_signal(const removed_on_signal&) = delete;
  removed_on_signal& operator=(const removed_on_signal&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int slot_;
};

/// Number of temporary output files currently being written (registered for removal on a
/// signal). For tests: 0 whenever no write_file_atomically call is running.
EXBSP_EXPORT int pending_temporary_files();

}  // namespace exbsp
