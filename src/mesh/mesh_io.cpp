// SPDX-License-Identifier: LGPL-3.0-or-later
// Mesh input entry points: choose the reader by extension, load the whole file into memory
// and hand it to the format reader (read_off.cpp, read_obj.cpp, read_ply.cpp, read_stl.cpp).
#include <exbsp/mesh/mesh_io.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <exbsp/core/errors.h>
#include "core/file_name.h"
#include "mesh/reader_util.h"

namespace exbsp {
namespace {

constexpr const char* supported_extensions = ".off, .obj, .ply, .stl";

}  // namespace

std::string read_input_file(const std::string& path) {
  // O_NONBLOCK: opening a FIFO without a writer must not hang; fstat then refuses it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) throw input_error(path, 0, std::string("cannot open file: ") + std::strerror(errno));
  struct fd_closer {
    int fd;
    ~fd_closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0)
    throw input_error(path, 0, std::string("cannot examine file: ") + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) {
    const char* kind = S_ISDIR(st.st_mode)    ? "a directory"
                       : S_ISFIFO(st.st_mode) ? "a FIFO (named pipe)"
                       : S_ISCHR(st.st_mode)  ? "a character device"
                       : S_ISBLK(st.st_mode)  ? "a block device"
                       : S_ISSOCK(st.st_mode) ? "a socket"
                                              : "a special file";
    throw input_error(path, 0,
                      std::string("cannot read ") + kind + " (input must be a regular file)");
  }
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(st.st_size));
  char buffer[1 << 16];
  for (;;) {
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got < 0) {
      if (errno == EINTR) continue;
      throw input_error(path, 0, std::string("cannot read file: ") + std::strerror(errno));
    }
    if (got == 0) break;
    bytes.append(buffer, static_cast<std::size_t>(got));
  }
  return bytes;
}

mesh_format mesh_format_for_path(const std::string& path) {
  const std::string ext = file_extension(path);
  if (ext.empty())
    throw input_error(
        path, 0, std::string("no file extension; supported mesh formats: ") + supported_extensions);
  if (has_extension(path, ".off")) return mesh_format::off;
  if (has_extension(path, ".obj")) return mesh_format::obj;
  if (has_extension(path, ".ply")) return mesh_format::ply;
  if (has_extension(path, ".stl")) return mesh_format::stl;
  throw input_error(path, 0,
                    "unknown file extension " + mesh_detail::quote(ext) +
                        "; supported mesh formats: " + supported_extensions);
}

triangle_soup read_mesh_data(std::string_view data, mesh_format format, const std::string& name) {
  if (data.empty()) throw input_error(name, 0, "empty file");
  // A UTF-8 byte order mark (written by some editors) is not part of the text formats.
  // STL decides itself: a binary STL's 80-byte header may begin with those bytes.
  const std::string_view text = mesh_detail::skip_utf8_bom(data);
  if (text.empty() && format != mesh_format::stl)
    throw input_error(name, 0, "empty file (only a byte order mark)");
  switch (format) {
    case mesh_format::off:
      return mesh_detail::read_off(text, name);
    case mesh_format::obj:
      return mesh_detail::read_obj(text, name);
    case mesh_format::ply:
      return mesh_detail::read_ply(text, name);
    case mesh_format::stl:
      return mesh_detail::read_stl(data, name);
  }
  throw usage_error("read_mesh_data: invalid mesh_format value");
}

triangle_soup read_mesh(const std::string& path) {
  const mesh_format format = mesh_format_for_path(path);
  const std::string bytes = read_input_file(path);
  return read_mesh_data(bytes, format, path);
}

}  // namespace exbsp
