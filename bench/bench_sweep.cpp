// SPDX-License-Identifier: LGPL-3.0-or-later
// bench_sweep: builds BSP trees for inputs x kernels x heuristics and writes one JSON line per
// (input, heuristic, kernel) with build time, heap memory, tree statistics and, optionally,
// the exact defect counts of defects.h.
//
// Measurement protocol, per input and heuristic (kernels interleaved, side by side):
//   1. one COUNTED build per kernel (also the warm-up): heap accounting on (alloc_counter.h),
//      tree statistics, then the defect checks on that tree (untimed);
//   2. `repeats` rounds, each building once with every kernel in turn, accounting off;
//      the reported time is the median of these rounds (wall clock of the tree constructor,
//      steady_clock), with the process CPU time of the same builds alongside.
// A build that runs longer than --time-cap seconds is stopped through the progress callback
// (status "timeout"), one that needs more than --max-fragments fragments by limit_error
// (status "limit": a runaway inexact build); --limit NAME=N skips a kernel or heuristic on inputs
// of more than N triangles (status "skipped").
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <exbsp/core/errors.h>
#include "alloc_counter.h"
#include "bsp/bsp_tree.h"
#include "bsp/geometry_cgal.h"
#include "bsp/geometry_exact.h"
#include "bsp/kernel_double.h"
#include "bsp/kernel_epeck.h"
#include "bsp/kernel_epick.h"
#include "bsp/kernel_gmpq.h"
#include "defects.h"
#include "generators.h"

namespace exbsp::bench {
namespace {

using json = nlohmann::json;

struct timeout_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct sweep_options {
  std::vector<std::string> kernels, heuristics;
  std::size_t repeats = 3;
  double time_cap = 120;
  std::map<std::string, std::size_t> limits;  ///< kernel or heuristic -> max input triangles
  std::map<std::string, std::size_t>
      repeats_for;                             ///< kernel or heuristic -> timed rounds (overrides)
  std::map<std::string, double> time_cap_for;  ///< kernel or heuristic -> time cap (overrides)
  bool defects = false;
  std::vector<unsigned> sampled{16, 512,
                                8};  ///< sampled heuristic: candidates, samples, split weight
  std::size_t control_max_triangles = 20000;  ///< defect checks of exact kernels only up to here
  bool skip_counted = false;  ///< no counted build (profiling): stats from the timed builds
  defect_options defect;
  std::uint64_t build_seed = 0;
  unsigned threads = 0;
  std::size_t max_fragments =
      4000000;  ///< a runaway build stops here (status "limit"), not in the OOM killer
  std::string label;
};

double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

/// State of one (input, heuristic, kernel) run across the protocol's phases.
struct run_state {
  std::string kernel;
  std::string status = "ok";  ///< ok, timeout, skipped, error
  std::string reason;
  json result = json::object();
  std::vector<double> wall, cpu;
};

/// The value for a (kernel, heuristic) run: an override for the kernel, else for the
/// heuristic, else the default.
template <class T>
T value_for(const std::map<std::string, T>& overrides, const std::string& kernel,
            const std::string& heuristic, T fallback) {
  if (const auto it = overrides.find(kernel); it != overrides.end()) return it->second;
  if (const auto it = overrides.find(heuristic); it != overrides.end()) return it->second;
  return fallback;
}

std::string load_average() {
  std::ifstream f("/proc/loadavg");
  std::string one;
  f >> one;
  return one;
}

build_options make_options(const std::string& kernel, const std::string& heuristic,
                           const sweep_options& o) {
  build_options b;
  b.heuristic = heuristic;
  b.seed = o.build_seed;
  b.threads = o.threads;
  b.max_fragments = o.max_fragments;
  b.sampled_candidates = o.sampled[0];
  b.sampled_samples = o.sampled[1];
  b.sampled_split_weight = o.sampled[2];
  const double cap = value_for(o.time_cap_for, kernel, heuristic, o.time_cap);
  b.progress = [cap](const build_progress& p) {
    if (cap > 0 && p.seconds > cap)
      throw timeout_error("time cap of " + std::to_string(cap) + " s exceeded");
  };
  return b;
}

json defects_json(const defect_report& d) {
  return {{"fragments", d.fragments},
          {"non_finite", d.non_finite},
          {"off_plane", d.off_plane},
          {"split_sources", d.split_sources},
          {"not_tiling", d.not_tiling},
          {"misclassified", d.misclassified},
          {"ancestor_tests", d.ancestor_tests},
          {"eyes", d.eyes},
          {"order_samples", d.order_samples},
          {"occluding_pairs", d.occluding_pairs},
          {"order_errors", d.order_errors},
          {"seconds", d.seconds},
          {"seconds_parts",
           {d.seconds_plane, d.seconds_tiling, d.seconds_classification, d.seconds_order}}};
}

/// The CGAL kernel behind a geometry (void for exbsp's own exact geometry).
template <class G>
struct cgal_kernel_of {
  using type = void;
};
template <class K>
struct cgal_kernel_of<cgal_geometry<K>> {
  using type = K;
};
/// Defects are checked for the CGAL kernels but gmpq (too slow; identical to epeck); the exact
/// kernel's tree is identical to epeck's (tests/test_exact_kernel.cpp), so it has epeck's zeros.
template <class G>
constexpr bool checkable = !std::is_void_v<typename cgal_kernel_of<G>::type> &&
                           !std::is_same_v<typename cgal_kernel_of<G>::type, gmpq_kernel>;

/// Phase 1: the counted build, statistics and defects.
template <class G>
void counted_build(const triangle_soup& soup, const std::string& heuristic, const sweep_options& o,
                   run_state& st) {
  const build_options options = make_options(st.kernel, heuristic, o);
  std::optional<basic_bsp_tree<G>> tree;
  alloc_counter::start();
  try {
    tree.emplace(soup, options);
  } catch (const timeout_error& e) {
    alloc_counter::stop();
    st.status = "timeout";
    st.reason = e.what();
    return;
  } catch (const limit_error& e) {
    alloc_counter::stop();
    st.status = "limit";
    st.reason = e.what();
    return;
  }
  alloc_counter::stop();
  const build_stats& s = tree->stats();
  json& r = st.result;
  for_each_stat_count(s, [&r](const char* name, std::size_t value) { r[name] = value; });
  r["counted_build_seconds"] = s.build_seconds;
  r["peak_heap_bytes"] = alloc_counter::peak();
  r["tree_heap_bytes"] = alloc_counter::live();
  r["allocations"] = alloc_counter::allocations();
  r["peak_heap_bytes_per_fragment"] =
      s.fragments ? static_cast<double>(alloc_counter::peak()) / static_cast<double>(s.fragments)
                  : 0.0;
  if constexpr (checkable<G>) {
    const bool control = G::exact;
    if (o.defects && (!control || s.input_triangles <= o.control_max_triangles))
      r["defects"] = defects_json(check_defects(*tree, soup, o.defect));
  }
}

/// Phase 2: one timed build, accounting off.
template <class G>
void timed_build(const triangle_soup& soup, const std::string& heuristic, const sweep_options& o,
                 run_state& st) {
  const build_options options = make_options(st.kernel, heuristic, o);
  std::optional<basic_bsp_tree<G>> tree;
  const double cpu0 = process_cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  try {
    tree.emplace(soup, options);
  } catch (const timeout_error& e) {
    st.status = "timeout";
    st.reason = e.what();
    return;
  } catch (const limit_error& e) {
    st.status = "limit";
    st.reason = e.what();
    return;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = process_cpu_seconds() - cpu0;
  if (!st.result.contains("fragments")) {
    const build_stats& s = tree->stats();
    for_each_stat_count(s, [&st](const char* name, std::size_t value) { st.result[name] = value; });
  }
  st.wall.push_back(wall);
  st.cpu.push_back(cpu);
}

template <template <class> class Fn>
struct dispatch {
  template <class... Args>
  static void run(const std::string& kernel, Args&&... args) {
    if (kernel == "exact") return Fn<exact_geometry>::run(std::forward<Args>(args)...);
    if (kernel == "double")
      return Fn<cgal_geometry<double_kernel>>::run(std::forward<Args>(args)...);
    if (kernel == "epick") return Fn<cgal_geometry<epick_kernel>>::run(std::forward<Args>(args)...);
    if (kernel == "epeck") return Fn<cgal_geometry<epeck_kernel>>::run(std::forward<Args>(args)...);
    if (kernel == "gmpq") return Fn<cgal_geometry<gmpq_kernel>>::run(std::forward<Args>(args)...);
    throw std::invalid_argument("unknown kernel " + kernel);
  }
};
template <class K>
struct counted_fn {
  template <class... Args>
  static void run(Args&&... args) {
    counted_build<K>(std::forward<Args>(args)...);
  }
};
template <class K>
struct timed_fn {
  template <class... Args>
  static void run(Args&&... args) {
    timed_build<K>(std::forward<Args>(args)...);
  }
};

void sweep_input(const input_spec& in, const sweep_options& o, std::ostream& out) {
  const auto load0 = std::chrono::steady_clock::now();
  const triangle_soup soup = load_input(in);
  const double load_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - load0).count();
  const std::size_t n = soup.triangles.size();
  for (const std::string& heuristic : o.heuristics) {
    std::vector<run_state> runs;
    for (const std::string& kernel : o.kernels) {
      run_state st;
      st.kernel = kernel;
      for (const std::string& name : {kernel, heuristic}) {
        const auto it = o.limits.find(name);
        if (it != o.limits.end() && n > it->second) {
          st.status = "skipped";
          st.reason =
              name + " only on inputs of at most " + std::to_string(it->second) + " triangles";
        }
      }
      runs.push_back(std::move(st));
    }
    const auto guarded = [&](run_state& st, auto&& body) {
      if (st.status != "ok") return;
      try {
        body();
      } catch (const std::exception& e) {
        alloc_counter::stop();
        st.status = "error";
        st.reason = e.what();
      }
    };
    if (!o.skip_counted)
      for (run_state& st : runs)
        guarded(st, [&] { dispatch<counted_fn>::run(st.kernel, soup, heuristic, o, st); });
    std::size_t rounds = 0;
    for (const run_state& st : runs)
      rounds = std::max(rounds, value_for(o.repeats_for, st.kernel, heuristic, o.repeats));
    for (std::size_t rep = 0; rep < rounds; ++rep)
      for (run_state& st : runs)
        if (rep < value_for(o.repeats_for, st.kernel, heuristic, o.repeats))
          guarded(st, [&] { dispatch<timed_fn>::run(st.kernel, soup, heuristic, o, st); });
    for (run_state& st : runs) {
      json line = {{"label", o.label},
                   {"input", in.name},
                   {"input_kind", in.kind},
                   {"input_size", in.size},
                   {"input_seed", in.seed},
                   {"triangles", n},
                   {"kernel", st.kernel},
                   {"heuristic", heuristic},
                   {"seed", o.build_seed},
                   {"threads", o.threads},
                   {"sampled", o.sampled},
                   {"repeats", value_for(o.repeats_for, st.kernel, heuristic, o.repeats)},
                   {"time_cap", value_for(o.time_cap_for, st.kernel, heuristic, o.time_cap)},
                   {"status", st.status},
                   {"load_seconds", load_seconds},
                   {"load_average", load_average()}};
      if (!st.reason.empty()) line["reason"] = st.reason;
      for (auto& [k, v] : st.result.items()) line[k] = v;
      if (!st.wall.empty()) {
        line["build_seconds"] = st.wall;
        line["cpu_seconds"] = st.cpu;
        line["build_seconds_median"] = median(st.wall);
        line["cpu_seconds_median"] = median(st.cpu);
      }
      out << line.dump() << "\n";
      out.flush();
      std::cerr << "[" << o.label << "] " << in.name << " " << heuristic << " " << st.kernel << ": "
                << st.status;
      if (line.contains("fragments")) std::cerr << ", " << line["fragments"] << " fragments";
      if (line.contains("build_seconds_median")) std::cerr << ", " << median(st.wall) << " s";
      if (line.contains("defects")) {
        const json& d = line["defects"];
        std::cerr << ", defects off_plane " << d["off_plane"] << " not_tiling " << d["not_tiling"]
                  << " misclassified " << d["misclassified"] << " order " << d["order_errors"]
                  << "/" << d["occluding_pairs"];
      }
      std::cerr << "\n";
    }
  }
}

std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::size_t at = 0;
  while (at <= s.size()) {
    const auto comma = s.find(',', at);
    const std::string item =
        s.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    if (!item.empty()) out.push_back(item);
    if (comma == std::string::npos) break;
    at = comma + 1;
  }
  return out;
}

}  // namespace
}  // namespace exbsp::bench

int main(int argc, char** argv) {
  using namespace exbsp::bench;
  CLI::App app{"bench_sweep: BSP builds over inputs x kernels x heuristics, one JSON line per run"};
  std::vector<std::string> meshes, inputs, limits;
  std::vector<std::size_t> soups, sticks;
  std::uint64_t input_seed = 0;
  std::string kernels = "double,epick,epeck,gmpq", heuristics = "sampled", out_path;
  sweep_options o;
  app.add_option("--mesh", meshes, "mesh file (repeatable)");
  app.add_option("--soup", soups, "random soup of N triangles (repeatable)");
  app.add_option("--sticks", sticks, "grid of K + K sticks, 4K triangles (repeatable)");
  app.add_option("--input", inputs, "input spec mesh:PATH, soup:N[:SEED], sticks:K (repeatable)");
  app.add_option("--input-seed", input_seed, "seed of the random soups");
  app.add_option("--kernels", kernels, "comma-separated: double,epick,epeck,gmpq");
  app.add_option("--heuristics", heuristics, "comma-separated: naive,min-split,sampled,random");
  app.add_option("--repeats", o.repeats, "timed rounds after the counted build (median reported)");
  app.add_option("--time-cap", o.time_cap, "seconds per build before it is stopped (0: none)");
  app.add_option("--limit", limits, "NAME=N: run kernel or heuristic NAME only up to N triangles");
  std::vector<std::string> repeats_for, caps_for;
  app.add_option("--repeats-for", repeats_for, "NAME=N: timed rounds for kernel or heuristic NAME");
  app.add_option("--time-cap-for", caps_for, "NAME=S: time cap for kernel or heuristic NAME");
  app.add_flag("--defects", o.defects, "exact defect checks on the counted build (not gmpq)");
  app.add_option("--control-max-triangles", o.control_max_triangles,
                 "defect checks of the exact control kernel (epeck) only up to N input triangles");
  app.add_flag("--skip-counted", o.skip_counted,
               "no counted build: only the timed ones (for profiling)");
  app.add_option("--order-samples", o.defect.samples,
                 "sample rays per eye for order errors (fragment centroids of a stride; 0: all)");
  app.add_option("--exact-order-samples", o.defect.exact_samples,
                 "the same for the exact control kernel epeck (0: all)");
  app.add_option("--eyes", o.defect.eyes, "eyes for order errors (at most 8; 0: no order check)");
  app.add_option("--seed", o.build_seed, "heuristic seed");
  app.add_option("--threads", o.threads, "build threads (0: all cores)");
  app.add_option("--sampled", o.sampled,
                 "sampled heuristic: CANDIDATES SAMPLES SPLIT_WEIGHT (default 16 512 8)")
      ->expected(3)
      ->delimiter(',');
  app.add_option("--max-fragments", o.max_fragments,
                 "stop a build beyond N fragments (status limit; 0: none)");
  app.add_option("--label", o.label, "label copied into every line");
  app.add_option("--out", out_path, "append JSON lines here (default: stdout)");
  CLI11_PARSE(app, argc, argv);
  // GMP's memory functions are replaced only when something is counted (not under callgrind).
  if (!o.skip_counted) alloc_counter::install();

  try {
    o.kernels = split_list(kernels);
    o.heuristics = split_list(heuristics);
    o.defect.order = o.defect.eyes > 0;
    const auto name_value = [](const std::string& l) {
      const auto eq = l.find('=');
      if (eq == std::string::npos) throw std::invalid_argument("expected NAME=VALUE: " + l);
      return std::pair<std::string, std::string>(l.substr(0, eq), l.substr(eq + 1));
    };
    for (const std::string& l : limits) {
      const auto [name, value] = name_value(l);
      o.limits[name] = std::stoull(value);
    }
    for (const std::string& l : repeats_for) {
      const auto [name, value] = name_value(l);
      o.repeats_for[name] = std::stoull(value);
    }
    for (const std::string& l : caps_for) {
      const auto [name, value] = name_value(l);
      o.time_cap_for[name] = std::stod(value);
    }
    std::vector<input_spec> specs;
    for (const auto& m : meshes) specs.push_back(parse_input_spec("mesh:" + m));
    for (auto n : soups)
      specs.push_back(
          parse_input_spec("soup:" + std::to_string(n) + ":" + std::to_string(input_seed)));
    for (auto k : sticks) specs.push_back(parse_input_spec("sticks:" + std::to_string(k)));
    for (const auto& s : inputs) specs.push_back(parse_input_spec(s));
    std::ofstream file;
    if (!out_path.empty()) {
      file.open(out_path, std::ios::app);
      if (!file) throw std::runtime_error("cannot open " + out_path);
    }
    std::ostream& out = out_path.empty() ? std::cout : file;
    for (const input_spec& in : specs) sweep_input(in, o, out);
  } catch (const std::exception& e) {
    std::cerr << "bench_sweep: error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
