// SPDX-License-Identifier: LGPL-3.0-or-later
// Private: the saved-tree format (docs/tree-file.md). A little-endian byte writer, a bounded
// reader that names the byte offset and field of every problem, and the parts of a tree file
// that do not depend on the kernel. bsp::save / bsp::load (engine.h) are the public side.
//
// Notation: V input vertices, T input triangles (soup order, degenerate ones included),
// D degenerate triangles, C constructed points (exact kernel), F fragments, N nodes.
#pragma once
#include <gmp.h>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/mesh/soup.h>

namespace exbsp {

class bsp_impl;

namespace tree_file {

/// "EXBSP", then CR LF and Ctrl-Z, which catch a text-mode transfer (as PNG's signature does).
inline constexpr char magic[8] = {'E', 'X', 'B', 'S', 'P', '\r', '\n', '\x1a'};
inline constexpr std::size_t magic_size = sizeof magic;
/// The version this code writes and the only one it reads.
inline constexpr std::uint32_t format_version = 1;
/// Bytes before the body: magic, version, kernel code, body size.
inline constexpr std::size_t header_size = 24;
/// The CRC-32 after the body.
inline constexpr std::size_t trailer_size = 4;

/// The CRC-32 (zlib's) of the bytes.
std::uint32_t crc32(std::string_view bytes);

/// Appends little-endian fixed-width fields to a byte string.
class writer {
 public:
  void u8(std::uint8_t v) { out_.push_back(static_cast<char>(v)); }
  void u32(std::uint32_t v) { put(v, 4); }
  void i32(std::int32_t v) { put(static_cast<std::uint32_t>(v), 4); }
  void u64(std::uint64_t v) { put(v, 8); }
  /// The IEEE bit pattern of v.
  void f64(double v);
  /// u32 length, then the bytes.
  void text(const std::string& s);
  void bytes(const void* data, std::size_t n) { out_.append(static_cast<const char*>(data), n); }
  std::string& data() { return out_; }

 private:
  void put(std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) out_.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
  }
  std::string out_;
};

/// Reads fields from a tree file's bytes. Every read checks the remaining size; every problem
/// throws input_error "NAME: byte OFFSET: FIELD: what" (OFFSET from the start of the file).
class reader {
 public:
  reader(std::string_view data, std::string name, std::size_t base_offset = 0)
      : data_(data), name_(std::move(name)), base_(base_offset) {}

  std::uint8_t u8(const char* field) { return static_cast<std::uint8_t>(get(field, 1)); }
  std::uint32_t u32(const char* field) { return static_cast<std::uint32_t>(get(field, 4)); }
  std::int32_t i32(const char* field) {
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(get(field, 4)));
  }
  std::uint64_t u64(const char* field) { return get(field, 8); }
  double f64(const char* field);
  /// A u32-length string of at most max_length bytes.
  std::string text(const char* field, std::size_t max_length);
  /// Raw bytes (a view into the data).
  std::string_view bytes(const char* field, std::size_t n);
  /// A u64 count of elements of `element_bytes` bytes each (at least 1) that must all fit in
  /// the bytes left, so a forged count can never make a huge allocation; and at most `max`.
  std::size_t count(const char* field, std::size_t element_bytes, std::uint64_t max);

  /// Offset of the next byte from the start of the file.
  std::size_t offset() const { return base_ + pos_; }
  std::size_t remaining() const { return data_.size() - pos_; }
  const std::string& name() const { return name_; }
  /// Throws input_error at the current offset.
  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    fail_at(offset(), field, what);
  }
  /// Throws input_error at `offset` (from the start of the file).
  [[noreturn]] void fail_at(std::size_t offset, const std::string& field,
                            const std::string& what) const;

 private:
  std::uint64_t get(const char* field, int n);
  std::string_view data_;
  std::string name_;
  std::size_t base_;
  std::size_t pos_ = 0;
};

/// What a tree file holds besides the kernel's own representation: the build's statistics
/// (the seed among them) and the sampled heuristic's parameters, and the input soup
/// (vertices, triangles with face ids) whose planes the nodes refer to.
struct common_part {
  build_stats stats;
  std::size_t stats_offset = 0;  ///< where the stats start in the file, for messages
  unsigned sampled_candidates = 0, sampled_samples = 0, sampled_split_weight = 0;
  triangle_soup soup;
};

/// Writes the common part of a tree's body with the tree's `stats` (common.stats is ignored).
void write_common(writer& out, const build_stats& stats, const common_part& common);
/// Reads what write_common wrote (input_error through `in` for anything malformed).
common_part read_common(reader& in);

/// A whole tree file: the header (magic, version, the kernel's file code, the body's size),
/// the body `write_body` writes, and the CRC-32 trailer.
template <class WriteBody>
std::string framed(std::uint32_t kernel_code, WriteBody&& write_body) {
  writer out;
  out.bytes(magic, magic_size);
  out.u32(format_version);
  out.u32(kernel_code);
  out.u64(0);  // body size, patched below
  write_body(out);
  std::string& bytes = out.data();
  const std::uint64_t body = bytes.size() - header_size;
  for (int i = 0; i < 8; ++i) bytes[16 + i] = static_cast<char>((body >> (8 * i)) & 0xff);
  out.u32(crc32(bytes));
  return std::move(bytes);
}

/// A rational as u32 sign-and-length of the numerator's magnitude (bit 31: negative), its
/// bytes (least significant first), then the same for the denominator (positive). The
/// reader accepts only the canonical form: no leading zero byte, zero as length 0, a positive
/// denominator coprime to the numerator.
void write_rational(writer& out, mpq_srcptr q);
void read_rational(reader& in, const char* field, mpq_ptr out);

/// "field[i]" for messages.
std::string indexed(const char* field, std::size_t i);

}  // namespace tree_file
}  // namespace exbsp
