// Mesh input entry points: choose the reader by extension, load the whole file into memory
// and hand it to the format reader (read_off.cpp, read_obj.cpp, read_ply.cpp, read_stl.cpp).
#include "mesh/mesh_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "mesh/errors.h"
#include "mesh/reader_util.h"

namespace exbsp {
namespace {

constexpr const char* supported_extensions = ".off, .obj, .ply, .stl";

struct file_closer {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

// The whole file as bytes; throws input_error (line 0) when it cannot be opened or read.
std::string read_file_bytes(const std::string& path) {
  errno = 0;
  std::unique_ptr<std::FILE, file_closer> f(std::fopen(path.c_str(), "rb"));
  if (!f) throw input_error(path, 0, std::string("cannot open file: ") + std::strerror(errno));
  std::string bytes;
  char buffer[1 << 16];
  for (;;) {
    const std::size_t got = std::fread(buffer, 1, sizeof buffer, f.get());
    bytes.append(buffer, got);
    if (got < sizeof buffer) break;
  }
  if (std::ferror(f.get())) {
    const int saved = errno;
    throw input_error(path, 0, std::string("cannot read file: ") + (saved ? std::strerror(saved) : "read error"));
  }
  return bytes;
}

}  // namespace

mesh_format mesh_format_for_path(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    throw input_error(path, 0, std::string("no file extension; supported mesh formats: ") + supported_extensions);
  std::string ext = path.substr(dot);
  for (char& c : ext)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  if (ext == ".off") return mesh_format::off;
  if (ext == ".obj") return mesh_format::obj;
  if (ext == ".ply") return mesh_format::ply;
  if (ext == ".stl") return mesh_format::stl;
  throw input_error(path, 0, "unknown file extension " + mesh_detail::quote(path.substr(dot)) +
                                 "; supported mesh formats: " + supported_extensions);
}

triangle_soup read_mesh_data(std::string_view data, mesh_format format, const std::string& name) {
  if (data.empty()) throw input_error(name, 0, "empty file");
  switch (format) {
    case mesh_format::off: return mesh_detail::read_off(data, name);
    case mesh_format::obj: return mesh_detail::read_obj(data, name);
    case mesh_format::ply: return mesh_detail::read_ply(data, name);
    case mesh_format::stl: return mesh_detail::read_stl(data, name);
  }
  throw usage_error("read_mesh_data: invalid mesh_format value");
}

triangle_soup read_mesh(const std::string& path) {
  const mesh_format format = mesh_format_for_path(path);
  const std::string bytes = read_file_bytes(path);
  return read_mesh_data(bytes, format, path);
}

}  // namespace exbsp
