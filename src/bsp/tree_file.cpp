// SPDX-License-Identifier: LGPL-3.0-or-later
// Saved trees: the file's frame (magic, version, kernel, body size, CRC-32), the common part
// (stats, options, soup) and bsp::save / load. The kernel-specific parts are in
// tree_file_impl.h. Layout and checks: docs/tree-file.md; notation: tree_file.h.
#include "bsp/tree_file.h"

#include <boost/crc.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <utility>

#include <exbsp/core/errors.h>
#include <exbsp/mesh/mesh_io.h>
#include "bsp/bsp_impl.h"
#include "bsp/kernels.h"
#include "core/atomic_file.h"

namespace exbsp {
namespace tree_file {
namespace {

std::uint32_t read_u32_at(std::string_view bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i)
    v |= std::uint32_t{static_cast<unsigned char>(bytes[at + i])} << (8 * i);
  return v;
}

std::uint64_t read_u64_at(std::string_view bytes, std::size_t at) {
  std::uint64_t v = 0;
  for (int i = 0; i < 8; ++i)
    v |= std::uint64_t{static_cast<unsigned char>(bytes[at + i])} << (8 * i);
  return v;
}

/// The stats' counts in file order, for the writer and the reader alike.
const std::pair<std::size_t build_stats::*, const char*> stats_counts[] = {
    {&build_stats::input_triangles, "stats.input_triangles"},
    {&build_stats::degenerate_input, "stats.degenerate_input"},
    {&build_stats::fragments, "stats.fragments"},
    {&build_stats::splits, "stats.splits"},
    {&build_stats::nodes, "stats.nodes"},
    {&build_stats::depth, "stats.depth"},
    {&build_stats::peak_rss_bytes, "stats.peak_rss_bytes"}};

/// Heuristic names are printed into JSON unescaped: letters, digits and a few marks only.
bool plain_name(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.' &&
        c != '+')
      return false;
  return true;
}

}  // namespace

void writer::f64(double v) {
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  u64(bits);
}

void writer::text(const std::string& s) {
  u32(static_cast<std::uint32_t>(s.size()));
  bytes(s.data(), s.size());
}

std::uint64_t reader::get(const char* field, int n) {
  if (remaining() < static_cast<std::size_t>(n))
    fail(field, "the data ends here (" + std::to_string(n) + " bytes needed, " +
                    std::to_string(remaining()) + " left)");
  std::uint64_t v = 0;
  for (int i = 0; i < n; ++i)
    v |= std::uint64_t{static_cast<unsigned char>(data_[pos_ + i])} << (8 * i);
  pos_ += static_cast<std::size_t>(n);
  return v;
}

double reader::f64(const char* field) {
  const std::uint64_t bits = get(field, 8);
  double v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

std::string reader::text(const char* field, std::size_t max_length) {
  const std::size_t at = offset();
  const std::uint32_t n = u32(field);
  if (n > max_length || n > remaining())
    fail_at(at, field,
            "length " + std::to_string(n) + " exceeds " +
                std::to_string(std::min(max_length, remaining())));
  return std::string(bytes(field, n));
}

std::string_view reader::bytes(const char* field, std::size_t n) {
  if (remaining() < n) fail(field, "the data ends here (" + std::to_string(n) + " bytes needed)");
  const std::string_view out = data_.substr(pos_, n);
  pos_ += n;
  return out;
}

std::size_t reader::count(const char* field, std::size_t element_bytes, std::uint64_t max) {
  const std::size_t at = offset();
  const std::uint64_t n = u64(field);
  if (n > max)
    fail_at(at, field, "count " + std::to_string(n) + " exceeds the limit " + std::to_string(max));
  if (n > remaining() / element_bytes)
    fail_at(at, field,
            "count " + std::to_string(n) + " needs at least " + std::to_string(element_bytes) +
                " bytes each, only " + std::to_string(remaining()) + " bytes are left");
  return static_cast<std::size_t>(n);
}

void reader::fail_at(std::size_t offset, const std::string& field, const std::string& what) const {
  throw input_error(name_, 0, "byte " + std::to_string(offset) + ": " + field + ": " + what);
}

std::string indexed(const char* field, std::size_t i) {
  return std::string(field) + "[" + std::to_string(i) + "]";
}

/// CRC-32 (the polynomial and conventions of zlib, PNG and zip: Boost.CRC's crc_32_type).
std::uint32_t crc32(std::string_view bytes) {
  boost::crc_32_type crc;
  crc.process_bytes(bytes.data(), bytes.size());
  return crc.checksum();
}

common_part read_common(reader& in) {
  common_part c;
  c.stats_offset = in.offset();
  build_stats& s = c.stats;
  for (const auto& [field, name] : stats_counts) s.*field = static_cast<std::size_t>(in.u64(name));
  s.seed = in.u64("stats.seed");
  const std::size_t seconds_at = in.offset();
  s.build_seconds = in.f64("stats.build_seconds");
  if (!std::isfinite(s.build_seconds) || s.build_seconds < 0)
    in.fail_at(seconds_at, "stats.build_seconds", "not a finite non-negative number");
  const std::size_t heuristic_at = in.offset();
  s.heuristic = in.text("stats.heuristic", 64);
  if (!plain_name(s.heuristic))
    in.fail_at(heuristic_at, "stats.heuristic",
               "not a heuristic name (letters, digits, '-', '_', '.', '+')");
  c.sampled_candidates = in.u32("options.sampled_candidates");
  c.sampled_samples = in.u32("options.sampled_samples");
  c.sampled_split_weight = in.u32("options.sampled_split_weight");

  triangle_soup& soup = c.soup;
  soup.face_count = in.u32("soup.face_count");
  const std::size_t vertices =
      in.count("soup.vertices", 24, std::numeric_limits<std::uint32_t>::max());
  soup.vertices.resize(vertices);
  for (std::size_t i = 0; i < vertices; ++i) {
    const std::size_t at = in.offset();
    for (int k = 0; k < 3; ++k) soup.vertices[i][k] = in.f64("soup.vertices");
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(soup.vertices[i][k]))
        in.fail_at(at, indexed("soup.vertices", i), "a coordinate is not finite");
  }
  const std::size_t triangles =
      in.count("soup.triangles", 16, std::numeric_limits<std::uint32_t>::max());
  soup.triangles.resize(triangles);
  for (std::size_t i = 0; i < triangles; ++i) {
    const std::size_t at = in.offset();
    soup_triangle& t = soup.triangles[i];
    for (int k = 0; k < 3; ++k) t.v[k] = in.u32("soup.triangles");
    t.face = in.u32("soup.triangles");
    for (int k = 0; k < 3; ++k)
      if (t.v[k] >= vertices)
        in.fail_at(at, indexed("soup.triangles", i),
                   "vertex " + std::to_string(t.v[k]) + " out of range (" +
                       std::to_string(vertices) + " vertices)");
  }
  return c;
}

void write_common(writer& out, const build_stats& s, const common_part& common) {
  for (const auto& [field, name] : stats_counts) out.u64(s.*field);
  out.u64(s.seed);
  out.f64(s.build_seconds);
  out.text(s.heuristic);
  out.u32(common.sampled_candidates);
  out.u32(common.sampled_samples);
  out.u32(common.sampled_split_weight);
  const triangle_soup& soup = common.soup;
  out.u32(soup.face_count);
  out.u64(soup.vertices.size());
  for (const vec3d& v : soup.vertices)
    for (double x : v) out.f64(x);
  out.u64(soup.triangles.size());
  for (const soup_triangle& t : soup.triangles) {
    for (std::uint32_t v : t.v) out.u32(v);
    out.u32(t.face);
  }
}

namespace {
constexpr std::uint32_t negative_bit = 0x80000000u;

void write_magnitude(writer& out, mpz_srcptr z, std::uint32_t sign_bit) {
  std::size_t n = (mpz_sizeinbase(z, 2) + 7) / 8;
  if (mpz_sgn(z) == 0) n = 0;
  if (n >= negative_bit) throw limit_error("save: a rational with more than 2^31 bytes");
  std::string bytes(n, '\0');
  std::size_t written = 0;
  if (n) mpz_export(bytes.data(), &written, -1, 1, 0, 0, z);  // least significant byte first
  out.u32(static_cast<std::uint32_t>(n) | sign_bit);
  out.bytes(bytes.data(), n);
}

/// Reads one magnitude into z; returns whether the sign bit was set.
bool read_magnitude(reader& in, const char* field, mpz_ptr z) {
  const std::size_t at = in.offset();
  const std::uint32_t head = in.u32(field);
  const std::size_t n = head & ~negative_bit;
  const std::string_view bytes = in.bytes(field, n);
  if (n && bytes.back() == '\0') in.fail_at(at, field, "not canonical: a leading zero byte");
  if (n == 0 && (head & negative_bit)) in.fail_at(at, field, "not canonical: a negative zero");
  if (n)
    mpz_import(z, n, -1, 1, 0, 0, bytes.data());
  else
    mpz_set_ui(z, 0);
  return (head & negative_bit) != 0;
}
}  // namespace

void write_rational(writer& out, mpq_srcptr q) {
  write_magnitude(out, mpq_numref(q), mpq_sgn(q) < 0 ? negative_bit : 0);
  write_magnitude(out, mpq_denref(q), 0);
}

void read_rational(reader& in, const char* field, mpq_ptr out) {
  const std::size_t at = in.offset();
  const bool negative = read_magnitude(in, field, mpq_numref(out));
  if (read_magnitude(in, field, mpq_denref(out)))
    in.fail_at(at, field, "not canonical: a negative denominator");
  if (mpz_sgn(mpq_denref(out)) == 0) in.fail_at(at, field, "a zero denominator");
  if (negative) mpz_neg(mpq_numref(out), mpq_numref(out));
  mpz_t g;
  mpz_init(g);
  mpz_gcd(g, mpq_numref(out), mpq_denref(out));
  const bool reduced = mpz_cmp_ui(g, 1) == 0 ||
                       (mpz_sgn(mpq_numref(out)) == 0 && mpz_cmp_ui(mpq_denref(out), 1) == 0);
  mpz_clear(g);
  if (!reduced) {
    mpz_set_ui(mpq_numref(out), 0);  // leave a valid value behind
    mpz_set_ui(mpq_denref(out), 1);
    in.fail_at(at, field, "not canonical: numerator and denominator have a common factor");
  }
}

}  // namespace tree_file

std::string bsp::serialize() const {
  return tree_file::framed(kernel_row_of(kernel()).file_code,
                           [&](tree_file::writer& out) { impl_->write_tree(out, true); });
}

std::string bsp::serialize_reproducible() const {
  return tree_file::framed(kernel_row_of(kernel()).file_code,
                           [&](tree_file::writer& out) { impl_->write_tree(out, false); });
}

bsp bsp::deserialize(std::string_view bytes, const std::string& name) {
  using namespace tree_file;
  const auto fail = [&](const std::string& what) { throw input_error(name, 0, what); };
  if (bytes.size() < magic_size || std::memcmp(bytes.data(), magic, magic_size) != 0) {
    if (bytes.size() >= 5 && std::memcmp(bytes.data(), magic, 5) == 0)
      fail(
          "byte 5: magic: the signature after \"EXBSP\" is damaged (was the file transferred in "
          "text mode?)");
    fail("not an exbsp saved tree (byte 0: no \"EXBSP\" signature)");
  }
  if (bytes.size() < header_size + trailer_size)
    fail("truncated: " + std::to_string(bytes.size()) + " bytes, a saved tree has at least " +
         std::to_string(header_size + trailer_size));
  const std::uint32_t version = read_u32_at(bytes, 8);
  if (version != format_version)
    fail("byte 8: version: format version " + std::to_string(version) +
         " is not supported (this exbsp reads version " + std::to_string(format_version) + ")");
  const std::uint32_t code = read_u32_at(bytes, 12);
  const kernel_row* row = kernel_row_of_file_code(code);
  if (!row) fail("byte 12: kernel: unknown kernel code " + std::to_string(code));
  const std::uint64_t body = read_u64_at(bytes, 16);
  const std::uint64_t actual = bytes.size() - header_size - trailer_size;
  if (body > actual)
    fail("truncated: the header announces " + std::to_string(body + header_size + trailer_size) +
         " bytes, the file has " + std::to_string(bytes.size()));
  if (body < actual)
    fail("byte " + std::to_string(body + header_size + trailer_size) + ": " +
         std::to_string(actual - body) + " bytes of trailing data after the checksum");
  const std::size_t crc_at = bytes.size() - trailer_size;
  const std::uint32_t stored = read_u32_at(bytes, crc_at);
  const std::uint32_t computed = crc32(bytes.substr(0, crc_at));
  if (stored != computed) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "byte %zu: checksum: CRC-32 is %08x, the data gives %08x: the file is corrupted",
                  crc_at, static_cast<unsigned>(stored), static_cast<unsigned>(computed));
    fail(text);
  }
  reader in(bytes.substr(header_size, static_cast<std::size_t>(body)), name, header_size);
  common_part common = read_common(in);
  std::unique_ptr<bsp_impl> impl = row->load(in, std::move(common));
  if (in.remaining()) in.fail("end", std::to_string(in.remaining()) + " bytes after the last node");
  bsp tree(std::move(impl));
  // Only the canonical form is accepted: the bytes this tree would save. A file with the same
  // content spelled otherwise (points numbered in another order, a non-reduced rational, ...)
  // passes every check above but would save back differently; it was not written by exbsp, or
  // was altered and checksummed again.
  const std::string again = tree.serialize();
  if (again != bytes) {
    std::size_t at = 0;
    while (at < again.size() && at < bytes.size() && again[at] == bytes[at]) ++at;
    fail("byte " + std::to_string(at) +
         ": not in the canonical form exbsp writes (saving the tree it holds gives other bytes "
         "from here on): the file was not written by exbsp, or was altered and checksummed again");
  }
  return tree;
}

void bsp::save(const std::string& path) const { write_file_atomically(path, serialize()); }

bsp bsp::load(const std::string& path) { return deserialize(read_input_file(path), path); }

bool bsp::is_saved_tree(const std::string& path) {
  constexpr std::string_view extension = ".exbsp";
  if (path.size() >= extension.size()) {
    std::string tail = path.substr(path.size() - extension.size());
    std::transform(tail.begin(), tail.end(), tail.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (tail == extension) return true;
  }
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;  // never opens a FIFO or device
  std::ifstream in(path, std::ios::binary);
  char head[tree_file::magic_size] = {};
  return in.read(head, sizeof head) && std::memcmp(head, tree_file::magic, sizeof head) == 0;
}

}  // namespace exbsp
