// SPDX-License-Identifier: LGPL-3.0-or-later
// The splitter heuristics, one row each (issue 26): names, --help, the options each reads, and
// how the tree runs it. The four built-in choosers have their own code paths in the tree
// (choose_splitter in bsp_tree_impl.h: min-split's bound and the sampled heuristic's batched
// static filters are what make them fast, and they need the kernel's types); any other
// heuristic is a score over the exact side counts of each candidate (candidate_score_input),
// run by the custom heuristic's machinery. So adding a heuristic is one file with its score
// and one row (or add_heuristic). tests/test_tables.cpp walks this table and adds one.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include "bsp/heuristics.h"

namespace exbsp {

struct heuristic_row {
  std::string name;                     ///< --heuristic NAME, build_stats::heuristic
  std::string description;              ///< one phrase for --help
  std::vector<std::string> parameters;  ///< the build_options fields it reads
  /// The tree's chooser: a built-in one, or heuristic_custom for a row with a score.
  detail::heuristic_id chooser = detail::heuristic_custom;
  /// A row defined by a score: the lowest score among `candidates` wins, ties to the earliest
  /// (build_options::score's contract: thread-safe, depending only on its input).
  std::function<double(const candidate_score_input&)> score;
  candidate_set candidates = candidate_set::all;
};

/// Every heuristic, in the order of heuristic_names(): naive, min-split, sampled, random, then
/// any added with add_heuristic. ("custom", with build_options::score, is not a row: its score
/// comes with the options.)
const std::vector<heuristic_row>& heuristic_table();

/// Adds a heuristic defined by a score (usage_error for a name that is taken, "custom", or a
/// row without a score). Call it before any build runs on another thread: the table is not
/// locked.
void add_heuristic(heuristic_row row);

namespace detail {

/// The chooser `options` ask for, and the options it runs with: `options` itself, or for a
/// row with a score, `scored` (a copy of options with that score and candidate set). Throws
/// usage_error for an unknown name, for "custom" without options.score and for options.score
/// with another heuristic.
std::pair<heuristic_id, const build_options*> heuristic_for(const build_options& options,
                                                            build_options& scored);

}  // namespace detail
}  // namespace exbsp
