// SPDX-License-Identifier: LGPL-3.0-or-later
// bench_inexact: which invariants the inexact kernels (double, Epick) break, per generator of
// the property tests (tests/support/generators.h) and on 40-triangle CAD subsets. A
// measurement, not a test: every case is built with a heuristic and seed drawn by RapidCheck
// (fragment limit 200000), checked exactly by the tests' tree checker, and counted.
//
// Output: one line per (kernel, generator) on stdout,
//   EXBSP-INEXACT kernel=double generator=near_coplanar cases=100 cases_with_splits=.. order=3/5
//   ...
// where invariant=A/B means A cases broke the invariant, with B broken items over those cases;
// with --out FILE also one JSON object per line. RapidCheck's RC_PARAMS sets the seed and the
// number of cases (default here: seed=20261121 max_success=100).
#include <rapidcheck.h>

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <exbsp/core/errors.h>
#include "support/generators.h"

namespace {

using namespace exbsp_test;

/// Per (kernel, generator): cases, cases with splits, and per invariant the number of cases
/// that broke it and the number of broken items.
struct inexact_record {
  std::size_t cases = 0, cases_with_splits = 0;
  std::map<std::string, std::pair<std::size_t, std::size_t>> broken;
};

template <class K>
void record_case(const soup_case& c, const std::string& h, std::uint64_t seed,
                 inexact_record& rec) {
  const exbsp::triangle_soup soup = c.soup();
  exbsp::build_options o;
  o.heuristic = h;
  o.seed = seed;
  o.max_fragments = 200000;
  ++rec.cases;
  try {
    const exbsp::bsp_tree<K> t(soup, o);
    if (t.stats().splits) ++rec.cases_with_splits;
    check_options co;
    co.seed = seed;
    co.max_rays = 40;
    co.viewpoints = 3;
    co.heuristic = h;
    const check_report r = check_tree(t, soup, co);
    for (const auto& [name, count] : r.broken) {
      ++rec.broken[name].first;
      rec.broken[name].second += count;
    }
  } catch (const exbsp::error&) {
    ++rec.broken[std::string("exbsp_error")].first;  // e.g. the fragment limit
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Which invariants the inexact kernels break, per test generator (see the top of the source)"};
  std::string out_path;
  app.add_option("--out", out_path,
                 "also write one JSON object per (kernel, generator) to this file");
  CLI11_PARSE(app, argc, argv);
  ::setenv("RC_PARAMS", "seed=20261121 max_success=100", 0);

  struct named_gen {
    std::string name;
    rc::Gen<soup_case> gen;
  };
  std::vector<named_gen> gens{{"random_soup", random_soup()},
                              {"grid_soup", grid_soup()},
                              {"coplanar_stack", coplanar_stack()},
                              {"vertex_on_plane", vertex_on_plane()},
                              {"near_coplanar", near_coplanar()},
                              {"scale_disparity", scale_disparity()},
                              {"slivers", slivers()},
                              {"mesh_like", mesh_like()},
                              {"cyclic_sticks", cyclic_sticks()}};
  const auto files = present_cad_meshes();
  if (!files.empty())
    gens.push_back({"cad_subset_40", cad_subset(files, 40)});
  else
    std::cerr << "bench_inexact: data/meshes/ is missing (run scripts/setup): no CAD subsets\n";
  std::map<std::string, inexact_record> records;  // "kernel generator"
  bool all_ran = true;
  for (const auto& g : gens) {
    all_ran &= rc::check("inexact kernels on " + g.name, [&] {
      const soup_case c = *g.gen;
      const std::string h = *rc::gen::elementOf(exbsp::heuristic_names());
      const auto seed = *rc::gen::arbitrary<std::uint64_t>();
      record_case<exbsp::double_kernel>(c, h, seed, records["double " + g.name]);
      record_case<exbsp::epick_kernel>(c, h, seed, records["epick " + g.name]);
    });
  }
  std::ofstream json_out;
  if (!out_path.empty()) json_out.open(out_path);
  for (const auto& [key, rec] : records) {
    const std::string kernel = key.substr(0, key.find(' ')), gen = key.substr(key.find(' ') + 1);
    std::string line = "EXBSP-INEXACT kernel=" + kernel + " generator=" + gen +
                       " cases=" + std::to_string(rec.cases) +
                       " cases_with_splits=" + std::to_string(rec.cases_with_splits);
    nlohmann::json j = {{"kernel", kernel},
                        {"generator", gen},
                        {"cases", rec.cases},
                        {"cases_with_splits", rec.cases_with_splits},
                        {"broken", nlohmann::json::object()}};
    for (const auto& [inv, n] : rec.broken) {
      line += " " + inv + "=" + std::to_string(n.first) + "/" + std::to_string(n.second);
      j["broken"][inv] = {{"cases", n.first}, {"items", n.second}};
    }
    if (rec.broken.empty()) line += " (nothing broken)";
    std::cout << line << "\n";
    if (json_out) json_out << j.dump() << "\n";
  }
  std::cout
      << "EXBSP-INEXACT format: invariant=<cases that broke it>/<broken items over those cases>\n";
  return all_ran ? 0 : 1;
}
