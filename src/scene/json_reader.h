// SPDX-License-Identifier: LGPL-3.0-or-later
// JSON reading with JSON-pointer error messages, for the view's types (numbers, triples,
// colours): the scene parser, `exbsp clip` (clip_input.cpp) and the effects' parameter readers
// (effect_parameters.h) share it. JSON stops here, at scene: view takes typed settings only.
//
// Notation: `key` is always the JSON pointer of the value being read ("/meshes/0/color/1");
// every failure is a scene_error naming the file and that key.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>
#include <string>

#include <exbsp/core/errors.h>
#include <exbsp/view/image.h>
#include <exbsp/view/matrix.h>

namespace exbsp::scene {

using view::rgb8;
using view::vector3;

using nlohmann::json;

/// A double with 17 significant digits (round-trips).
inline std::string number_text(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

/// JSON reading with JSON-pointer error messages.
class reader {
 public:
  /// `strict`: unknown keys (warn_unknown) are errors, not warnings.
  reader(std::string file, std::ostream* warnings, bool strict = false)
      : file_(std::move(file)), warnings_(warnings), strict_(strict) {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw scene_error(file_, key, what);
  }

  void warn(const std::string& key, const std::string& what) const {
    if (warnings_) *warnings_ << "exbsp: warning: " << file_ << ": " << key << ": " << what << "\n";
  }

  const json& object(const json& v, const std::string& key) const {
    if (!v.is_object()) fail(key, std::string("must be an object (got ") + v.type_name() + ")");
    return v;
  }

  /// The member `name` of object `obj` at pointer `key`; fails when absent or null.
  const json& require(const json& obj, const std::string& key, const char* name) const {
    auto it = obj.find(name);
    if (it == obj.end() || it->is_null()) fail(key + "/" + name, "missing key");
    return *it;
  }

  /// Pointer to the member or nullptr when absent or null.
  const json* optional(const json& obj, const char* name) const {
    auto it = obj.find(name);
    if (it == obj.end() || it->is_null()) return nullptr;
    return &*it;
  }

  /// Calls visit(entry, entry_key) for each entry of the array member `name` of `obj` (at
  /// pointer `key`, "" for the document), in order; nothing when it is absent or null; fails
  /// when it is not an array.
  template <class Visit>
  void for_each_entry(const json& obj, const std::string& key, const char* name,
                      Visit&& visit) const {
    const json* a = optional(obj, name);
    if (!a) return;
    const std::string at = key + "/" + name;
    if (!a->is_array()) fail(at, std::string("must be an array (got ") + a->type_name() + ")");
    for (std::size_t i = 0; i < a->size(); ++i) visit((*a)[i], at + "/" + std::to_string(i));
  }

  /// Warns about (strict: fails on) each member of `obj` whose name is not in `known`, and
  /// says which names were expected there (a misspelt key is then easy to spot).
  void warn_unknown(const json& obj, const std::string& key,
                    std::initializer_list<const char*> known) const {
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      const bool ok =
          std::any_of(known.begin(), known.end(), [&](const char* k) { return it.key() == k; });
      if (ok) continue;
      std::string expected;
      for (const char* k : known) expected += (expected.empty() ? "" : ", ") + std::string(k);
      if (strict_) fail(key + "/" + it.key(), "unknown key (expected one of: " + expected + ")");
      warn(key + "/" + it.key(), "unknown key ignored (expected one of: " + expected + ")");
    }
  }

  double number(const json& v, const std::string& key) const {
    if (!v.is_number()) fail(key, std::string("must be a number (got ") + v.type_name() + ")");
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(key, "must be a finite number");
    return d;
  }

  long long integer(const json& v, const std::string& key) const {
    if (v.is_number_integer()) {
      if (v.is_number_unsigned() && v.get<unsigned long long>() > 1ull << 62)
        fail(key, "integer out of range");
      return v.get<long long>();
    }
    const double d = number(v, key);
    if (d != std::floor(d) || std::fabs(d) > 4.0e18)
      fail(key, "must be an integer (got " + number_text(d) + ")");
    return static_cast<long long>(d);
  }

  vector3 triple(const json& v, const std::string& key) const {
    if (!v.is_array() || v.size() != 3) fail(key, "must be an array of 3 numbers");
    return {number(v[0], key + "/0"), number(v[1], key + "/1"), number(v[2], key + "/2")};
  }

  rgb8 color(const json& v, const std::string& key) const {
    if (!v.is_array() || v.size() != 3) fail(key, "must be an array of 3 integers in 0..255");
    std::uint8_t c[3];
    for (int k = 0; k < 3; ++k) {
      const std::string ck = key + "/" + std::to_string(k);
      if (!v[k].is_number())
        fail(ck, std::string("must be an integer in 0..255 (got ") + v[k].type_name() + ")");
      const double d = v[k].get<double>();
      if (!(d >= 0 && d <= 255) || d != std::floor(d))
        fail(ck, "colour component must be an integer in 0..255 (got " + number_text(d) + ")");
      c[k] = static_cast<std::uint8_t>(d);
    }
    return {c[0], c[1], c[2]};
  }

  /// Fails naming KEY/PARAM for a member of `params` not in `known` (the parameters of `name`).
  void reject_unknown(const json& params, const std::string& key, const std::string& name,
                      std::initializer_list<const char*> known) const {
    std::string list;
    for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
    for (auto it = params.begin(); it != params.end(); ++it) {
      const bool ok =
          std::any_of(known.begin(), known.end(), [&](const char* k) { return it.key() == k; });
      if (!ok)
        fail(key + "/" + it.key(), "unknown parameter (" + name + " takes " +
                                       (list.empty() ? std::string("none") : list) + ")");
    }
  }

  /// A finite number > 0 (or >= 0 when `zero_ok`).
  double positive(const json& v, const std::string& key, bool zero_ok = false) const {
    const double d = number(v, key);
    if (zero_ok ? !(d >= 0) : !(d > 0))
      fail(key,
           std::string("must be ") + (zero_ok ? ">= 0" : "> 0") + " (got " + number_text(d) + ")");
    return d;
  }

  const std::string& file() const { return file_; }
  std::ostream* warnings() const { return warnings_; }
  bool strict() const { return strict_; }

 private:
  std::string file_;
  std::ostream* warnings_;
  bool strict_;
};

}  // namespace exbsp::scene
