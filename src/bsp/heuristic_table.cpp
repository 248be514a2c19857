// SPDX-License-Identifier: LGPL-3.0-or-later
// The heuristic table (heuristic_table.h): one row per heuristic.
#include "bsp/heuristic_table.h"

#include <exbsp/core/errors.h>

namespace exbsp {

namespace {

std::vector<heuristic_row>& table() {
  static std::vector<heuristic_row> rows{
      {"naive", "first triangle", {}, detail::heuristic_naive, {}, candidate_set::all},
      {"min-split",
       "fewest straddlers",
       {"threads"},
       detail::heuristic_min_split,
       {},
       candidate_set::all},
      {"sampled",
       "16 seeded candidates, split/balance score",
       {"seed", "sampled_candidates", "sampled_samples", "sampled_split_weight", "threads"},
       detail::heuristic_sampled,
       {},
       candidate_set::all},
      {"random", "seeded", {"seed"}, detail::heuristic_random, {}, candidate_set::all},
  };
  return rows;
}

/// heuristic_names() hands out a reference: it is kept beside the table and grown with it.
std::vector<std::string>& names() {
  static std::vector<std::string> out = [] {
    std::vector<std::string> n;
    for (const heuristic_row& r : table()) n.push_back(r.name);
    return n;
  }();
  return out;
}

}  // namespace

const std::vector<heuristic_row>& heuristic_table() { return table(); }

const std::vector<std::string>& heuristic_names() { return names(); }

const char* default_heuristic() { return "sampled"; }

void add_heuristic(heuristic_row row) {
  if (row.name.empty() || row.name == "custom" || !row.score)
    throw usage_error("add_heuristic: a heuristic needs a name other than 'custom' and a score");
  names();  // made from the table before it grows
  for (const heuristic_row& r : table())
    if (r.name == row.name) throw usage_error("add_heuristic: '" + row.name + "' is taken");
  row.chooser = detail::heuristic_custom;
  names().push_back(row.name);
  table().push_back(std::move(row));
}

namespace detail {

std::pair<heuristic_id, const build_options*> heuristic_for(const build_options& options,
                                                            build_options& scored) {
  const std::string& name = options.heuristic;
  if (name == "custom") {
    if (!options.score)
      throw usage_error("heuristic 'custom' needs a score callback (build_options::score)");
    return {heuristic_custom, &options};
  }
  for (const heuristic_row& r : table())
    if (r.name == name) {
      if (options.score)
        throw usage_error("a score callback is set but the heuristic is '" + name +
                          "': use heuristic 'custom'");
      if (!r.score) return {r.chooser, &options};
      scored = options;
      scored.score = r.score;
      scored.score_candidates = r.candidates;
      return {heuristic_custom, &scored};
    }
  std::string list;
  for (const heuristic_row& r : table()) list += (list.empty() ? "" : ", ") + r.name;
  throw usage_error("unknown heuristic '" + name + "' (expected one of: " + list +
                    ", or custom with a score callback)");
}

}  // namespace detail
}  // namespace exbsp
