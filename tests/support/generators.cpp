// SPDX-License-Identifier: LGPL-3.0-or-later
// RapidCheck generators of triangle soups and the CAD corpus cases; what each generator is
// for: tests/HARD_CASES.md, declarations and notation in generators.h.
#include "support/generators.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include <exbsp/mesh/mesh_io.h>
#include "support/inputs.h"
#include "support/test_helpers.h"

namespace exbsp_test {

exbsp::triangle_soup soup_case::soup() const {
  exbsp::triangle_soup s;
  s.source = kind;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const auto base = static_cast<std::uint32_t>(s.vertices.size());
    for (const vec3d& p : tris[i]) s.vertices.push_back(p);
    s.add_polygon({base, base + 1, base + 2}, face_of(i));
  }
  return s;
}

std::string to_off(const soup_case& c) { return off_text(c.soup()); }

void showValue(const soup_case& c, std::ostream& os) {
  os << c.kind << " (" << c.tris.size() << " triangles)\n" << to_off(c);
  if (!c.faces.empty()) {
    os << "face ids:";
    for (std::uint32_t f : c.faces) os << " " << f;
    os << "\n";
  }
}

namespace {

/// A plane with an exact integer parametrisation o + a u + b v (+ w n off the plane, n = u x v):
/// for small integers and halves a, b, w every point is an exact double.
struct lattice_plane {
  vec3d o, u, v;
  vec3d n() const { return cross(u, v); }
  vec3d at(double a, double b, double w = 0) const {
    return add(add(o, add(scale(a, u), scale(b, v))), scale(w, n()));
  }
};

lattice_plane pick_lattice_plane() {
  const double h = pick_half(-2, 2);
  switch (pick_int(0, 4)) {
    case 0:
      return {{0, 0, h}, {1, 0, 0}, {0, 1, 0}};  // z = h
    case 1:
      return {{h, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // x = h
    case 2:
      return {{0, 0, h}, {1, 0, -1}, {0, 1, -1}};  // x + y + z = h
    case 3:
      return {{h, h, 0}, {1, 1, 0}, {0, 0, 1}};  // x = y, shifted
    default: {
      lattice_plane p{{static_cast<double>(pick_int(-2, 2)), static_cast<double>(pick_int(-2, 2)),
                       static_cast<double>(pick_int(-2, 2))},
                      {static_cast<double>(pick_int(-2, 2)), static_cast<double>(pick_int(-2, 2)),
                       static_cast<double>(pick_int(-2, 2))},
                      {static_cast<double>(pick_int(-2, 2)), static_cast<double>(pick_int(-2, 2)),
                       static_cast<double>(pick_int(-2, 2))}};
      const vec3d n = p.n();
      if (n[0] == 0 && n[1] == 0 && n[2] == 0) return {{0, h, 0}, {0, 0, 1}, {1, 0, 0}};  // y = h
      return p;
    }
  }
}

/// A rigid motion of a soup: exact (axis permutation, reflections, power-of-two scale: every
/// coincidence survives) or rounded (random rotation from a quaternion and a translation, in
/// double: flat regions become near-coplanar).
void apply_picked_motion(soup_case& c) {
  const int kind = pick_int(0, 2);
  if (kind == 0) return;
  if (kind == 1) {
    std::array<int, 3> perm{0, 1, 2};
    for (int i = 2; i > 0; --i)
      std::swap(perm[static_cast<std::size_t>(i)], perm[static_cast<std::size_t>(pick_int(0, i))]);
    const vec3d sign{pick_bool() ? 1.0 : -1.0, pick_bool() ? 1.0 : -1.0, pick_bool() ? 1.0 : -1.0};
    const double s = std::ldexp(1.0, pick_int(-4, 4));
    for (tri_d& t : c.tris)
      for (vec3d& p : t) {
        const vec3d q = p;
        for (int k = 0; k < 3; ++k)
          p[static_cast<std::size_t>(k)] =
              s * sign[static_cast<std::size_t>(k)] *
              q[static_cast<std::size_t>(perm[static_cast<std::size_t>(k)])];
      }
    c.kind += " (exact motion)";
    return;
  }
  double w = pick_real(-1, 1), x = pick_real(-1, 1), y = pick_real(-1, 1), z = pick_real(-1, 1);
  const double norm = std::sqrt(w * w + x * x + y * y + z * z);
  if (norm < 1e-3)
    w = 1, x = y = z = 0;
  else
    w /= norm, x /= norm, y /= norm, z /= norm;
  const double R[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                          {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                          {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
  const vec3d shift = pick_point(-10, 10);
  for (tri_d& t : c.tris)
    for (vec3d& p : t) {
      const vec3d q = p;
      for (int k = 0; k < 3; ++k)
        p[static_cast<std::size_t>(k)] =
            R[k][0] * q[0] + R[k][1] * q[1] + R[k][2] * q[2] + shift[static_cast<std::size_t>(k)];
    }
  c.kind += " (rounded rotation)";
}

std::vector<tri_d> triangles_of(const exbsp::triangle_soup& s) {
  std::vector<tri_d> out;
  out.reserve(s.triangles.size());
  for (const auto& t : s.triangles)
    out.push_back({s.vertices[t.v[0]], s.vertices[t.v[1]], s.vertices[t.v[2]]});
  return out;
}

/// A generator of soups of kind `name`: fill(tris) picks the triangles, which are then
/// shuffled (so that no case depends on the order the generator wrote them in).
template <class Fill>
rc::Gen<soup_case> shuffled_soup(const char* name, Fill fill) {
  return rc::gen::exec([name, fill] {
    soup_case c{name, {}, {}};
    fill(c.tris);
    shuffle_picked(c.tris);
    return c;
  });
}

}  // namespace

/// Generic random soups: 1..max_triangles triangles with 52-bit random coordinates in [-10,10].
rc::Gen<soup_case> random_soup(int max_triangles) {
  return rc::gen::exec([max_triangles] {
    soup_case c{"random_soup", {}, {}};
    const int n = pick_int(1, max_triangles);
    for (int i = 0; i < n; ++i)
      c.tris.push_back({pick_point(-10, 10), pick_point(-10, 10), pick_point(-10, 10)});
    return c;
  });
}

/// Soups on the 5x5x5 lattice {-1, -0.5, 0, 0.5, 1}^3: exact coincidences of every kind
/// (shared vertices and edges, vertices on planes, coplanar and collinear triangles).
rc::Gen<soup_case> grid_soup(int max_triangles) {
  return rc::gen::exec([max_triangles] {
    soup_case c{"grid_soup", {}, {}};
    const int n = pick_int(2, max_triangles);
    auto p = [] { return vec3d{pick_half(-1, 1), pick_half(-1, 1), pick_half(-1, 1)}; };
    for (int i = 0; i < n; ++i) c.tris.push_back({p(), p(), p()});
    return c;
  });
}

/// Many overlapping coplanar triangles in both orientations (with exact duplicates and
/// reversed copies) on one lattice plane, and crossers: straddling ones, ones with a vertex
/// exactly on the plane (two-piece splits), ones touching it with a vertex or an edge, and
/// parallel ones. Shuffled, so the splitter is sometimes a crosser, sometimes a stack triangle.
rc::Gen<soup_case> coplanar_stack() {
  return shuffled_soup("coplanar_stack", [](std::vector<tri_d>& tris) {
    const lattice_plane pl = pick_lattice_plane();
    auto on = [&] { return pl.at(pick_half(-2, 2), pick_half(-2, 2)); };
    const int m = pick_int(2, 7);
    std::vector<tri_d> stack;
    for (int i = 0; i < m; ++i) {
      tri_d t{on(), on(), on()};
      if (pick_bool()) t = flipped(t);
      stack.push_back(t);
    }
    const int copies = pick_int(0, 2);
    for (int i = 0; i < copies; ++i) {
      const tri_d& t = stack[static_cast<std::size_t>(pick_int(0, m - 1))];
      stack.push_back(pick_bool() ? t : flipped(t));
    }
    tris = stack;
    const int crossers = pick_int(1, 4);
    for (int i = 0; i < crossers; ++i) {
      auto off = [&](double w) { return pl.at(pick_half(-2, 2), pick_half(-2, 2), w); };
      auto w_pos = [] { return pick_int(1, 4) / 2.0; };
      tri_d t;
      switch (pick_int(0, 5)) {
        case 0:
          t = {off(w_pos()), off(-w_pos()), off(pick_bool() ? w_pos() : -w_pos())};
          break;  // straddles
        case 1:
          t = {off(0), off(w_pos()), off(-w_pos())};
          break;  // vertex on the plane, 2 pieces
        case 2:
          t = {off(0), off(w_pos()), off(w_pos())};
          break;  // touches with a vertex
        case 3:
          t = {off(0), off(0), off(-w_pos())};
          break;  // touches with an edge
        case 4: {
          const double w = w_pos();
          t = {off(w), off(w), off(w)};
          break;
        }  // parallel
        default:
          t = {off(pick_half(-2, 2)), off(pick_half(-2, 2)), off(pick_half(-2, 2))};
          break;
      }
      for (int k = pick_int(0, 2); k > 0; --k) t = {t[1], t[2], t[0]};  // vertex on plane anywhere
      tris.push_back(t);
    }
  });
}

/// Vertices exactly on other triangles' planes: three axis planes x = hx, y = hy, z = hz and
/// one sloped lattice plane, each carrying a large triangle; the other triangles' coordinates
/// are each hx/hy/hz with probability 1/2, so vertices lie on 0..3 planes (on their lines of
/// intersection and at their common point), and some vertices lie exactly on the sloped plane.
rc::Gen<soup_case> vertex_on_plane() {
  return shuffled_soup("vertex_on_plane", [](std::vector<tri_d>& tris) {
    const vec3d h{pick_half(-1, 1), pick_half(-1, 1), pick_half(-1, 1)};
    for (int axis = 0; axis < 3; ++axis) {
      if (pick_int(0, 3) == 0) continue;
      const int i = (axis + 1) % 3, j = (axis + 2) % 3;
      tri_d t;
      const double corner[3][2] = {{-3, -3}, {3, -2}, {-1, 3}};
      for (int k = 0; k < 3; ++k) {
        t[k][axis] = h[axis];
        t[k][i] = corner[k][0];
        t[k][j] = corner[k][1];
      }
      tris.push_back(pick_bool() ? t : flipped(t));
    }
    const lattice_plane sloped = pick_lattice_plane();
    tris.push_back({sloped.at(-2, -2), sloped.at(2, -1), sloped.at(-1, 2)});
    const int n = pick_int(1, 6);
    for (int i = 0; i < n; ++i) {
      tri_d t;
      for (vec3d& p : t) {
        if (pick_int(0, 3) == 0) {
          p = sloped.at(pick_half(-2, 2), pick_half(-2, 2));
        } else {
          for (int k = 0; k < 3; ++k) p[k] = pick_bool() ? h[k] : pick_half(-3, 3);
        }
      }
      tris.push_back(t);
    }
  });
}

/// Near-coplanar triangles: a plane z = h, x = h or y = x (h from 0, 0.1, 1e-3, 1e5 + r,
/// 1e-200 or random), triangles exactly in it, and triangles whose vertices are 0, 1 or 2
/// ulps off it on either side (nextafter on the coordinate that defines the plane; for h = 0
/// that is a subnormal, 4.9e-324).
rc::Gen<soup_case> near_coplanar() {
  return shuffled_soup("near_coplanar", [](std::vector<tri_d>& tris) {
    double h = 0;
    switch (pick_int(0, 5)) {
      case 0:
        h = 0;
        break;
      case 1:
        h = 0.1;
        break;
      case 2:
        h = -1e-3;
        break;
      case 3:
        h = 1e5 + pick_real(0, 1);
        break;
      case 4:
        h = 1e-200;
        break;
      default:
        h = pick_real(-1, 1);
        break;
    }
    const int kind = pick_int(0, 2);  // 0: z = h, 1: x = h, 2: y = x
    auto point = [&](int ulps) {
      const double a = pick_real(-1, 1), b = pick_real(-1, 1);
      switch (kind) {
        case 0:
          return vec3d{a, b, ulps_from(h, ulps)};
        case 1:
          return vec3d{ulps_from(h, ulps), a, b};
        default:
          return vec3d{a, ulps_from(a, ulps), b};
      }
    };
    const int exact = pick_int(1, 3);
    for (int i = 0; i < exact; ++i) tris.push_back({point(0), point(0), point(0)});
    const int near = pick_int(1, 5);
    for (int i = 0; i < near; ++i) {
      tri_d t;
      for (vec3d& p : t) p = point(pick_int(-2, 2));
      tris.push_back(t);
    }
  });
}

/// Scale disparity: (0) coordinates near 1e9 with features near 1e-3 and huge triangles
/// (extent 1e9) through the cluster, some exactly in an axis plane of the cluster;
/// (1) all coordinates near 1e-300 (products underflow in double); (2) unit triangles through
/// the origin with tiny (1e-300) triangles crossing them.
rc::Gen<soup_case> scale_disparity() {
  return shuffled_soup("scale_disparity", [](std::vector<tri_d>& tris) {
    const int mode = pick_int(0, 2);
    if (mode == 0) {
      const vec3d centre{1e9 * (1 + pick_real(0, 1)), -1e9 * (1 + pick_real(0, 1)),
                         1e9 * pick_real(0.5, 1)};
      auto feature = [&] { return add(centre, pick_point(-1e-3, 1e-3)); };
      const int n = pick_int(2, 6);
      for (int i = 0; i < n; ++i) tris.push_back({feature(), feature(), feature()});
      // A huge triangle in the plane z = centre.z, and a huge generic one.
      tris.push_back({vec3d{centre[0] - 1e9, centre[1] - 1e9, centre[2]},
                      vec3d{centre[0] + 1e9, centre[1], centre[2]},
                      vec3d{centre[0], centre[1] + 1e9, centre[2]}});
      if (pick_bool()) {
        vec3d a = feature();
        a[2] = centre[2];  // a feature vertex exactly in the huge plane
        tris.push_back({a, feature(), feature()});
      }
      if (pick_bool())
        tris.push_back(
            {add(centre, pick_point(-1e9, 1e9)), add(centre, pick_point(-1e9, 1e9)), feature()});
    } else if (mode == 1) {
      const int n = pick_int(2, 6);
      for (int i = 0; i < n; ++i)
        tris.push_back({scale(1e-300, pick_point(-1, 1)), scale(1e-300, pick_point(-1, 1)),
                        scale(1e-300, pick_point(-1, 1))});
    } else {
      tris.push_back({vec3d{-1, -1, 0}, vec3d{1, -1, 0}, vec3d{0, 1, 0}});
      if (pick_bool()) tris.push_back({pick_point(-1, 1), pick_point(-1, 1), pick_point(-1, 1)});
      const int n = pick_int(1, 4);
      for (int i = 0; i < n; ++i)
        tris.push_back({scale(1e-300, pick_point(-1, 1)), scale(1e-300, pick_point(-1, 1)),
                        scale(1e-300, pick_point(-1, 1))});
    }
  });
}

/// Slivers: needles (an angle near 0), caps (an angle near 180 degrees) and thin isosceles
/// triangles with relative widths 1e-3 .. 1e-15, crossing each other and generic triangles;
/// sometimes an exactly collinear triangle (skipped and counted).
rc::Gen<soup_case> slivers() {
  return shuffled_soup("slivers", [](std::vector<tri_d>& tris) {
    const int n = pick_int(2, 6);
    for (int i = 0; i < n; ++i) {
      const vec3d a = pick_point(-2, 2), u = pick_point(-3, 3), v = pick_point(-1, 1);
      const double eps = std::pow(10.0, -3 * pick_int(1, 5));
      switch (pick_int(0, 2)) {
        case 0:
          tris.push_back({a, add(a, u), add(add(a, u), scale(eps, v))});
          break;  // needle
        case 1:
          tris.push_back({a, add(a, u), add(add(a, scale(0.5, u)), scale(eps, v))});
          break;  // cap
        default:
          tris.push_back({a, add(add(a, u), scale(eps, v)), sub(add(a, u), scale(eps, v))});
          break;
      }
    }
    if (pick_int(0, 3) == 0) tris.push_back({vec3d{0, 0, 0}, vec3d{1, 2, 3}, vec3d{2, 4, 6}});
    const int crossers = pick_int(0, 3);
    for (int i = 0; i < crossers; ++i)
      tris.push_back({pick_point(-3, 3), pick_point(-3, 3), pick_point(-3, 3)});
  });
}

/// Mesh-like soups: a consistently oriented integer height field (shared edges), with
/// T-junctions (a triangle split at an edge midpoint while its neighbour keeps the edge),
/// exact duplicates, reversed copies (the same triangle in both orientations), sometimes a
/// second sheet crossing it and lattice crossers.
rc::Gen<soup_case> mesh_like() {
  return shuffled_soup("mesh_like", [](std::vector<tri_d>& tris) {
    const int n = pick_int(1, 3);
    std::vector<std::vector<double>> h(static_cast<std::size_t>(n + 1),
                                       std::vector<double>(static_cast<std::size_t>(n + 1)));
    for (auto& row : h)
      for (double& z : row) z = pick_int(-1, 1);
    auto P = [&](int i, int j) {
      return vec3d{static_cast<double>(i), static_cast<double>(j),
                   h[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]};
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        if (pick_bool()) {
          tris.push_back({P(i, j), P(i + 1, j), P(i + 1, j + 1)});
          tris.push_back({P(i, j), P(i + 1, j + 1), P(i, j + 1)});
        } else {
          tris.push_back({P(i, j), P(i + 1, j), P(i, j + 1)});
          tris.push_back({P(i + 1, j), P(i + 1, j + 1), P(i, j + 1)});
        }
      }
    for (int k = pick_int(0, 2); k > 0; --k) {  // T-junctions
      const std::size_t t =
          static_cast<std::size_t>(pick_int(0, static_cast<int>(tris.size()) - 1));
      const int e = pick_int(0, 2);
      const tri_d o = tris[t];
      const vec3d& a = o[static_cast<std::size_t>(e)];
      const vec3d& b = o[static_cast<std::size_t>((e + 1) % 3)];
      const vec3d& d = o[static_cast<std::size_t>((e + 2) % 3)];
      const vec3d m = scale(0.5, add(a, b));
      tris[t] = {a, m, d};
      tris.push_back({m, b, d});
    }
    for (int k = pick_int(0, 2); k > 0; --k)
      tris.push_back(
          tris[static_cast<std::size_t>(pick_int(0, static_cast<int>(tris.size()) - 1))]);
    for (int k = pick_int(0, 2); k > 0; --k)
      tris.push_back(
          flipped(tris[static_cast<std::size_t>(pick_int(0, static_cast<int>(tris.size()) - 1))]));
    if (pick_bool()) {  // a second sheet, roughly the plane y = 0.5 + x/2, crossing the first
      for (int i = 0; i < n; ++i) {
        const double y0 = 0.5 + i / 2.0, y1 = 0.5 + (i + 1) / 2.0;
        tris.push_back({vec3d{double(i), y0, -1.5}, vec3d{double(i + 1), y1, -1.5},
                        vec3d{double(i), y0, 1.5}});
      }
    }
    for (int k = pick_int(0, 2); k > 0; --k) {
      auto p = [&] { return vec3d{pick_half(-1, n + 1), pick_half(-1, n + 1), pick_half(-2, 2)}; };
      tris.push_back({p(), p(), p()});
    }
  });
}

/// Cyclic overlaps: n sticks (long thin triangles) tangent to a circle of radius r around the
/// z axis, each rising along its own direction (a pinwheel). Seen from above, stick k is over
/// the next sticks counter-clockwise where they cross, so consecutive sticks form a cycle and
/// no order of whole triangles draws them correctly (test_degenerate verifies this exactly).
rc::Gen<soup_case> cyclic_sticks(int min_n, int max_n) {
  return rc::gen::exec([min_n, max_n] {
    soup_case c{"cyclic_sticks", {}, {}};
    const int n = pick_int(min_n, max_n);
    const double r = pick_real(0.5, 1.5), len = pick_real(4, 6), width = pick_real(0.1, 0.35);
    const double tau = 6.283185307179586;
    for (int k = 0; k < n; ++k) {
      const double phi = tau * k / n + pick_real(-0.15, 0.15) * tau / n;
      const double slope = pick_real(0.1, 1);
      const vec3d radial{std::cos(phi), std::sin(phi), 0}, along{-std::sin(phi), std::cos(phi), 0};
      const vec3d touch = scale(r, radial);
      const vec3d tail = add(touch, scale(-len, along)), tip = add(touch, scale(len, along));
      c.tris.push_back({add(tail, scale(width, radial)), sub(tail, scale(width, radial)),
                        vec3d{tip[0], tip[1], 2 * len * slope}});
    }
    return c;
  });
}

/// Every small generator above (not the sticks): for properties that hold for any soup.
rc::Gen<soup_case> any_small_soup() {
  return rc::gen::oneOf(random_soup(), grid_soup(), coplanar_stack(), vertex_on_plane(),
                        near_coplanar(), scale_disparity(), slivers(), mesh_like());
}

/// The triangles and face ids of data/meshes/NAME (read once), or nullptr if it is missing.
const soup_case* cad_mesh(const std::string& name) {
  static std::map<std::string, std::unique_ptr<soup_case>> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    std::unique_ptr<soup_case> c;
    if (std::ifstream(corpus_dir() + name).good()) {
      const exbsp::triangle_soup s = exbsp::read_mesh(corpus_dir() + name);
      c = std::make_unique<soup_case>();
      c->kind = name;
      c->tris = triangles_of(s);
      for (const auto& t : s.triangles) c->faces.push_back(t.face);
    }
    it = cache.emplace(name, std::move(c)).first;
  }
  return it->second.get();
}

/// The CAD meshes of the corpus used by the subset generators, those present.
std::vector<std::string> present_cad_meshes() {
  std::vector<std::string> out;
  for (const char* name : {"fandisk.off", "part.off", "couplingdown.off", "rotor.off",
                           "ALSTOM_TEST4.off", "anchor.off"})
    if (cad_mesh(name)) out.push_back(name);
  return out;
}

/// A contiguous run of at most max_triangles triangles of one of `files` (all present),
/// with a random rigid motion. Face ids are the file's.
rc::Gen<soup_case> cad_subset(std::vector<std::string> files, std::size_t max_triangles) {
  return rc::gen::exec([files, max_triangles] {
    const std::string name = *rc::gen::elementOf(files);
    const soup_case& mesh = *cad_mesh(name);
    const std::size_t count = std::min(max_triangles, mesh.tris.size());
    const std::size_t start = *rc::gen::inRange<std::size_t>(0, mesh.tris.size() - count + 1);
    soup_case c;
    c.kind = name + " [" + std::to_string(start) + ", " + std::to_string(start + count) + ")";
    c.tris.assign(mesh.tris.begin() + static_cast<std::ptrdiff_t>(start),
                  mesh.tris.begin() + static_cast<std::ptrdiff_t>(start + count));
    c.faces.assign(mesh.faces.begin() + static_cast<std::ptrdiff_t>(start),
                   mesh.faces.begin() + static_cast<std::ptrdiff_t>(start + count));
    apply_picked_motion(c);
    return c;
  });
}

template <class K>
check_report build_and_check(const soup_case& c, const std::string& heuristic,
                             const check_options& o, std::uint64_t build_seed) {
  const exbsp::triangle_soup soup = c.soup();
  exbsp::build_options bo;
  bo.heuristic = heuristic;
  bo.seed = build_seed;
  bo.kernel = exbsp::kernel_traits<K>::id;
  const exbsp::bsp_tree<K> t(soup, bo);
  check_options co = o;
  co.heuristic = heuristic;
  return check_tree(t, soup, co);
}

template <class K>
void rc_assert_invariants_for_every_heuristic(const soup_case& c, std::size_t max_rays,
                                              const check_options& extra) {
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  bool any_split = false;
  for (const std::string& h : exbsp::heuristic_names()) {
    const exbsp::triangle_soup soup = c.soup();
    exbsp::build_options bo;
    bo.heuristic = h;
    bo.seed = seed;
    const exbsp::bsp_tree<K> t(soup, bo);
    any_split |= t.stats().splits > 0;
    check_options o = extra;
    o.seed = seed;
    o.max_rays = max_rays;
    o.heuristic = h;
    const check_report r = check_tree(t, soup, o);
    if (!r.ok()) RC_FAIL(h + ": " + r.text());
  }
  RC_TAG(c.kind.substr(0, c.kind.find(' ')), any_split ? "splits" : "no splits");
}

#define EXBSP_GENERATORS_FOR_KERNEL(K)                                                     \
  template check_report build_and_check<K>(const soup_case&, const std::string&,           \
                                           const check_options&, std::uint64_t);           \
  template void rc_assert_invariants_for_every_heuristic<K>(const soup_case&, std::size_t, \
                                                            const check_options&);
EXBSP_GENERATORS_FOR_KERNEL(exbsp::double_kernel)
EXBSP_GENERATORS_FOR_KERNEL(exbsp::epick_kernel)
EXBSP_GENERATORS_FOR_KERNEL(exbsp::epeck_kernel)
EXBSP_GENERATORS_FOR_KERNEL(exbsp::gmpq_kernel)

}  // namespace exbsp_test
