// SPDX-License-Identifier: LGPL-3.0-or-later
// Option-value parsing, mesh input and typo suggestions for the command line (cli_parse.h).
#include "app/cli_parse.h"
#include "app/resources.h"

#include <CLI/CLI.hpp>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>
#include <numeric>
#include <sstream>

#include <exbsp/core/errors.h>
#include <exbsp/mesh/mesh_io.h>

namespace exbsp::cli {

namespace {

/// Parses `count` finite doubles separated by `sep` that make up all of `text`.
bool parse_numbers(const std::string& text, char sep, double* out, int count) {
  const char* p = text.data();
  const char* end = p + text.size();
  for (int k = 0; k < count; ++k) {
    const auto r = std::from_chars(p, end, out[k]);
    if (r.ec != std::errc() || !std::isfinite(out[k])) return false;
    p = r.ptr;
    if (k + 1 < count) {
      if (p == end || *p != sep) return false;
      ++p;
    }
  }
  return p == end;
}

}  // namespace

vec3d parse_triple(const std::string& text, const std::string& option) {
  vec3d v{};
  if (!parse_numbers(text, ',', v.data(), 3))
    throw usage_error(option + " expects three finite numbers X,Y,Z separated by commas, got '" +
                      text + "'");
  return v;
}

section_plane parse_plane(const std::string& text, const std::string& option) {
  section_plane p{};
  if (!parse_numbers(text, ',', p.data(), 4))
    throw usage_error(option +
                      " expects four finite numbers A,B,C,D (the plane A*x+B*y+C*z+D = 0), got '" +
                      text + "'");
  check_section_plane(p, option);
  return p;
}

std::vector<std::array<double, 2>> parse_drag_path(const std::string& text,
                                                   const std::string& option) {
  std::vector<std::array<double, 2>> path;
  std::size_t start = 0;
  while (true) {
    const std::size_t colon = text.find(':', start);
    const std::string point =
        text.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
    std::array<double, 2> pt{};
    if (!parse_numbers(point, ',', pt.data(), 2))
      throw usage_error(option + " expects screen points X0,Y0:X1,Y1:... (finite numbers), got '" +
                        text + "'");
    path.push_back(pt);
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  return path;
}

std::array<int, 2> parse_size(const std::string& text, const std::string& option) {
  std::array<int, 2> size{};
  const std::size_t x = text.find('x');
  bool ok = x != std::string::npos;
  for (int k = 0; ok && k < 2; ++k) {
    const char* b = text.data() + (k == 0 ? 0 : x + 1);
    const char* e = k == 0 ? text.data() + x : text.data() + text.size();
    const auto r = std::from_chars(b, e, size[k]);
    ok = r.ec == std::errc() && r.ptr == e && b != e && size[k] >= 1 && size[k] <= 16384;
  }
  if (!ok)
    throw usage_error(option +
                      " expects WIDTHxHEIGHT in pixels, each 1..16384 (e.g. 800x600), got '" +
                      text + "'");
  return size;
}

triangle_soup read_mesh_input(const std::string& path, const std::string& format, std::istream& in,
                              std::uint64_t max_stdin_bytes) {
  mesh_format f{};
  if (!format.empty()) {
    if (format == "off")
      f = mesh_format::off;
    else if (format == "obj")
      f = mesh_format::obj;
    else if (format == "ply")
      f = mesh_format::ply;
    else if (format == "stl")
      f = mesh_format::stl;
    else
      throw usage_error("--format: expected off, obj, ply or stl, got '" + format + "'");
  }
  if (path == "-") {
    if (format.empty())
      throw usage_error("reading a mesh from standard input ('-') needs --format off|obj|ply|stl");
    if (&in == &std::cin) {
      struct stat st {};
      if (::fstat(STDIN_FILENO, &st) == 0 && (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) &&
          !::isatty(STDIN_FILENO))
        throw input_error("<stdin>", 0,
                          std::string("cannot read ") +
                              (S_ISCHR(st.st_mode) ? "a character device" : "a block device") +
                              " (standard input must be a file, a pipe or a terminal)");
      if (::fstat(STDIN_FILENO, &st) == 0 && S_ISDIR(st.st_mode))
        throw input_error("<stdin>", 0, "cannot read a directory");
    }
    std::uint64_t limit = max_stdin_bytes;
    if (limit == 0) limit = available_memory_bytes() / 4;
    if (limit == 0) limit = std::uint64_t{1} << 34;  // 16 GiB when the memory is unknown
    std::string data;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
      data.append(buffer, static_cast<std::size_t>(in.gcount()));
      if (data.size() > limit)
        throw limit_error("<stdin>: standard input is larger than " + std::to_string(limit) +
                          " bytes (a quarter of the available memory); give the mesh as a file");
    }
    if (in.bad()) throw input_error("<stdin>", 0, "cannot read standard input");
    return read_mesh_data(data, f, "<stdin>");
  }
  if (format.empty()) return read_mesh(path);
  return read_mesh_data(read_input_file(path), f, path);
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string closest(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const std::string& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

namespace {

std::vector<std::string> option_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app.get_options()) {
    for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
    for (const std::string& s : o->get_snames()) names.push_back("-" + s);
  }
  return names;
}

/// An option spelling: "--word..." or "-x..." with a letter (not "-", not a negative number).
bool looks_like_option(const std::string& arg) {
  if (arg.size() >= 3 && arg[0] == '-' && arg[1] == '-') return true;
  return arg.size() >= 2 && arg[0] == '-' && std::isalpha(static_cast<unsigned char>(arg[1]));
}

std::string unknown_option(const CLI::App& app, const std::string& arg, const std::string& where) {
  const std::string name = arg[1] == '-' ? arg.substr(0, arg.find('=')) : arg.substr(0, 2);
  // CLI11 also accepts "-abc" as grouped flags and "-ovalue"; a known first letter is left to it.
  if (app.get_option_no_throw(name) != nullptr) return "";
  std::string message = "unknown option '" + name + "'" + where;
  const std::string suggestion = closest(name, option_names(app));
  if (!suggestion.empty()) message += "; did you mean '" + suggestion + "'?";
  return message;
}

}  // namespace

std::string misspelling(const CLI::App& app, const std::vector<std::string>& args) {
  const CLI::App* command = nullptr;
  for (const std::string& arg : args) {
    if (arg == "--") break;
    if (command == nullptr && !looks_like_option(arg)) {
      const auto subs = app.get_subcommands([](const CLI::App*) { return true; });
      for (const CLI::App* s : subs)
        if (s->get_name() == arg) command = s;
      if (command) continue;
      std::vector<std::string> names;
      for (const CLI::App* s : subs) names.push_back(s->get_name());
      std::string message = "unknown command '" + arg + "'";
      const std::string suggestion = closest(arg, names);
      if (!suggestion.empty()) message += "; did you mean '" + suggestion + "'?";
      return message;
    }
    if (!looks_like_option(arg)) continue;
    const std::string m = command
                              ? unknown_option(*command, arg, " for '" + command->get_name() + "'")
                              : unknown_option(app, arg, "");
    if (!m.empty()) return m;
  }
  return "";
}

}  // namespace exbsp::cli
