// SPDX-License-Identifier: LGPL-3.0-or-later
// The heuristic table (heuristic_table.h): one row per heuristic.
#include "bsp/heuristic_table.h"

#include <exbsp/core/errors.h>
#include "core/named_table.h"

namespace exbsp {

namespace {

named_table<heuristic_row>& table() {
  static named_table<heuristic_row> rows({
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
  });
  return rows;
}

}  // namespace

const std::vector<heuristic_row>& heuristic_table() { return table().rows(); }

const std::vector<std::string>& heuristic_names() { return table().names(); }

const char* default_heuristic() { return "sampled"; }

void add_heuristic(heuristic_row row) {
  if (row.name.empty() || row.name == "custom" || !row.score)
    throw usage_error("add_heuristic: a heuristic needs a name other than 'custom' and a score");
  if (table().find(row.name)) throw usage_error("add_heuristic: '" + row.name + "' is taken");
  row.chooser = detail::heuristic_custom;
  table().add(std::move(row));
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
  if (const heuristic_row* r = table().find(name)) {
    if (options.score)
      throw usage_error("a score callback is set but the heuristic is '" + name +
                        "': use heuristic 'custom'");
    if (!r->score) return {r->chooser, &options};
    scored = options;
    scored.score = r->score;
    scored.score_candidates = r->candidates;
    return {heuristic_custom, &scored};
  }
  std::string list;
  for (const heuristic_row& r : table().rows()) list += (list.empty() ? "" : ", ") + r.name;
  throw usage_error("unknown heuristic '" + name + "' (expected one of: " + list +
                    ", or custom with a score callback)");
}

}  // namespace detail
}  // namespace exbsp
