// SPDX-License-Identifier: LGPL-3.0-or-later
// exbsp::distributed_build (bsp/distributed.h): the coordinator's side and the workers' entry
// point over basic_bsp_tree<exact_geometry>'s distributed members (tree_distributed.h, compiled
// with the exact kernel in bsp_exact.cpp).
//
// The input's bytes: "EXBSPINP", u32 version, u64 fragment limit, then a saved tree's common
// part (stats with the heuristic and seed, the sampled heuristic's parameters, the soup).
#include <exbsp/bsp/distributed.h>

#include <chrono>
#include <cstring>
#include <map>
#include <utility>

#include <exbsp/core/errors.h>
#include "bsp/bsp_tree.h"
#include "bsp/geometry_exact.h"
#include "bsp/kernels.h"
#include "bsp/tree_file.h"

namespace exbsp {

namespace {

constexpr char input_magic[8] = {'E', 'X', 'B', 'S', 'P', 'I', 'N', 'P'};
constexpr std::uint32_t input_version = 1;

using tree_type = basic_bsp_tree<exact_geometry>;

/// `o`, or usage_error unless the options can travel (exact kernel, no callback).
const build_options& distributable(const build_options& o) {
  if (o.kernel != kernel_id::exact)
    throw usage_error("distributed build: the kernel must be 'exact' (got '" + to_string(o.kernel) +
                      "'): the bytes carry its exact points");
  if (o.score || o.heuristic == "custom")
    throw usage_error(
        "distributed build: a score callback cannot be shipped to other machines (heuristic "
        "'custom'); use a named heuristic");
  return o;
}

std::string input_bytes(const triangle_soup& soup, const build_options& o) {
  tree_file::writer out;
  out.bytes(input_magic, sizeof input_magic);
  out.u32(input_version);
  out.u64(o.max_fragments);
  build_stats stats;
  stats.heuristic = o.heuristic;
  stats.seed = o.seed;
  tree_file::common_part common;
  common.sampled_candidates = o.sampled_candidates;
  common.sampled_samples = o.sampled_samples;
  common.sampled_split_weight = o.sampled_split_weight;
  common.soup = soup;
  tree_file::write_common(out, stats, common);
  return std::move(out.data());
}

/// The soup and options of input bytes.
std::pair<triangle_soup, build_options> read_input(std::string_view bytes) {
  tree_file::reader in(bytes, "input");
  const std::string_view m = in.bytes("magic", sizeof input_magic);
  if (std::memcmp(m.data(), input_magic, sizeof input_magic) != 0)
    in.fail_at(0, "magic", "not the input of a distributed exbsp build");
  const std::uint32_t v = in.u32("version");
  if (v != input_version)
    in.fail_at(8, "version",
               "version " + std::to_string(v) + " (this exbsp reads " +
                   std::to_string(input_version) + ")");
  build_options o;
  o.max_fragments = static_cast<std::size_t>(in.u64("max_fragments"));
  tree_file::common_part common = tree_file::read_common(in);
  if (in.remaining()) in.fail("end", std::to_string(in.remaining()) + " bytes after the soup");
  o.heuristic = common.stats.heuristic;
  o.seed = common.stats.seed;
  o.sampled_candidates = common.sampled_candidates;
  o.sampled_samples = common.sampled_samples;
  o.sampled_split_weight = common.sampled_split_weight;
  o.keep_input = false;
  distributable(o);
  return {std::move(common.soup), std::move(o)};
}

}  // namespace

class distributed_build::impl {
 public:
  impl(const triangle_soup& soup, const build_options& options)
      : start_(std::chrono::steady_clock::now()),
        soup_(soup),
        options_(options),
        tree_(soup, distributable(options), tree_type::top_only{}) {
    input_ = input_bytes(soup, options);
    for (std::size_t i = 0; i < tree_.cell_count(); ++i) cells_.push_back(tree_.write_cell(i));
  }

  const std::string& input() const { return input_; }
  std::size_t cell_count() const { return cells_.size(); }
  const std::string& cell(std::size_t i) const {
    if (i >= cells_.size())
      throw usage_error("cell: index " + std::to_string(i) + " out of range (" +
                        std::to_string(cells_.size()) + " cells)");
    return cells_[i];
  }

  void add_part(std::size_t i, std::string part) {
    if (finished_) throw usage_error("add_part: the build is finished");
    if (i >= cells_.size())
      throw usage_error("add_part: index " + std::to_string(i) + " out of range (" +
                        std::to_string(cells_.size()) + " cells)");
    if (i < joined_ || waiting_.count(i))
      throw usage_error("add_part: part " + std::to_string(i) + " was already added");
    waiting_.emplace(i, std::move(part));
    // Join every part whose predecessors are in (frontier order), freeing its bytes and cell.
    for (auto it = waiting_.find(joined_); it != waiting_.end(); it = waiting_.find(joined_)) {
      tree_.append_part(soup_, joined_, it->second);
      waiting_.erase(it);
      std::string().swap(cells_[joined_]);
      ++joined_;
    }
  }

  bsp finish() {
    if (finished_) throw usage_error("finish: the build is already finished");
    if (joined_ != cells_.size())
      throw usage_error("finish: " + std::to_string(cells_.size() - joined_) + " of " +
                        std::to_string(cells_.size()) + " parts missing");
    finished_ = true;
    tree_.finish_parts(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
    // The saved tree's bytes, read back: bsp::deserialize checks the whole tree as it checks
    // any file (and its canonical form), and gives the bsp.
    tree_file::common_part common;
    common.sampled_candidates = options_.sampled_candidates;
    common.sampled_samples = options_.sampled_samples;
    common.sampled_split_weight = options_.sampled_split_weight;
    common.soup = std::move(soup_);
    const std::string bytes =
        tree_file::framed(kernel_row_of(kernel_id::exact).file_code, [&](tree_file::writer& out) {
          tree_file::write_common(out, tree_.stats(), common);
          tree_.write_tree(out);
        });
    return bsp::deserialize(bytes, "distributed build");
  }

 private:
  std::chrono::steady_clock::time_point start_;
  triangle_soup soup_;
  build_options options_;
  tree_type tree_;
  std::string input_;
  std::vector<std::string> cells_;
  std::map<std::size_t, std::string> waiting_;  ///< parts added before their predecessors
  std::size_t joined_ = 0;
  bool finished_ = false;
};

distributed_build::distributed_build(const triangle_soup& soup, const build_options& options)
    : impl_(std::make_unique<impl>(soup, options)) {}
distributed_build::distributed_build(distributed_build&&) noexcept = default;
distributed_build& distributed_build::operator=(distributed_build&&) noexcept = default;
distributed_build::~distributed_build() = default;

const std::string& distributed_build::input() const { return impl_->input(); }
std::size_t distributed_build::cell_count() const { return impl_->cell_count(); }
const std::string& distributed_build::cell(std::size_t i) const { return impl_->cell(i); }
void distributed_build::add_part(std::size_t i, std::string part) {
  impl_->add_part(i, std::move(part));
}
bsp distributed_build::finish() { return impl_->finish(); }

std::string distributed_build::build_cell(std::string_view input, std::string_view cell) {
  const auto [soup, options] = read_input(input);
  return tree_type::grow_cell(soup, options, cell);
}

bsp distributed_build::build_here(const triangle_soup& soup, const build_options& options) {
  distributed_build plan(soup, options);
  for (std::size_t i = 0; i < plan.cell_count(); ++i)
    plan.add_part(i, build_cell(plan.input(), plan.cell(i)));
  return plan.finish();
}

}  // namespace exbsp
