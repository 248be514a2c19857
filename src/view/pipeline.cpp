// SPDX-License-Identifier: LGPL-3.0-or-later
// The stage list runner (pipeline.h): runs named stages in order and times them.
#include <exbsp/view/pipeline.h>

#include <chrono>
#include <cstdio>

#include <exbsp/core/errors.h>
#include "core/named_table.h"

namespace exbsp::view {

const char* to_string(projection_kind k) {
  static constexpr enum_name<projection_kind> names[] = {
      {projection_kind::perspective, "perspective"},
      {projection_kind::frustum, "frustum"},
      {projection_kind::orthographic, "orthographic"},
      {projection_kind::oblique, "oblique"}};
  return name_of(k, names);
}

void pipeline::add(std::string name, std::function<std::string(frame&)> run) {
  stages_.push_back({std::move(name), std::move(run)});
}

void pipeline::insert_after(const std::string& after, std::string name,
                            std::function<std::string(frame&)> run) {
  for (std::size_t i = 0; i < stages_.size(); ++i)
    if (stages_[i].name == after) {
      stages_.insert(stages_.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                     {std::move(name), std::move(run)});
      return;
    }
  throw usage_error("pipeline::insert_after: no stage named " + after);
}

std::vector<std::string> pipeline::names() const {
  std::vector<std::string> r;
  for (const stage& s : stages_) r.push_back(s.name);
  return r;
}

void pipeline::run(frame& f, std::ostream* log) const {
  for (const stage& s : stages_) {
    if (f.on_stage) f.on_stage(s.name);
    const auto t0 = std::chrono::steady_clock::now();
    const std::string note = s.run(f);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (log) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.4f", seconds);
      *log << "stage " << s.name << ": " << buf << " s";
      if (!note.empty()) *log << " (" << note << ")";
      *log << "\n";
    }
  }
}

}  // namespace exbsp::view
