// SPDX-License-Identifier: LGPL-3.0-or-later
// Saved trees of the exact kernel: the point table and the fragments (docs/tree-file.md).
// Notation: see geometry_exact.h; V input vertices (point ids 0 .. V-1), C constructed points
// SEG(p, q, plane) (ids V .. V+C-1 in the file, each after its endpoints), F fragments.
#include <algorithm>
#include <limits>
#include <string>

#include <exbsp/core/errors.h>
#include "bsp/geometry_exact.h"
#include "bsp/tree_file.h"

namespace exbsp {

std::uint32_t exact_geometry::point_id_end() {
  const std::lock_guard<std::mutex> lock(claim_mutex_);
  return claimed_;
}

void exact_geometry::write_fragments(tree_file::writer& out, const std::vector<fragment>& fragments,
                                     std::uint32_t known_end,
                                     std::vector<std::uint32_t>* written) const {
  // The constructed points in use, numbered by first use: fragments in order, each point
  // after its endpoints (post-order). Point ids are claimed in an order that depends on thread
  // timing, but which points exist and how they are built does not, so this numbering makes
  // the file the same for every thread count and run. Explicit stack: nesting may be deep.
  known_end = std::max(known_end, inputs_);
  std::vector<std::uint32_t> renumbered(std::max(claimed_, known_end), none);
  for (std::uint32_t id = 0; id < known_end; ++id) renumbered[id] = id;
  std::vector<std::uint32_t> file_order;  // constructed ids, in file order
  std::vector<std::uint32_t> stack;
  for (const fragment& f : fragments)
    for (std::uint32_t root : f.v) {
      stack.push_back(root);
      while (!stack.empty()) {
        const std::uint32_t id = stack.back();
        if (renumbered[id] != none) {
          stack.pop_back();
          continue;
        }
        const point& pt = at(id);
        const bool ready = renumbered[pt.p] != none && renumbered[pt.q] != none;
        if (!ready) {
          if (renumbered[pt.q] == none) stack.push_back(pt.q);
          if (renumbered[pt.p] == none) stack.push_back(pt.p);  // p is numbered before q
          continue;
        }
        stack.pop_back();
        renumbered[id] = known_end + static_cast<std::uint32_t>(file_order.size());
        file_order.push_back(id);
      }
    }
  out.u64(file_order.size());
  for (std::uint32_t id : file_order) {
    const point& pt = at(id);
    out.u32(renumbered[pt.p]);
    out.u32(renumbered[pt.q]);
    out.u32(pt.plane);
  }
  out.u64(fragments.size());
  for (const fragment& f : fragments) {
    for (std::uint32_t id : f.v) out.u32(renumbered[id]);
    out.u32(f.source);
  }
  if (written) *written = std::move(file_order);
}

void exact_geometry::read_fragments(tree_file::reader& in, const triangle_soup& soup,
                                    const std::vector<char>& usable,
                                    std::vector<fragment>& fragments) {
  // The exact values this tree may make (the checks below, orders, roundings): 4096 bits per
  // byte of the file, at least 16 MB. Trees exbsp writes need 10-20 bits per byte (the CGAL
  // corpus, every point's exact value once).
  exact_budget_bits_ = std::max<std::uint64_t>(std::uint64_t{1} << 27,
                                               std::uint64_t{in.offset() + in.remaining()} * 4096);
  exact_budget_file_ = in.name();
  read_fragments(in, soup, usable, fragments, {});
}

void exact_geometry::read_fragments(tree_file::reader& in, const triangle_soup& soup,
                                    const std::vector<char>& usable,
                                    std::vector<fragment>& fragments,
                                    const std::vector<std::uint32_t>& known) {
  using tree_file::indexed;
  const std::uint32_t triangles = static_cast<std::uint32_t>(soup.triangles.size());
  const auto check_plane = [&](std::size_t at, const std::string& field, std::uint32_t plane,
                               const char* what) {
    if (plane >= triangles)
      in.fail_at(at, field,
                 std::string(what) + " " + std::to_string(plane) + " out of range (" +
                     std::to_string(triangles) + " triangles)");
    if (!usable[plane])
      in.fail_at(
          at, field,
          std::string(what) + " " + std::to_string(plane) + " is a degenerate triangle (no plane)");
  };

  // Constructed points, each checked and approximated after its endpoints.
  // File ids: V input vertices, then the known points, then the file's constructed points,
  // which take the ids from `base` on (a fresh geometry: base = V, file ids = ids).
  const auto known_count = static_cast<std::uint32_t>(known.size());
  std::uint32_t base = 0;
  {
    const std::lock_guard<std::mutex> lock(claim_mutex_);
    base = claimed_;
  }
  const std::uint64_t capacity = (std::uint64_t{1} << max_point_bits) - 2 * block - base;
  const auto constructed = static_cast<std::uint32_t>(in.count("points", 12, capacity));
  const std::uint32_t first = inputs_ + known_count;  // the first constructed file id
  const std::uint32_t total = first + constructed;    // file ids end here
  {
    const std::lock_guard<std::mutex> lock(claim_mutex_);
    grow_chunks(base + constructed);
    claimed_ = base + constructed;
  }
  const auto id_of = [&](std::uint32_t file_id) {
    return file_id < inputs_ ? file_id
           : file_id < first ? known[file_id - inputs_]
                             : base + (file_id - first);
  };
  for (std::uint32_t file_id = first; file_id < total; ++file_id) {
    const std::size_t where = in.offset();
    const std::uint32_t p = in.u32("points"), q = in.u32("points"), plane = in.u32("points");
    const std::string field = indexed("points", file_id);
    if (p >= file_id || q >= file_id)
      in.fail_at(where, field,
                 "endpoint " + std::to_string(std::max(p, q)) + " is not an earlier point");
    check_plane(where, field, plane, "plane");
    const std::uint32_t id = id_of(file_id);
    point& x = at(id);
    x.p = id_of(p);
    x.q = id_of(q);
    x.plane = plane;
    // Exact signs (filter, structure, GMP): p and q strictly on opposite sides, so the
    // point's exact value (fp q - fq p) / (fp - fq) has a non-zero denominator.
    const fast_plane_core fp = filter(plane);
    const int sp = point_sign_of(plane, fp, x.p);
    const int sq = point_sign_of(plane, fp, x.q);
    if (sp * sq >= 0)
      in.fail_at(where, field,
                 "the segment between points " + std::to_string(p) + " and " + std::to_string(q) +
                     " does not cross the plane of triangle " + std::to_string(plane));
    approximate(id);
  }

  const std::size_t count = in.count("fragments", 16, std::numeric_limits<std::uint32_t>::max());
  fragments.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t at = in.offset();
    fragment& f = fragments[i];
    for (std::uint32_t& id : f.v) id = in.u32("fragments");
    f.source = in.u32("fragments");
    for (std::uint32_t& id : f.v) {
      if (id >= total)
        in.fail_at(
            at, indexed("fragments", i),
            "point " + std::to_string(id) + " out of range (" + std::to_string(total) + " points)");
      id = id_of(id);
    }
    check_plane(at, indexed("fragments", i), f.source, "source triangle");
    f.face = soup.triangles[f.source].face;
  }
}

}  // namespace exbsp
