// Visible regions, hidden-line edges and curves for vector output (notation in
// vector_drawing.h). The 2D Booleans are Clipper's (libpolyclipping): integer coordinates, so
// the grid points of the drawing are its exact input and output; a measurement against CGAL's
// Boolean_set_operations_2 on an exact kernel is in bench/vector_output.md.
#include "view/vector_drawing.h"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>
#include <unordered_set>

#include "core/errors.h"
#include "view/clip_stage.h"
#include "view/pipeline.h"

namespace exbsp::view {

namespace cl = ClipperLib;

const char* to_string(vector_options::mode_kind m) {
  return m == vector_options::mode_kind::painter ? "painter" : "visible";
}

const char* to_string(vector_options::edges_kind e) {
  switch (e) {
    case vector_options::edges_kind::none:
      return "none";
    case vector_options::edges_kind::visible:
      return "visible";
    case vector_options::edges_kind::visible_hidden:
      return "visible+hidden";
  }
  return "?";
}

long long to_grid(double v) { return std::llround(v * static_cast<double>(grid_per_pixel)); }

drawing_counts count_paths(const vector_drawing& d) {
  drawing_counts c;
  for (const vector_path& p : d.paths) {
    switch (p.kind) {
      case vector_path::kind_type::underlay:
        ++c.underlays;
        break;
      case vector_path::kind_type::region:
        ++c.regions;
        c.rings += p.rings.size();
        break;
      case vector_path::kind_type::visible_edge:
        c.visible_edges += p.rings.size();
        break;
      case vector_path::kind_type::hidden_edge:
        c.hidden_edges += p.rings.size();
        break;
      case vector_path::kind_type::curve:
      case vector_path::kind_type::point:
        ++c.curves;
        break;
    }
  }
  return c;
}

namespace {

cl::IntPoint grid_of(const viewport& vp, const window_point& w) {
  return {to_grid(w.x - vp.x), to_grid(w.y - vp.y)};
}

std::vector<grid_point> to_ring(const cl::Path& p) {
  std::vector<grid_point> r;
  r.reserve(p.size());
  for (const cl::IntPoint& q : p) r.push_back({q.X, q.Y});
  return r;
}

/// Mean width 2 |area| / perimeter of a closed ring, in grid units.
double mean_width(const cl::Path& p) {
  double perimeter = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const cl::IntPoint& a = p[i];
    const cl::IntPoint& b = p[(i + 1) % p.size()];
    perimeter += std::hypot(static_cast<double>(b.X - a.X), static_cast<double>(b.Y - a.Y));
  }
  return perimeter > 0 ? 2 * std::abs(cl::Area(p)) / perimeter : 0;
}

/// True when b is the tip of a spike a -> b -> c: a and c lie on the same side of b, the
/// nearer of them less than one grid unit from the line through b and the farther one. Such
/// zero-area antennas appear where a region shows through a rounding crack (a T-junction of
/// the polygons in front of it); they are no part of any true region.
bool spike_at(const cl::IntPoint& a, const cl::IntPoint& b, const cl::IntPoint& c) {
  const double ax = static_cast<double>(a.X - b.X), ay = static_cast<double>(a.Y - b.Y);
  const double cx = static_cast<double>(c.X - b.X), cy = static_cast<double>(c.Y - b.Y);
  if (ax * cx + ay * cy <= 0) return false;
  const double longer = std::max(std::hypot(ax, ay), std::hypot(cx, cy));
  return longer > 0 && std::abs(ax * cy - ay * cx) < longer;
}

/// The ring without spikes (spike_at), removed until none is left.
void remove_spikes(cl::Path& ring) {
  cl::Path out;
  out.reserve(ring.size());
  for (const cl::IntPoint& p : ring) {
    out.push_back(p);
    while (out.size() >= 3 && spike_at(out[out.size() - 3], out[out.size() - 2], out.back()))
      out.erase(out.end() - 2);
  }
  for (bool changed = true; changed && out.size() >= 3;) {
    changed = false;
    const std::size_t n = out.size();
    if (spike_at(out[n - 2], out[n - 1], out[0])) {
      out.pop_back();
      changed = true;
    } else if (spike_at(out[n - 1], out[0], out[1])) {
      out.erase(out.begin());
      changed = true;
    }
  }
  ring.swap(out);
}

struct bbox_i {
  long long x0, y0, x1, y1;
};

template <class Points>
bbox_i bbox_of(const Points& pts) {
  bbox_i b{pts[0].X, pts[0].Y, pts[0].X, pts[0].Y};
  for (const auto& q : pts) {
    b.x0 = std::min(b.x0, q.X);
    b.y0 = std::min(b.y0, q.Y);
    b.x1 = std::max(b.x1, q.X);
    b.y1 = std::max(b.y1, q.Y);
  }
  return b;
}

/// Screen coverage indexed by square tiles. Every polygon added is stored, whole (never cut
/// at tile lines, so no rounded point is made there), in the list of each tile its bounding
/// box meets; a list is merged (union) every merge_every additions, and a tile found fully
/// covered keeps only its square. The coverage near a polygon P is then the union of the
/// lists (or squares) of P's tiles: any earlier polygon overlapping P shares a tile with it.
/// Nonzero fill with every input polygon counter-clockwise makes a list mean its union.
class tiled_coverage {
 public:
  static constexpr long long tile_side = 16 * grid_per_pixel;
  static constexpr int merge_every = 8;

  tiled_coverage(long long width, long long height)
      : nx_(static_cast<int>(std::max<long long>(1, (width + tile_side - 1) / tile_side))),
        ny_(static_cast<int>(std::max<long long>(1, (height + tile_side - 1) / tile_side))),
        tiles_(static_cast<std::size_t>(nx_) * ny_) {
    for (int ty = 0; ty < ny_; ++ty)
      for (int tx = 0; tx < nx_; ++tx) {
        const long long x0 = tx * tile_side, y0 = ty * tile_side;
        tiles_[index(tx, ty)].rect = {
            {x0, y0}, {x0 + tile_side, y0}, {x0 + tile_side, y0 + tile_side}, {x0, y0 + tile_side}};
      }
  }

  /// True when every tile p's bounding box meets is fully covered (p is hidden).
  bool hides(const cl::Path& p) const {
    const auto [tx0, ty0, tx1, ty1] = tile_range(bbox_of(p));
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx)
        if (!tiles_[index(tx, ty)].full) return false;
    return true;
  }

  /// Adds the counter-clockwise polygon p; appends its part not covered before to `visible`.
  void add(const cl::Path& p, cl::Paths& visible) {
    if (hides(p)) return;
    const auto [tx0, ty0, tx1, ty1] = tile_range(bbox_of(p));
    clip_.clear();
    gather(tx0, ty0, tx1, ty1, clip_);
    if (clip_.empty()) {
      visible.push_back(p);
    } else {
      clipper_.Clear();
      clipper_.AddPath(p, cl::ptSubject, true);
      clipper_.AddPaths(clip_, cl::ptClip, true);
      out_.clear();
      clipper_.Execute(cl::ctDifference, out_, cl::pftNonZero, cl::pftNonZero);
      visible.insert(visible.end(), out_.begin(), out_.end());
    }
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx) {
        tile& t = tiles_[index(tx, ty)];
        if (t.full) continue;
        t.covered.push_back(p);
        if (++t.pending >= merge_every) merge(t);
      }
  }

  /// The parts of the open polyline `line` outside the coverage.
  cl::Paths outside(const cl::Path& line) {
    const auto [tx0, ty0, tx1, ty1] = tile_range(bbox_of(line));
    cl::Paths clip;
    gather(tx0, ty0, tx1, ty1, clip);
    if (clip.empty()) return {line};
    clipper_.Clear();
    clipper_.AddPath(line, cl::ptSubject, false);
    clipper_.AddPaths(clip, cl::ptClip, true);
    cl::PolyTree tree;
    clipper_.Execute(cl::ctDifference, tree, cl::pftNonZero, cl::pftNonZero);
    cl::Paths out;
    cl::OpenPathsFromPolyTree(tree, out);
    return out;
  }

  /// True when the point is strictly covered (nonzero winding of the coverage).
  bool covers(const cl::IntPoint& q) {
    const auto [tx0, ty0, tx1, ty1] = tile_range({q.X, q.Y, q.X, q.Y});
    cl::Paths clip;
    gather(tx0, ty0, tx1, ty1, clip);
    int winding = 0;
    for (const cl::Path& p : clip)
      if (cl::PointInPolygon(q, p) == 1) winding += cl::Orientation(p) ? 1 : -1;
    return winding != 0;
  }

 private:
  struct tile {
    cl::Paths covered;  ///< merged paths and pending polygons (nonzero union)
    cl::Path rect;
    int pending = 0;
    bool full = false;
  };

  std::size_t index(int tx, int ty) const { return static_cast<std::size_t>(ty) * nx_ + tx; }

  std::array<int, 4> tile_range(const bbox_i& b) const {
    auto clamp_x = [&](long long v) {
      return static_cast<int>(std::clamp<long long>(v / tile_side, 0, nx_ - 1));
    };
    auto clamp_y = [&](long long v) {
      return static_cast<int>(std::clamp<long long>(v / tile_side, 0, ny_ - 1));
    };
    return {clamp_x(std::max(0LL, b.x0)), clamp_y(std::max(0LL, b.y0)),
            clamp_x(std::max(0LL, b.x1)), clamp_y(std::max(0LL, b.y1))};
  }

  void merge(tile& t) {
    clipper_.Clear();
    clipper_.AddPaths(t.covered, cl::ptSubject, true);
    clipper_.Execute(cl::ctUnion, t.covered, cl::pftNonZero, cl::pftNonZero);
    t.pending = 0;
    // Holes thinner than min_region_width are rounding cracks, not gaps anything can be seen
    // through: closing them keeps the coverage simple and lets the tile become full.
    t.covered.erase(std::remove_if(t.covered.begin(), t.covered.end(),
                                   [](const cl::Path& p) {
                                     return !cl::Orientation(p) && mean_width(p) < min_region_width;
                                   }),
                    t.covered.end());
    double area = 0;
    for (const cl::Path& p : t.covered) area += cl::Area(p);
    if (area < cl::Area(t.rect)) return;  // cannot cover the square yet
    clipper_.Clear();
    clipper_.AddPath(t.rect, cl::ptSubject, true);
    clipper_.AddPaths(t.covered, cl::ptClip, true);
    out_.clear();
    clipper_.Execute(cl::ctDifference, out_, cl::pftNonZero, cl::pftNonZero);
    if (out_.empty()) {
      t.full = true;
      t.covered = {t.rect};
    }
  }

  /// The coverage of tiles [tx0, tx1] x [ty0, ty1]: each full tile's square, the others' lists,
  /// each distinct path once. A polygon larger than a tile sits whole in the list of every tile
  /// it meets; handing Clipper hundreds of copies of it (a cube face at 800x600 meets ~600 tiles)
  /// made its intersection fix-up quadratic in the copies: minutes for 12 triangles.
  void gather(int tx0, int ty0, int tx1, int ty1, cl::Paths& clip) const {
    std::unordered_set<std::size_t> seen;
    const std::size_t first = clip.size();
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx) {
        const tile& t = tiles_[index(tx, ty)];
        for (const cl::Path& p : t.covered) {
          std::size_t h = p.size();
          for (const cl::IntPoint& q : p)
            h = (h * 1000003u) ^ std::hash<long long>{}(q.X * 31 + q.Y);
          if (!seen.insert(h).second &&
              std::any_of(clip.begin() + static_cast<std::ptrdiff_t>(first), clip.end(),
                          [&](const cl::Path& o) { return o == p; }))
            continue;
          clip.push_back(p);
        }
      }
  }

  int nx_, ny_;
  std::vector<tile> tiles_;
  cl::Clipper clipper_;
  cl::Paths clip_, out_;
};

/// T-junctions: where a vertex of one polygon lies inside an edge of another (a BSP split
/// point on a neighbour's edge), rounding to the grid moves it up to half a unit off that edge
/// and opens a crack through which what is behind would show. Every vertex lying less than
/// one unit from the inside of an edge of another polygon is inserted into that edge, so the
/// two share the boundary exactly. Vertices are found in a sorted index of 4-pixel cells,
/// walking the cells along each edge; a polygon is mended only when it may be visible.
class t_junction_mender {
 public:
  explicit t_junction_mender(const std::vector<cl::Path>& polys) {
    for (const cl::Path& p : polys)
      for (const cl::IntPoint& q : p) index_.push_back({key(cell_of(q.X), cell_of(q.Y)), q});
    std::sort(index_.begin(), index_.end(), [](const entry& a, const entry& b) {
      return a.key != b.key ? a.key < b.key : a.p.X != b.p.X ? a.p.X < b.p.X : a.p.Y < b.p.Y;
    });
    index_.erase(
        std::unique(index_.begin(), index_.end(),
                    [](const entry& a, const entry& b) { return a.key == b.key && a.p == b.p; }),
        index_.end());
  }

  /// Inserts into p's edges the vertices lying less than one unit from their insides.
  void mend(cl::Path& p) {
    mended_.clear();
    for (std::size_t i = 0; i < p.size(); ++i) {
      const cl::IntPoint a = p[i], b = p[(i + 1) % p.size()];
      mended_.push_back(a);
      const double dx = static_cast<double>(b.X - a.X), dy = static_cast<double>(b.Y - a.Y);
      const double len2 = dx * dx + dy * dy, len = std::sqrt(len2);
      on_edge_.clear();
      cells_.clear();
      const long long steps = static_cast<long long>(len / (cell / 2)) + 1;
      for (long long s = 0; s <= steps; ++s) {
        const double t = static_cast<double>(s) / static_cast<double>(steps);
        const long long cx = cell_of(a.X + std::llround(t * dx)),
                        cy = cell_of(a.Y + std::llround(t * dy));
        for (long long ox = -1; ox <= 1; ++ox)
          for (long long oy = -1; oy <= 1; ++oy) cells_.push_back(key(cx + ox, cy + oy));
      }
      std::sort(cells_.begin(), cells_.end());
      cells_.erase(std::unique(cells_.begin(), cells_.end()), cells_.end());
      for (const std::uint64_t k : cells_) {
        auto it = std::lower_bound(index_.begin(), index_.end(), k,
                                   [](const entry& e, std::uint64_t v) { return e.key < v; });
        for (; it != index_.end() && it->key == k; ++it) {
          const cl::IntPoint& v = it->p;
          const double vx = static_cast<double>(v.X - a.X), vy = static_cast<double>(v.Y - a.Y);
          const double along = vx * dx + vy * dy;
          if (along <= 0 || along >= len2) continue;
          if (std::abs(vx * dy - vy * dx) >= len) continue;  // one unit or more off the line
          on_edge_.push_back({along, v});
        }
      }
      std::sort(on_edge_.begin(), on_edge_.end(),
                [](const auto& x, const auto& y) { return x.first < y.first; });
      for (const auto& [along, v] : on_edge_)
        if (!(mended_.back() == v)) mended_.push_back(v);
    }
    p.swap(mended_);
  }

 private:
  static constexpr long long cell = 4 * grid_per_pixel;
  struct entry {
    std::uint64_t key;
    cl::IntPoint p;
  };
  static std::uint64_t key(long long cx, long long cy) {
    return static_cast<std::uint64_t>(cx + (1LL << 30)) << 32 |
           static_cast<std::uint64_t>(cy + (1LL << 30));
  }
  static long long cell_of(long long v) { return v >= 0 ? v / cell : -((-v + cell - 1) / cell); }

  std::vector<entry> index_;
  std::vector<std::uint64_t> cells_;
  std::vector<std::pair<double, cl::IntPoint>> on_edge_;
  cl::Path mended_;
};

/// Mesh index of each face id (f.mesh_face_offsets: first face of mesh k).
std::uint32_t mesh_of(const frame& f, std::uint32_t face) {
  if (f.mesh_face_offsets.empty()) return 0;
  const auto it = std::upper_bound(f.mesh_face_offsets.begin(), f.mesh_face_offsets.end(), face);
  return static_cast<std::uint32_t>(
      std::max<std::ptrdiff_t>(0, it - f.mesh_face_offsets.begin() - 1));
}

rgb8 shaded(const frame& f, rgb8 c, double x, double y, double z) {
  return f.shader ? f.shader->shade(c, x, y, z) : c;
}

/// A curve piece (or point) as a path, shaded at its midpoint.
vector_path curve_path(const frame& f, const screen_line& l) {
  vector_path p;
  p.kind = l.point ? vector_path::kind_type::point : vector_path::kind_type::curve;
  p.face = l.curve;
  p.color = shaded(f, l.color, 0.5 * (l.a.x + l.b.x), 0.5 * (l.a.y + l.b.y), 0.5 * (l.a.z + l.b.z));
  const viewport& vp = f.view.vp;
  p.rings.push_back({{to_grid(l.a.x - vp.x), to_grid(l.a.y - vp.y)}});
  if (!l.point) p.rings.back().push_back({to_grid(l.b.x - vp.x), to_grid(l.b.y - vp.y)});
  return p;
}

/// Appends `piece` to the drawing, joined to the previous curve path when it continues it
/// (same curve, same colour).
void append_curve(vector_drawing& d, vector_path&& piece) {
  if (piece.kind == vector_path::kind_type::curve && !d.paths.empty()) {
    vector_path& last = d.paths.back();
    if (last.kind == vector_path::kind_type::curve && last.face == piece.face &&
        last.color == piece.color) {
      for (auto& r : piece.rings) {
        if (!last.rings.empty() && last.rings.back().back() == r.front())
          last.rings.back().insert(last.rings.back().end(), r.begin() + 1, r.end());
        else
          last.rings.push_back(std::move(r));
      }
      return;
    }
  }
  d.paths.push_back(std::move(piece));
}

/// Per face: the pieces of its visible region and the data for its colour.
struct face_accumulator {
  cl::Paths pieces;
  rgb8 color;
  bool seen = false;
  double sx = 0, sy = 0, sz = 0;
  std::size_t n = 0;
};

// ---- edges ------------------------------------------------------------------------------

struct feature_edge {
  vec3d a, b;
  std::uint32_t faces[2];
  int face_count;  ///< 1 or 2 faces kept (a non-manifold edge keeps its first two)
};

struct vec3d_hash {
  std::size_t operator()(const vec3d& v) const {
    std::size_t h = 0;
    for (double c : v) h = h * 1000003u ^ std::hash<double>()(c == 0 ? 0.0 : c);
    return h;
  }
};

vec3d sub(const vec3d& a, const vec3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
vec3d cross(const vec3d& a, const vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const vec3d& a, const vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// Boundary, non-manifold, crease and silhouette edges of the soup for the view.
std::vector<feature_edge> feature_edges(const frame& f, double crease_deg) {
  const triangle_soup& s = f.soup;
  // Weld vertices by exact position: files often repeat a point under several indices.
  std::unordered_map<vec3d, std::uint32_t, vec3d_hash> weld;
  std::vector<std::uint32_t> id(s.vertices.size());
  for (std::size_t i = 0; i < s.vertices.size(); ++i) {
    vec3d v = s.vertices[i];
    for (double& c : v) c = c == 0 ? 0.0 : c;
    id[i] = weld.emplace(v, static_cast<std::uint32_t>(weld.size())).first->second;
  }
  std::vector<vec3d> normal(s.triangles.size());
  struct half {
    std::uint64_t key;
    std::uint32_t tri;
  };
  std::vector<half> halves;
  halves.reserve(3 * s.triangles.size());
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const auto& v = s.triangles[t].v;
    normal[t] =
        cross(sub(s.vertices[v[1]], s.vertices[v[0]]), sub(s.vertices[v[2]], s.vertices[v[0]]));
    if (dot(normal[t], normal[t]) == 0) continue;  // degenerate: no plane, not drawn
    for (int k = 0; k < 3; ++k) {
      std::uint64_t p = id[v[k]], q = id[v[(k + 1) % 3]];
      if (p > q) std::swap(p, q);
      halves.push_back({p << 32 | q, static_cast<std::uint32_t>(t)});
    }
  }
  std::sort(halves.begin(), halves.end(), [](const half& x, const half& y) {
    return x.key != y.key ? x.key < y.key : x.tri < y.tri;
  });
  const double cos_crease = std::cos(crease_deg * M_PI / 180.0);
  const vec3d eye = to_vec3d(f.view.cam.eye);
  const vec3d towards_eye = {-f.view.direction.x, -f.view.direction.y, -f.view.direction.z};
  auto facing = [&](std::uint32_t t) {
    const vec3d& a = s.vertices[s.triangles[t].v[0]];
    const double side = dot(normal[t], f.view.is_parallel() ? towards_eye : sub(eye, a));
    return (side > 0) - (side < 0);
  };
  std::vector<feature_edge> edges;
  for (std::size_t i = 0; i < halves.size();) {
    std::size_t j = i;
    while (j < halves.size() && halves[j].key == halves[i].key) ++j;
    const std::uint32_t t0 = halves[i].tri;
    const auto& tv = s.triangles[t0].v;
    const std::uint32_t a_id = static_cast<std::uint32_t>(halves[i].key >> 32);
    vec3d a{}, b{};
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t p = tv[k], q = tv[(k + 1) % 3];
      const std::uint64_t lo = std::min(id[p], id[q]), hi = std::max(id[p], id[q]);
      if ((lo << 32 | hi) == halves[i].key) {
        a = s.vertices[id[p] == a_id ? p : q];
        b = s.vertices[id[p] == a_id ? q : p];
        break;
      }
    }
    // Distinct faces around the edge (two triangles of one face: a fan diagonal, not drawn).
    std::vector<std::uint32_t> tris;
    for (std::size_t k = i; k < j; ++k) {
      const std::uint32_t t = halves[k].tri;
      if (std::none_of(tris.begin(), tris.end(),
                       [&](std::uint32_t u) { return s.triangles[u].face == s.triangles[t].face; }))
        tris.push_back(t);
    }
    const std::size_t uses = j - i;
    i = j;
    bool draw;
    if (uses >= 3) {
      draw = true;  // non-manifold
    } else if (tris.size() == 1) {
      draw = uses == 1;  // boundary; two triangles of one face: a fan diagonal
    } else {
      const vec3d& n0 = normal[tris[0]];
      const vec3d& n1 = normal[tris[1]];
      const bool crease = dot(n0, n1) < cos_crease * std::sqrt(dot(n0, n0) * dot(n1, n1));
      draw = crease || facing(tris[0]) != facing(tris[1]);
    }
    if (!draw) continue;
    const std::uint32_t f0 = s.triangles[tris[0]].face;
    edges.push_back(
        {a, b, {f0, tris.size() > 1 ? s.triangles[tris[1]].face : f0}, tris.size() > 1 ? 2 : 1});
  }
  return edges;
}

/// The projection of a world-space edge in grid points; false when the view volume cuts it
/// away or it shrinks to a point.
bool project_edge(const frame& f, const mat4& pm, const feature_edge& e, cl::Path& out) {
  hpoint a, b;
  if (!clip_segment_to_view_volume(pm * to_point(e.a), pm * to_point(e.b), a, b)) return false;
  const viewport& vp = f.view.vp;
  const window_point wa = to_window(vp, a.x / a.w, a.y / a.w, a.z / a.w);
  const window_point wb = to_window(vp, b.x / b.w, b.y / b.w, b.z / b.w);
  out = {grid_of(vp, wa), grid_of(vp, wb)};
  return !(out[0] == out[1]);
}

/// The runs of an edge of length `length` given its visible intervals (any order, may
/// overlap): alternating visible / hidden runs covering [0, length], each run shorter than
/// 3 edge_margin (a gap between two regions' margins, or a rounding crumb) absorbed by the
/// run before it, and neighbours of one kind merged.
std::vector<std::pair<std::pair<double, double>, bool>> edge_runs(
    std::vector<std::pair<double, double>> visible, double length) {
  using run = std::pair<std::pair<double, double>, bool>;
  std::sort(visible.begin(), visible.end());
  std::vector<run> raw;  // alternating runs covering [0, length]
  double at = 0;
  for (const auto& [lo, hi] : visible) {
    if (hi <= at) continue;
    if (lo > at) raw.push_back({{at, lo}, false});
    raw.push_back({{std::max(at, lo), hi}, true});
    at = hi;
  }
  if (at < length) raw.push_back({{at, length}, false});
  const double crumb = 3 * edge_margin;
  std::vector<run> runs;
  for (const run& r : raw) {
    if (runs.empty()) {
      runs.push_back(r);
    } else if (runs.back().second == r.second || r.first.second - r.first.first < crumb) {
      runs.back().first.second = r.first.second;  // same kind, or a crumb: absorbed
    } else if (runs.back().first.second - runs.back().first.first < crumb) {
      runs.back() = {{runs.back().first.first, r.first.second}, r.second};  // a crumb at the start
    } else {
      runs.push_back(r);
    }
  }
  return runs;
}

/// Splits every feature edge into its visible and hidden parts against the regions and
/// appends one visible (and, when asked, one hidden) edge path per mesh.
void add_edges(const frame& f, const std::vector<vector_path>& regions, vector_drawing& d) {
  const vector_options& opt = f.vector;
  const std::vector<feature_edge> edges = feature_edges(f, opt.crease_deg);
  // Region index by tile (bounding boxes), and each region shrunk by edge_margin on demand.
  constexpr long long tile = 16 * grid_per_pixel;
  const long long nx = std::max<long long>(1, (d.width * grid_per_pixel + tile - 1) / tile);
  const long long ny = std::max<long long>(1, (d.height * grid_per_pixel + tile - 1) / tile);
  std::vector<std::vector<std::uint32_t>> by_tile(static_cast<std::size_t>(nx * ny));
  std::vector<bbox_i> boxes(regions.size());
  auto tile_of = [&](long long v, long long n) {
    return std::clamp<long long>(v / tile, 0, n - 1);
  };
  for (std::size_t r = 0; r < regions.size(); ++r) {
    bbox_i b{regions[r].rings[0][0].x, regions[r].rings[0][0].y, regions[r].rings[0][0].x,
             regions[r].rings[0][0].y};
    for (const auto& ring : regions[r].rings)
      for (const grid_point& q : ring) {
        b.x0 = std::min(b.x0, q.x);
        b.y0 = std::min(b.y0, q.y);
        b.x1 = std::max(b.x1, q.x);
        b.y1 = std::max(b.y1, q.y);
      }
    boxes[r] = b;
    for (long long ty = tile_of(b.y0, ny); ty <= tile_of(b.y1, ny); ++ty)
      for (long long tx = tile_of(b.x0, nx); tx <= tile_of(b.x1, nx); ++tx)
        by_tile[static_cast<std::size_t>(ty * nx + tx)].push_back(static_cast<std::uint32_t>(r));
  }
  std::vector<cl::Paths> shrunk(regions.size());
  std::vector<char> shrunk_done(regions.size(), 0);
  std::vector<std::size_t> stamp(regions.size(), 0);
  auto shrunk_region = [&](std::uint32_t r) -> const cl::Paths& {
    if (!shrunk_done[r]) {
      cl::Paths rings;
      for (const auto& ring : regions[r].rings) {
        cl::Path p;
        for (const grid_point& q : ring) p.push_back({q.x, q.y});
        rings.push_back(std::move(p));
      }
      cl::ClipperOffset off;
      off.AddPaths(rings, cl::jtMiter, cl::etClosedPolygon);
      off.Execute(shrunk[r], -edge_margin);
      shrunk_done[r] = 1;
    }
    return shrunk[r];
  };
  const bool hidden = opt.edges == vector_options::edges_kind::visible_hidden;
  const std::uint32_t meshes =
      f.mesh_face_offsets.empty() ? 1 : static_cast<std::uint32_t>(f.mesh_face_offsets.size());
  std::vector<vector_path> visible_paths(meshes), hidden_paths(meshes);
  for (std::uint32_t m = 0; m < meshes; ++m) {
    visible_paths[m].kind = vector_path::kind_type::visible_edge;
    hidden_paths[m].kind = vector_path::kind_type::hidden_edge;
    visible_paths[m].mesh = hidden_paths[m].mesh = m;
    visible_paths[m].color = hidden_paths[m].color = {0, 0, 0};
  }
  const mat4 pm = f.view.projection * f.view.model_view;
  cl::Clipper clipper;
  cl::Path segment;
  cl::Paths clip, pieces;
  std::size_t edge_number = 0;
  for (const feature_edge& e : edges) {
    ++edge_number;
    if (!project_edge(f, pm, e, segment)) continue;
    const std::uint32_t mesh = std::min(mesh_of(f, e.faces[0]), meshes - 1);
    const bbox_i b = bbox_of(segment);
    clip.clear();
    for (long long ty = tile_of(b.y0, ny); ty <= tile_of(b.y1, ny); ++ty)
      for (long long tx = tile_of(b.x0, nx); tx <= tile_of(b.x1, nx); ++tx)
        for (std::uint32_t r : by_tile[static_cast<std::size_t>(ty * nx + tx)]) {
          if (stamp[r] == edge_number) continue;
          stamp[r] = edge_number;
          const std::uint32_t face = regions[r].face;
          if (face == e.faces[0] || face == e.faces[1]) continue;
          const bbox_i& rb = boxes[r];
          if (rb.x1 < b.x0 || rb.x0 > b.x1 || rb.y1 < b.y0 || rb.y0 > b.y1) continue;
          const cl::Paths& s = shrunk_region(r);
          clip.insert(clip.end(), s.begin(), s.end());
        }
    // Visible intervals along the segment (parameter = grid units from segment[0]); the rest
    // is hidden.
    const double dx = static_cast<double>(segment[1].X - segment[0].X),
                 dy = static_cast<double>(segment[1].Y - segment[0].Y);
    const double length = std::hypot(dx, dy);
    std::vector<std::pair<double, double>> visible_parts;
    if (clip.empty()) {
      visible_parts.push_back({0, length});
    } else {
      clipper.Clear();
      clipper.AddPath(segment, cl::ptSubject, false);
      clipper.AddPaths(clip, cl::ptClip, true);
      cl::PolyTree tree;
      clipper.Execute(cl::ctDifference, tree, cl::pftNonZero, cl::pftNonZero);
      cl::OpenPathsFromPolyTree(tree, pieces);
      auto param = [&](const cl::IntPoint& q) {
        return std::clamp((static_cast<double>(q.X - segment[0].X) * dx +
                           static_cast<double>(q.Y - segment[0].Y) * dy) /
                              length,
                          0.0, length);
      };
      for (const cl::Path& piece : pieces) {
        double lo = length, hi = 0;
        for (const cl::IntPoint& q : piece) {
          lo = std::min(lo, param(q));
          hi = std::max(hi, param(q));
        }
        if (hi > lo) visible_parts.push_back({lo, hi});
      }
    }
    for (const auto& [run, is_visible] : edge_runs(visible_parts, length)) {
      if (!is_visible && !hidden) continue;
      auto at = [&](double t) {
        return grid_point{segment[0].X + std::llround(t / length * dx),
                          segment[0].Y + std::llround(t / length * dy)};
      };
      (is_visible ? visible_paths : hidden_paths)[mesh].rings.push_back(
          {at(run.first), at(run.second)});
    }
  }
  if (hidden)
    for (vector_path& p : hidden_paths)
      if (!p.rings.empty()) d.paths.push_back(std::move(p));
  for (vector_path& p : visible_paths)
    if (!p.rings.empty()) d.paths.push_back(std::move(p));
}

}  // namespace

drawing_placement placement_of(const frame& f) {
  const view_setup& v = f.view;
  if (!v.needs_placement()) return {};
  return {v.image_width, v.image_height, v.place_x, v.place_y, f.background};
}

namespace {

/// A drawing of the frame's viewport with nothing on it: its size, background (the sample
/// shader's when a screen effect installed one) and placement in the image.
vector_drawing empty_drawing(const frame& f) {
  vector_drawing d;
  d.width = f.view.vp.width;
  d.height = f.view.vp.height;
  d.background = f.shader ? f.shader->background : f.background;
  d.placement = placement_of(f);
  return d;
}

}  // namespace

vector_drawing visible_drawing(const frame& f) {
  const vector_options& opt = f.vector;
  if (!(opt.crease_deg > 0 && opt.crease_deg <= 180))
    throw usage_error("svg: crease_deg must be in (0, 180], got " + std::to_string(opt.crease_deg));
  const viewport& vp = f.view.vp;
  vector_drawing d = empty_drawing(f);
  tiled_coverage coverage(static_cast<long long>(vp.width) * grid_per_pixel,
                          static_cast<long long>(vp.height) * grid_per_pixel);
  std::unordered_map<std::uint32_t, face_accumulator> faces;
  std::vector<vector_path> curve_paths;
  auto clip_line = [&](const screen_line& l) {
    vector_path p = curve_path(f, l);
    if (l.point) {
      const grid_point q = p.rings[0][0];
      if (!coverage.covers({q.x, q.y})) curve_paths.push_back(std::move(p));
      return;
    }
    const cl::Paths parts =
        coverage.outside({{p.rings[0][0].x, p.rings[0][0].y}, {p.rings[0][1].x, p.rings[0][1].y}});
    p.rings.clear();
    for (const cl::Path& part : parts)
      if (part.size() >= 2) p.rings.push_back(to_ring(part));
    if (!p.rings.empty()) curve_paths.push_back(std::move(p));
  };
  std::size_t next_line = f.lines.size();  // lines are sorted by slot; taken from the back
  // Snap every polygon to the grid (counter-clockwise), then mend T-junctions.
  std::vector<cl::Path> snapped(f.polygons.size());
  for (std::size_t k = 0; k < f.polygons.size(); ++k) {
    cl::Path& poly = snapped[k];
    for (const window_point& w : f.polygons[k].v) {
      const cl::IntPoint q = grid_of(vp, w);
      if (poly.empty() || !(poly.back() == q)) poly.push_back(q);
    }
    while (poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();
    if (poly.size() < 3 || cl::Area(poly) == 0) {  // seen edge-on: no area
      poly.clear();
      continue;
    }
    if (!cl::Orientation(poly)) cl::ReversePath(poly);
  }
  t_junction_mender mender(snapped);
  cl::Paths visible;
  for (std::size_t k = f.polygons.size(); k-- > 0;) {
    // Lines of slot k + 1 lie behind polygons k + 1 .. n - 1: clip them now.
    while (next_line > 0 && f.lines[next_line - 1].slot > k) clip_line(f.lines[--next_line]);
    const screen_polygon& p = f.polygons[k];
    cl::Path& poly = snapped[k];
    if (poly.empty() || coverage.hides(poly)) continue;
    mender.mend(poly);
    visible.clear();
    coverage.add(poly, visible);
    if (visible.empty()) continue;
    face_accumulator& acc = faces[p.face];
    if (!acc.seen) {
      acc.seen = true;
      acc.color = p.color;
    }
    for (const window_point& w : p.v) {
      acc.sx += w.x;
      acc.sy += w.y;
      acc.sz += w.z;
      ++acc.n;
    }
    acc.pieces.insert(acc.pieces.end(), visible.begin(), visible.end());
  }
  while (next_line > 0) clip_line(f.lines[--next_line]);

  // One region per face: the union of its pieces, rounding slivers dropped.
  std::vector<std::uint32_t> face_ids;
  face_ids.reserve(faces.size());
  for (const auto& [face, acc] : faces) face_ids.push_back(face);
  std::sort(face_ids.begin(), face_ids.end(), [&](std::uint32_t a, std::uint32_t b) {
    const std::uint32_t ma = mesh_of(f, a), mb = mesh_of(f, b);
    return ma != mb ? ma < mb : a < b;
  });
  std::vector<vector_path> regions;
  regions.reserve(face_ids.size());
  cl::Clipper clipper;
  cl::Paths merged;
  for (std::uint32_t face : face_ids) {
    face_accumulator& acc = faces[face];
    clipper.Clear();
    clipper.AddPaths(acc.pieces, cl::ptSubject, true);
    merged.clear();
    clipper.Execute(cl::ctUnion, merged, cl::pftNonZero, cl::pftNonZero);
    vector_path r;
    r.kind = vector_path::kind_type::region;
    r.face = face;
    r.mesh = mesh_of(f, face);
    const double n = static_cast<double>(acc.n);
    r.color = shaded(f, acc.color, acc.sx / n, acc.sy / n, acc.sz / n);
    for (cl::Path& ring : merged) {
      remove_spikes(ring);
      if (ring.size() >= 3 && mean_width(ring) >= min_region_width)
        r.rings.push_back(to_ring(ring));
    }
    if (!r.rings.empty()) regions.push_back(std::move(r));
  }
  // Underlays: the union of the regions of each colour used more than once.
  std::map<std::array<std::uint8_t, 3>, std::vector<std::size_t>> by_color;
  for (std::size_t k = 0; k < regions.size(); ++k)
    by_color[{regions[k].color.r, regions[k].color.g, regions[k].color.b}].push_back(k);
  for (const auto& [rgb, members] : by_color) {
    if (members.size() < 2) continue;
    clipper.Clear();
    for (std::size_t k : members)
      for (const auto& ring : regions[k].rings) {
        cl::Path p;
        p.reserve(ring.size());
        for (const grid_point& q : ring) p.push_back({q.x, q.y});
        clipper.AddPath(p, cl::ptSubject, true);
      }
    merged.clear();
    clipper.Execute(cl::ctUnion, merged, cl::pftNonZero, cl::pftNonZero);
    vector_path u;
    u.kind = vector_path::kind_type::underlay;
    u.color = regions[members[0]].color;
    for (cl::Path& ring : merged) {
      remove_spikes(ring);
      if (ring.size() >= 3) u.rings.push_back(to_ring(ring));
    }
    if (!u.rings.empty()) d.paths.push_back(std::move(u));
  }
  d.paths.insert(d.paths.end(), regions.begin(), regions.end());
  if (opt.edges != vector_options::edges_kind::none) add_edges(f, regions, d);
  // Curve pieces were clipped front to back: put them back in back-to-front order.
  for (auto it = curve_paths.rbegin(); it != curve_paths.rend(); ++it)
    append_curve(d, std::move(*it));
  return d;
}

vector_drawing painter_drawing(const frame& f) {
  const viewport& vp = f.view.vp;
  vector_drawing d = empty_drawing(f);
  d.painter = true;
  std::size_t next_line = 0;
  for (std::size_t k = 0; k <= f.polygons.size(); ++k) {
    while (next_line < f.lines.size() && f.lines[next_line].slot <= k)
      append_curve(d, curve_path(f, f.lines[next_line++]));
    if (k == f.polygons.size()) break;
    const screen_polygon& p = f.polygons[k];
    vector_path r;
    r.kind = vector_path::kind_type::region;
    r.face = p.face;
    r.fragment = p.fragment;
    r.mesh = mesh_of(f, p.face);
    double sx = 0, sy = 0, sz = 0;
    std::vector<grid_point> ring;
    for (const window_point& w : p.v) {
      sx += w.x;
      sy += w.y;
      sz += w.z;
      const cl::IntPoint q = grid_of(vp, w);
      ring.push_back({q.X, q.Y});
    }
    const double n = static_cast<double>(p.v.size());
    r.color = shaded(f, p.color, sx / n, sy / n, sz / n);
    r.rings.push_back(std::move(ring));
    d.paths.push_back(std::move(r));
  }
  return d;
}

}  // namespace exbsp::view
