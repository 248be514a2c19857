// Shared RapidCheck generators of triangle soups and the exact invariant checker of BSP trees,
// used by tests/test_properties.cpp and tests/test_degenerate.cpp (see tests/HARD_CASES.md for
// what each generator is for and what each invariant proves).
//
// Notation (DESIGN.md section 3): triangle (a,b,c), normal n = (b-a)x(c-a), f(p) = sign of
// orientation(a,b,c,p). A "view" is a copy of a built tree in an exact kernel E: for the exact
// kernels (Epeck, Gmpq) E is the kernel itself and nothing is converted; for the inexact ones
// (double, Epick) the rounded output is converted exactly into Epeck, so every invariant is
// always evaluated exactly and an inexact kernel "breaks" an invariant when its rounded
// fragments really violate it.
//
// Generators must be dereferenced inside a RapidCheck generation context (a property or
// rc::gen::exec); the checker never draws from RapidCheck: it takes explicit seeds, so the
// deterministic tests of test_degenerate.cpp use it too.
#pragma once
#include <rapidcheck.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "bsp/bsp_tree.h"
#include "bsp/geometry_cgal.h"
#include "bsp/engine.h"
#include "bsp/kernel_double.h"
#include "bsp/kernel_epeck.h"
#include "bsp/kernel_epick.h"
#include "bsp/kernel_gmpq.h"
#include "core/errors.h"
#include "mesh/mesh_io.h"
#include "mesh/soup.h"

namespace exbsp_test {

using exbsp::vec3d;
using tri_d = std::array<vec3d, 3>;

// ---------------------------------------------------------------------------------------------
// Soups as generated values
// ---------------------------------------------------------------------------------------------

/// A generated soup: its generator's name, the triangles (doubles, the exact input) and
/// optional face ids (empty: face id = triangle index).
struct soup_case {
  std::string kind;
  std::vector<tri_d> tris;
  std::vector<std::uint32_t> faces;

  std::uint32_t face_of(std::size_t i) const {
    return faces.empty() ? static_cast<std::uint32_t>(i) : faces[i];
  }
  exbsp::triangle_soup soup() const {
    exbsp::triangle_soup s;
    s.source = kind;
    for (std::size_t i = 0; i < tris.size(); ++i) {
      const auto base = static_cast<std::uint32_t>(s.vertices.size());
      for (const vec3d& p : tris[i]) s.vertices.push_back(p);
      s.add_polygon({base, base + 1, base + 2}, face_of(i));
    }
    return s;
  }
};

inline std::string format_double(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// The case as an OFF file (17 significant digits: reading it back gives the same doubles).
inline std::string to_off(const soup_case& c) {
  std::ostringstream os;
  os << "OFF\n" << 3 * c.tris.size() << " " << c.tris.size() << " 0\n";
  for (const tri_d& t : c.tris)
    for (const vec3d& p : t)
      os << format_double(p[0]) << " " << format_double(p[1]) << " " << format_double(p[2]) << "\n";
  for (std::size_t i = 0; i < c.tris.size(); ++i)
    os << "3 " << 3 * i << " " << 3 * i + 1 << " " << 3 * i + 2 << "\n";
  return os.str();
}

/// How RapidCheck prints a counterexample: reproducible as an OFF file.
inline void showValue(const soup_case& c, std::ostream& os) {
  os << c.kind << " (" << c.tris.size() << " triangles)\n" << to_off(c);
  if (!c.faces.empty()) {
    os << "face ids:";
    for (std::uint32_t f : c.faces) os << " " << f;
    os << "\n";
  }
}

inline soup_case case_of(const std::string& kind, const std::vector<tri_d>& tris) {
  return soup_case{kind, tris, {}};
}

inline std::vector<tri_d> triangles_of(const exbsp::triangle_soup& s) {
  std::vector<tri_d> out;
  out.reserve(s.triangles.size());
  for (const auto& t : s.triangles)
    out.push_back({s.vertices[t.v[0]], s.vertices[t.v[1]], s.vertices[t.v[2]]});
  return out;
}

// ---------------------------------------------------------------------------------------------
// Drawing values (only inside a RapidCheck generation context)
// ---------------------------------------------------------------------------------------------

inline int pick_int(int lo, int hi) { return *rc::gen::inRange(lo, hi + 1); }
inline bool pick_bool() { return pick_int(0, 1) == 1; }
/// A double in [lo, hi] with (up to) 52 random mantissa bits: generic position.
inline double pick_real(double lo, double hi) {
  const std::int64_t k = *rc::gen::inRange<std::int64_t>(0, (std::int64_t{1} << 52) + 1);
  return lo + (hi - lo) * std::ldexp(static_cast<double>(k), -52);
}
inline vec3d pick_point(double lo, double hi) { return {pick_real(lo, hi), pick_real(lo, hi), pick_real(lo, hi)}; }
/// k/2 for an integer k in [2*lo, 2*hi]: exact, and exactly representable sums and products.
inline double pick_half(int lo, int hi) { return pick_int(2 * lo, 2 * hi) / 2.0; }

template <class T>
void shuffle_picked(std::vector<T>& v) {
  for (std::size_t i = v.size(); i > 1; --i) {
    const std::size_t j = *rc::gen::inRange<std::size_t>(0, i);
    std::swap(v[i - 1], v[j]);
  }
}

inline tri_d flipped(const tri_d& t) { return {t[0], t[2], t[1]}; }

/// x moved by k ulps (k > 0 up, k < 0 down).
inline double ulps_from(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, HUGE_VAL);
  for (; k < 0; ++k) x = std::nextafter(x, -HUGE_VAL);
  return x;
}

inline vec3d add(const vec3d& a, const vec3d& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline vec3d sub(const vec3d& a, const vec3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline vec3d scale(double s, const vec3d& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline vec3d cross_d(const vec3d& a, const vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// A plane with an exact integer parametrisation o + a u + b v (+ w n off the plane, n = u x v):
/// for small integers and halves a, b, w every point is an exact double.
struct lattice_plane {
  vec3d o, u, v;
  vec3d n() const { return cross_d(u, v); }
  vec3d at(double a, double b, double w = 0) const {
    return add(add(o, add(scale(a, u), scale(b, v))), scale(w, n()));
  }
};

inline lattice_plane pick_lattice_plane() {
  const double h = pick_half(-2, 2);
  switch (pick_int(0, 4)) {
    case 0: return {{0, 0, h}, {1, 0, 0}, {0, 1, 0}};    // z = h
    case 1: return {{h, 0, 0}, {0, 1, 0}, {0, 0, 1}};    // x = h
    case 2: return {{0, 0, h}, {1, 0, -1}, {0, 1, -1}};  // x + y + z = h
    case 3: return {{h, h, 0}, {1, 1, 0}, {0, 0, 1}};    // x = y, shifted
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

// ---------------------------------------------------------------------------------------------
// Generators
// ---------------------------------------------------------------------------------------------

/// Generic random soups: 1..max_triangles triangles with 52-bit random coordinates in [-10,10].
inline rc::Gen<soup_case> random_soup(int max_triangles = 8) {
  return rc::gen::exec([max_triangles] {
    soup_case c{"random_soup", {}, {}};
    const int n = pick_int(1, max_triangles);
    for (int i = 0; i < n; ++i) c.tris.push_back({pick_point(-10, 10), pick_point(-10, 10), pick_point(-10, 10)});
    return c;
  });
}

/// Soups on the 5x5x5 lattice {-1, -0.5, 0, 0.5, 1}^3: exact coincidences of every kind
/// (shared vertices and edges, vertices on planes, coplanar and collinear triangles).
inline rc::Gen<soup_case> grid_soup(int max_triangles = 10) {
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
inline rc::Gen<soup_case> coplanar_stack() {
  return rc::gen::exec([] {
    soup_case c{"coplanar_stack", {}, {}};
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
    c.tris = stack;
    const int crossers = pick_int(1, 4);
    for (int i = 0; i < crossers; ++i) {
      auto off = [&](double w) { return pl.at(pick_half(-2, 2), pick_half(-2, 2), w); };
      auto w_pos = [] { return pick_int(1, 4) / 2.0; };
      tri_d t;
      switch (pick_int(0, 5)) {
        case 0: t = {off(w_pos()), off(-w_pos()), off(pick_bool() ? w_pos() : -w_pos())}; break;  // straddles
        case 1: t = {off(0), off(w_pos()), off(-w_pos())}; break;  // vertex on the plane, 2 pieces
        case 2: t = {off(0), off(w_pos()), off(w_pos())}; break;   // touches with a vertex
        case 3: t = {off(0), off(0), off(-w_pos())}; break;        // touches with an edge
        case 4: { const double w = w_pos(); t = {off(w), off(w), off(w)}; break; }  // parallel
        default: t = {off(pick_half(-2, 2)), off(pick_half(-2, 2)), off(pick_half(-2, 2))}; break;
      }
      for (int k = pick_int(0, 2); k > 0; --k) t = {t[1], t[2], t[0]};  // vertex on plane anywhere
      c.tris.push_back(t);
    }
    shuffle_picked(c.tris);
    return c;
  });
}

/// Vertices exactly on other triangles' planes: three axis planes x = hx, y = hy, z = hz and
/// one sloped lattice plane, each carrying a large triangle; the other triangles' coordinates
/// are each hx/hy/hz with probability 1/2, so vertices lie on 0..3 planes (on their lines of
/// intersection and at their common point), and some vertices lie exactly on the sloped plane.
inline rc::Gen<soup_case> vertex_on_plane() {
  return rc::gen::exec([] {
    soup_case c{"vertex_on_plane", {}, {}};
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
      c.tris.push_back(pick_bool() ? t : flipped(t));
    }
    const lattice_plane sloped = pick_lattice_plane();
    c.tris.push_back({sloped.at(-2, -2), sloped.at(2, -1), sloped.at(-1, 2)});
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
      c.tris.push_back(t);
    }
    shuffle_picked(c.tris);
    return c;
  });
}

/// Near-coplanar triangles: a plane z = h, x = h or y = x (h from 0, 0.1, 1e-3, 1e5 + r,
/// 1e-200 or random), triangles exactly in it, and triangles whose vertices are 0, 1 or 2
/// ulps off it on either side (nextafter on the coordinate that defines the plane; for h = 0
/// that is a subnormal, 4.9e-324).
inline rc::Gen<soup_case> near_coplanar() {
  return rc::gen::exec([] {
    soup_case c{"near_coplanar", {}, {}};
    double h = 0;
    switch (pick_int(0, 5)) {
      case 0: h = 0; break;
      case 1: h = 0.1; break;
      case 2: h = -1e-3; break;
      case 3: h = 1e5 + pick_real(0, 1); break;
      case 4: h = 1e-200; break;
      default: h = pick_real(-1, 1); break;
    }
    const int kind = pick_int(0, 2);  // 0: z = h, 1: x = h, 2: y = x
    auto point = [&](int ulps) {
      const double a = pick_real(-1, 1), b = pick_real(-1, 1);
      switch (kind) {
        case 0: return vec3d{a, b, ulps_from(h, ulps)};
        case 1: return vec3d{ulps_from(h, ulps), a, b};
        default: return vec3d{a, ulps_from(a, ulps), b};
      }
    };
    const int exact = pick_int(1, 3);
    for (int i = 0; i < exact; ++i) c.tris.push_back({point(0), point(0), point(0)});
    const int near = pick_int(1, 5);
    for (int i = 0; i < near; ++i) {
      tri_d t;
      for (vec3d& p : t) p = point(pick_int(-2, 2));
      c.tris.push_back(t);
    }
    shuffle_picked(c.tris);
    return c;
  });
}

/// Scale disparity: (0) coordinates near 1e9 with features near 1e-3 and huge triangles
/// (extent 1e9) through the cluster, some exactly in an axis plane of the cluster;
/// (1) all coordinates near 1e-300 (products underflow in double); (2) unit triangles through
/// the origin with tiny (1e-300) triangles crossing them.
inline rc::Gen<soup_case> scale_disparity() {
  return rc::gen::exec([] {
    soup_case c{"scale_disparity", {}, {}};
    const int mode = pick_int(0, 2);
    if (mode == 0) {
      const vec3d centre{1e9 * (1 + pick_real(0, 1)), -1e9 * (1 + pick_real(0, 1)), 1e9 * pick_real(0.5, 1)};
      auto feature = [&] { return add(centre, pick_point(-1e-3, 1e-3)); };
      const int n = pick_int(2, 6);
      for (int i = 0; i < n; ++i) c.tris.push_back({feature(), feature(), feature()});
      // A huge triangle in the plane z = centre.z, and a huge generic one.
      c.tris.push_back({vec3d{centre[0] - 1e9, centre[1] - 1e9, centre[2]}, vec3d{centre[0] + 1e9, centre[1], centre[2]},
                        vec3d{centre[0], centre[1] + 1e9, centre[2]}});
      if (pick_bool()) {
        vec3d a = feature();
        a[2] = centre[2];  // a feature vertex exactly in the huge plane
        c.tris.push_back({a, feature(), feature()});
      }
      if (pick_bool())
        c.tris.push_back({add(centre, pick_point(-1e9, 1e9)), add(centre, pick_point(-1e9, 1e9)), feature()});
    } else if (mode == 1) {
      const int n = pick_int(2, 6);
      for (int i = 0; i < n; ++i)
        c.tris.push_back({scale(1e-300, pick_point(-1, 1)), scale(1e-300, pick_point(-1, 1)),
                          scale(1e-300, pick_point(-1, 1))});
    } else {
      c.tris.push_back({vec3d{-1, -1, 0}, vec3d{1, -1, 0}, vec3d{0, 1, 0}});
      if (pick_bool()) c.tris.push_back({pick_point(-1, 1), pick_point(-1, 1), pick_point(-1, 1)});
      const int n = pick_int(1, 4);
      for (int i = 0; i < n; ++i)
        c.tris.push_back({scale(1e-300, pick_point(-1, 1)), scale(1e-300, pick_point(-1, 1)),
                          scale(1e-300, pick_point(-1, 1))});
    }
    shuffle_picked(c.tris);
    return c;
  });
}

/// Slivers: needles (an angle near 0), caps (an angle near 180 degrees) and thin isosceles
/// triangles with relative widths 1e-3 .. 1e-15, crossing each other and generic triangles;
/// sometimes an exactly collinear triangle (skipped and counted).
inline rc::Gen<soup_case> slivers() {
  return rc::gen::exec([] {
    soup_case c{"slivers", {}, {}};
    const int n = pick_int(2, 6);
    for (int i = 0; i < n; ++i) {
      const vec3d a = pick_point(-2, 2), u = pick_point(-3, 3), v = pick_point(-1, 1);
      const double eps = std::pow(10.0, -3 * pick_int(1, 5));
      switch (pick_int(0, 2)) {
        case 0: c.tris.push_back({a, add(a, u), add(add(a, u), scale(eps, v))}); break;    // needle
        case 1: c.tris.push_back({a, add(a, u), add(add(a, scale(0.5, u)), scale(eps, v))}); break;  // cap
        default: c.tris.push_back({a, add(add(a, u), scale(eps, v)), sub(add(a, u), scale(eps, v))}); break;
      }
    }
    if (pick_int(0, 3) == 0) c.tris.push_back({vec3d{0, 0, 0}, vec3d{1, 2, 3}, vec3d{2, 4, 6}});
    const int crossers = pick_int(0, 3);
    for (int i = 0; i < crossers; ++i) c.tris.push_back({pick_point(-3, 3), pick_point(-3, 3), pick_point(-3, 3)});
    shuffle_picked(c.tris);
    return c;
  });
}

/// Mesh-like soups: a consistently oriented integer height field (shared edges), with
/// T-junctions (a triangle split at an edge midpoint while its neighbour keeps the edge),
/// exact duplicates, reversed copies (the same triangle in both orientations), sometimes a
/// second sheet crossing it and lattice crossers.
inline rc::Gen<soup_case> mesh_like() {
  return rc::gen::exec([] {
    soup_case c{"mesh_like", {}, {}};
    const int n = pick_int(1, 3);
    std::vector<std::vector<double>> h(static_cast<std::size_t>(n + 1), std::vector<double>(static_cast<std::size_t>(n + 1)));
    for (auto& row : h)
      for (double& z : row) z = pick_int(-1, 1);
    auto P = [&](int i, int j) {
      return vec3d{static_cast<double>(i), static_cast<double>(j), h[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]};
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        if (pick_bool()) {
          c.tris.push_back({P(i, j), P(i + 1, j), P(i + 1, j + 1)});
          c.tris.push_back({P(i, j), P(i + 1, j + 1), P(i, j + 1)});
        } else {
          c.tris.push_back({P(i, j), P(i + 1, j), P(i, j + 1)});
          c.tris.push_back({P(i + 1, j), P(i + 1, j + 1), P(i, j + 1)});
        }
      }
    for (int k = pick_int(0, 2); k > 0; --k) {  // T-junctions
      const std::size_t t = static_cast<std::size_t>(pick_int(0, static_cast<int>(c.tris.size()) - 1));
      const int e = pick_int(0, 2);
      const tri_d o = c.tris[t];
      const vec3d& a = o[static_cast<std::size_t>(e)];
      const vec3d& b = o[static_cast<std::size_t>((e + 1) % 3)];
      const vec3d& d = o[static_cast<std::size_t>((e + 2) % 3)];
      const vec3d m = scale(0.5, add(a, b));
      c.tris[t] = {a, m, d};
      c.tris.push_back({m, b, d});
    }
    for (int k = pick_int(0, 2); k > 0; --k)
      c.tris.push_back(c.tris[static_cast<std::size_t>(pick_int(0, static_cast<int>(c.tris.size()) - 1))]);
    for (int k = pick_int(0, 2); k > 0; --k)
      c.tris.push_back(flipped(c.tris[static_cast<std::size_t>(pick_int(0, static_cast<int>(c.tris.size()) - 1))]));
    if (pick_bool()) {  // a second sheet, roughly the plane y = 0.5 + x/2, crossing the first
      for (int i = 0; i < n; ++i) {
        const double y0 = 0.5 + i / 2.0, y1 = 0.5 + (i + 1) / 2.0;
        c.tris.push_back({vec3d{double(i), y0, -1.5}, vec3d{double(i + 1), y1, -1.5}, vec3d{double(i), y0, 1.5}});
      }
    }
    for (int k = pick_int(0, 2); k > 0; --k) {
      auto p = [&] { return vec3d{pick_half(-1, n + 1), pick_half(-1, n + 1), pick_half(-2, 2)}; };
      c.tris.push_back({p(), p(), p()});
    }
    shuffle_picked(c.tris);
    return c;
  });
}

/// Cyclic overlaps: n sticks (long thin triangles) tangent to a circle of radius r around the
/// z axis, each rising along its own direction (a pinwheel). Seen from above, stick k is over
/// the next sticks counter-clockwise where they cross, so consecutive sticks form a cycle and
/// no order of whole triangles draws them correctly (test_degenerate verifies this exactly).
inline rc::Gen<soup_case> cyclic_sticks(int min_n = 3, int max_n = 8) {
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
inline rc::Gen<soup_case> any_small_soup() {
  return rc::gen::oneOf(random_soup(), grid_soup(), coplanar_stack(), vertex_on_plane(), near_coplanar(),
                        scale_disparity(), slivers(), mesh_like());
}

// --- What a user observes of a tree ----------------------------------------------------------

/// Everything a user can observe of a tree, as one string: stats (no timings), exact and
/// double coordinates, ancestors, and orders for several eyes and directions.
inline std::string observable(const exbsp::bsp& t, const std::vector<vec3d>& eyes) {
  const auto& s = t.stats();
  std::string out = std::to_string(s.input_triangles) + " " + std::to_string(s.degenerate_input) + " " +
                    std::to_string(s.fragments) + " " + std::to_string(s.splits) + " " + std::to_string(s.nodes) +
                    " " + std::to_string(s.depth) + " " + s.heuristic + "\n";
  char buf[64];
  for (std::size_t i = 0; i < t.fragment_count(); ++i) {
    const auto d = t.fragment(i);
    out += std::to_string(d.face);
    for (const auto& p : t.fragment_exact(i))
      for (const auto& x : p) out += " " + x;
    for (const auto& p : d.v)
      for (double x : p) {
        std::snprintf(buf, sizeof buf, " %.17g", x);
        out += buf;
      }
    for (const auto& a : t.ancestors(i)) out += " " + std::to_string(a.plane_face) + (a.side > 0 ? "+" : "-");
    out += "\n";
  }
  for (const vec3d& e : eyes) {
    out += "eye:";
    for (const auto i : t.order_from_eye(e)) out += std::to_string(i) + ",";
    out += "\n";
    if (e == vec3d{0, 0, 0}) continue;
    out += "direction:";
    for (const auto i : t.order_for_direction(e)) out += std::to_string(i) + ",";
    out += "\n";
  }
  return out;
}

/// Eyes for a soup: fixed far points, and input vertices (eyes exactly on node planes).
inline std::vector<vec3d> eyes_for(const exbsp::triangle_soup& soup) {
  std::vector<vec3d> eyes{{0.3, -7, 11}, {-5, 2, -3}, {1, 1, 1}};
  for (std::size_t i = 0; i < soup.vertices.size() && i < 9; i += 4) eyes.push_back(soup.vertices[i]);
  return eyes;
}

// --- Real CAD meshes -------------------------------------------------------------------------

inline std::string mesh_dir() { return std::string(EXBSP_SOURCE_DIR) + "/data/meshes/"; }

/// The triangles and face ids of data/meshes/NAME (read once), or nullptr if it is missing.
inline const soup_case* cad_mesh(const std::string& name) {
  static std::map<std::string, std::unique_ptr<soup_case>> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    std::unique_ptr<soup_case> c;
    if (std::ifstream(mesh_dir() + name).good()) {
      const exbsp::triangle_soup s = exbsp::read_mesh(mesh_dir() + name);
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
inline std::vector<std::string> present_cad_meshes() {
  std::vector<std::string> out;
  for (const char* name : {"fandisk.off", "part.off", "couplingdown.off", "rotor.off", "ALSTOM_TEST4.off", "anchor.off"})
    if (cad_mesh(name)) out.push_back(name);
  return out;
}

/// A rigid motion of a soup: exact (axis permutation, reflections, power-of-two scale: every
/// coincidence survives) or rounded (random rotation from a quaternion and a translation, in
/// double: flat regions become near-coplanar).
inline void apply_picked_motion(soup_case& c) {
  const int kind = pick_int(0, 2);
  if (kind == 0) return;
  if (kind == 1) {
    std::array<int, 3> perm{0, 1, 2};
    for (int i = 2; i > 0; --i) std::swap(perm[static_cast<std::size_t>(i)], perm[static_cast<std::size_t>(pick_int(0, i))]);
    const vec3d sign{pick_bool() ? 1.0 : -1.0, pick_bool() ? 1.0 : -1.0, pick_bool() ? 1.0 : -1.0};
    const double s = std::ldexp(1.0, pick_int(-4, 4));
    for (tri_d& t : c.tris)
      for (vec3d& p : t) {
        const vec3d q = p;
        for (int k = 0; k < 3; ++k) p[static_cast<std::size_t>(k)] = s * sign[static_cast<std::size_t>(k)] * q[static_cast<std::size_t>(perm[static_cast<std::size_t>(k)])];
      }
    c.kind += " (exact motion)";
    return;
  }
  double w = pick_real(-1, 1), x = pick_real(-1, 1), y = pick_real(-1, 1), z = pick_real(-1, 1);
  const double norm = std::sqrt(w * w + x * x + y * y + z * z);
  if (norm < 1e-3) w = 1, x = y = z = 0;
  else w /= norm, x /= norm, y /= norm, z /= norm;
  const double R[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                          {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                          {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
  const vec3d shift = pick_point(-10, 10);
  for (tri_d& t : c.tris)
    for (vec3d& p : t) {
      const vec3d q = p;
      for (int k = 0; k < 3; ++k)
        p[static_cast<std::size_t>(k)] = R[k][0] * q[0] + R[k][1] * q[1] + R[k][2] * q[2] + shift[static_cast<std::size_t>(k)];
    }
  c.kind += " (rounded rotation)";
}

/// A contiguous run of at most max_triangles triangles of one of `files` (all present),
/// with a random rigid motion. Face ids are the file's.
inline rc::Gen<soup_case> cad_subset(std::vector<std::string> files, std::size_t max_triangles) {
  return rc::gen::exec([files, max_triangles] {
    const std::string name = *rc::gen::elementOf(files);
    const soup_case& mesh = *cad_mesh(name);
    const std::size_t count = std::min(max_triangles, mesh.tris.size());
    const std::size_t start = *rc::gen::inRange<std::size_t>(0, mesh.tris.size() - count + 1);
    soup_case c;
    c.kind = name + " [" + std::to_string(start) + ", " + std::to_string(start + count) + ")";
    c.tris.assign(mesh.tris.begin() + static_cast<std::ptrdiff_t>(start), mesh.tris.begin() + static_cast<std::ptrdiff_t>(start + count));
    c.faces.assign(mesh.faces.begin() + static_cast<std::ptrdiff_t>(start), mesh.faces.begin() + static_cast<std::ptrdiff_t>(start + count));
    apply_picked_motion(c);
    return c;
  });
}

// ---------------------------------------------------------------------------------------------
// The invariant checker
// ---------------------------------------------------------------------------------------------

/// splitmix64: the checker's own deterministic stream (viewpoints), independent of RapidCheck.
struct det_rng {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t x = (state += 0x9e3779b97f4a7c15ULL);
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
  }
  std::size_t below(std::size_t n) { return n ? static_cast<std::size_t>(next() % n) : 0; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * std::ldexp(static_cast<double>(next() >> 11), -53); }
};

/// Broken invariants by name, with the first few messages.
struct check_report {
  std::map<std::string, std::size_t> broken;
  std::vector<std::string> messages;
  void fail(const std::string& invariant, const std::string& message) {
    ++broken[invariant];
    if (messages.size() < 8) messages.push_back(invariant + ": " + message);
  }
  bool ok() const { return broken.empty(); }
  std::string text() const {
    std::string s;
    for (const auto& [k, v] : broken) s += k + "=" + std::to_string(v) + " ";
    for (const auto& m : messages) s += "\n  " + m;
    return s;
  }
};

template <class K>
using exact_kernel_of = std::conditional_t<exbsp::kernel_traits<K>::exact, K, exbsp::epeck_kernel>;

/// A built tree copied into the exact kernel E.
template <class E>
struct tree_view {
  using point = typename E::Point_3;
  using triangle = std::array<point, 3>;
  struct node {
    std::uint32_t plane_source, first, count;
    std::int32_t negative, positive, parent, side_in_parent;
    std::uint32_t depth;
  };
  std::vector<triangle> fragments;
  std::vector<char> finite;              ///< false: a coordinate was NaN/Inf (inexact kernels)
  std::vector<std::uint32_t> source, face;
  std::vector<std::size_t> node_of;      ///< as the tree reports it (node_of_fragment)
  std::vector<node> nodes;
  std::vector<triangle> sources;         ///< input triangles, exact doubles from the soup
  std::vector<std::uint32_t> source_face;
  std::vector<char> degenerate;          ///< exactly collinear input, computed here
  exbsp::build_stats stats;
  std::size_t nonfinite = 0;
};

template <class E>
typename E::Point_3 exact_point(const vec3d& p) {
  return typename E::Point_3(p[0], p[1], p[2]);
}

template <class E, class K>
tree_view<E> view_of(const exbsp::bsp_tree<K>& t, const exbsp::triangle_soup& soup) {
  tree_view<E> v;
  for (const auto& st : soup.triangles) {
    typename tree_view<E>::triangle tri{exact_point<E>(soup.vertices[st.v[0]]), exact_point<E>(soup.vertices[st.v[1]]),
                                        exact_point<E>(soup.vertices[st.v[2]])};
    v.degenerate.push_back(CGAL::collinear(tri[0], tri[1], tri[2]) ? 1 : 0);
    v.sources.push_back(tri);
    v.source_face.push_back(st.face);
  }
  for (std::size_t i = 0; i < t.fragments().size(); ++i) {
    const auto& f = t.fragments()[i];
    typename tree_view<E>::triangle tri;
    bool ok = true;
    for (std::size_t k = 0; k < 3; ++k) {
      if constexpr (std::is_same_v<E, K>) {
        tri[k] = f.v[k];
      } else {
        const double x = f.v[k].x(), y = f.v[k].y(), z = f.v[k].z();
        if (std::isfinite(x) && std::isfinite(y) && std::isfinite(z)) tri[k] = exact_point<E>({x, y, z});
        else ok = false;
      }
    }
    v.fragments.push_back(tri);
    v.finite.push_back(ok ? 1 : 0);
    if (!ok) ++v.nonfinite;
    v.source.push_back(f.source);
    v.face.push_back(f.face);
    v.node_of.push_back(t.node_of_fragment(i));
  }
  for (const auto& n : t.nodes())
    v.nodes.push_back({n.plane_source, n.first, n.count, n.negative, n.positive, n.parent, n.side_in_parent, n.depth});
  v.stats = t.stats();
  return v;
}

template <class E>
typename E::Vector_3 normal_of(const std::array<typename E::Point_3, 3>& t) {
  return CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
}

/// Fragments lie in their source's plane with the same orientation.
template <class E>
void check_source_planes(const tree_view<E>& v, check_report& r) {
  for (std::size_t i = 0; i < v.fragments.size(); ++i) {
    if (!v.finite[i]) continue;
    const auto& f = v.fragments[i];
    if (v.source[i] >= v.sources.size()) {
      r.fail("structure", "fragment " + std::to_string(i) + " has no source");
      continue;
    }
    const auto& s = v.sources[v.source[i]];
    for (std::size_t k = 0; k < 3; ++k)
      if (CGAL::orientation(s[0], s[1], s[2], f[k]) != CGAL::COPLANAR) {
        r.fail("source_plane", "fragment " + std::to_string(i) + " vertex " + std::to_string(k) +
                                   " is off the plane of source " + std::to_string(v.source[i]));
        break;
      }
    const auto n1 = normal_of<E>(f), n2 = normal_of<E>(s);
    if (CGAL::cross_product(n1, n2) != CGAL::NULL_VECTOR || CGAL::sign(n1 * n2) != CGAL::POSITIVE)
      r.fail("orientation", "fragment " + std::to_string(i) + " is not positively parallel to source " +
                                std::to_string(v.source[i]));
  }
}

/// True when the closed triangle t (oriented by n) is separated from the interior of u by the
/// line of one of t's edges.
template <class E>
bool edge_separates(const std::array<typename E::Point_3, 3>& t, const std::array<typename E::Point_3, 3>& u,
                    const typename E::Vector_3& n) {
  for (std::size_t e = 0; e < 3; ++e) {
    const auto& a = t[e];
    const auto& b = t[(e + 1) % 3];
    bool all_out = true;
    for (const auto& q : u)
      if (CGAL::sign(CGAL::cross_product(b - a, q - a) * n) == CGAL::POSITIVE) {
        all_out = false;
        break;
      }
    if (all_out) return true;
  }
  return false;
}

/// The fragments of each source tile it exactly: their normals sum to the source's, every
/// vertex is in the closed source triangle and no two have overlapping interiors.
/// (Same area, inside and disjoint interiors: they cover it, no gaps and no overlaps.)
template <class E>
void check_tiling(const tree_view<E>& v, check_report& r) {
  std::vector<std::vector<std::size_t>> by_source(v.sources.size());
  for (std::size_t i = 0; i < v.fragments.size(); ++i)
    if (v.source[i] < v.sources.size()) by_source[v.source[i]].push_back(i);
  for (std::size_t s = 0; s < v.sources.size(); ++s) {
    const auto& frags = by_source[s];
    if (v.degenerate[s]) {
      if (!frags.empty()) r.fail("structure", "degenerate source " + std::to_string(s) + " has fragments");
      continue;
    }
    if (frags.empty()) {
      r.fail("tiling_area", "source " + std::to_string(s) + " has no fragment (face dropped)");
      continue;
    }
    bool all_finite = true;
    for (std::size_t i : frags) all_finite = all_finite && v.finite[i];
    if (!all_finite) continue;
    const auto& src = v.sources[s];
    const auto n = normal_of<E>(src);
    typename E::Vector_3 sum = CGAL::NULL_VECTOR;
    for (std::size_t i : frags) sum = sum + normal_of<E>(v.fragments[i]);
    if (sum != n) r.fail("tiling_area", "normals of the " + std::to_string(frags.size()) + " fragments of source " +
                                            std::to_string(s) + " do not sum to its normal");
    for (std::size_t i : frags) {
      bool inside = true;
      for (const auto& p : v.fragments[i])
        for (std::size_t e = 0; e < 3 && inside; ++e)
          if (CGAL::sign(CGAL::cross_product(src[(e + 1) % 3] - src[e], p - src[e]) * n) == CGAL::NEGATIVE)
            inside = false;
      if (!inside) r.fail("inside_source", "fragment " + std::to_string(i) + " leaves source " + std::to_string(s));
    }
    for (std::size_t a = 0; a < frags.size(); ++a)
      for (std::size_t b = a + 1; b < frags.size(); ++b) {
        const auto& fa = v.fragments[frags[a]];
        const auto& fb = v.fragments[frags[b]];
        if (CGAL::sign(normal_of<E>(fa) * n) != CGAL::POSITIVE || CGAL::sign(normal_of<E>(fb) * n) != CGAL::POSITIVE)
          continue;  // reported by check_source_planes
        if (!edge_separates<E>(fa, fb, n) && !edge_separates<E>(fb, fa, n))
          r.fail("overlap", "fragments " + std::to_string(frags[a]) + " and " + std::to_string(frags[b]) +
                                " of source " + std::to_string(s) + " overlap");
      }
  }
}

/// Node array, parent/child links, depths, contiguous fragment ranges, node_of_fragment,
/// face ids, and the splitter of each node stored at it.
template <class E>
void check_structure(const tree_view<E>& v, check_report& r) {
  const std::size_t N = v.nodes.size(), M = v.fragments.size();
  if ((N == 0) != (M == 0)) r.fail("structure", std::to_string(N) + " nodes for " + std::to_string(M) + " fragments");
  std::size_t expected_first = 0;
  for (std::size_t i = 0; i < N; ++i) {
    const auto& nd = v.nodes[i];
    const std::string at = "node " + std::to_string(i) + ": ";
    if (nd.first != expected_first) r.fail("structure", at + "fragment range does not follow the previous node's");
    if (nd.count == 0) r.fail("structure", at + "no fragment (its splitter must be stored there)");
    expected_first = nd.first + nd.count;
    if (i == 0) {
      if (nd.parent != -1 || nd.depth != 1) r.fail("structure", at + "the root has a parent or depth != 1");
    } else {
      if (nd.parent < 0 || static_cast<std::size_t>(nd.parent) >= N || (nd.side_in_parent != 1 && nd.side_in_parent != -1)) {
        r.fail("structure", at + "bad parent link");
        continue;
      }
      const auto& p = v.nodes[static_cast<std::size_t>(nd.parent)];
      if ((nd.side_in_parent > 0 ? p.positive : p.negative) != static_cast<std::int32_t>(i))
        r.fail("structure", at + "parent does not point back");
      if (nd.depth != p.depth + 1) r.fail("structure", at + "depth is not parent's + 1");
    }
    for (std::int32_t child : {nd.negative, nd.positive})
      if (child >= 0 && (static_cast<std::size_t>(child) >= N || v.nodes[static_cast<std::size_t>(child)].parent != static_cast<std::int32_t>(i)))
        r.fail("structure", at + "child does not point back");
    if (nd.plane_source >= v.sources.size() || v.degenerate[nd.plane_source]) {
      r.fail("structure", at + "plane of a degenerate or missing source");
      continue;
    }
    bool splitter_here = false;
    for (std::size_t k = nd.first; k < nd.first + nd.count && k < M; ++k) splitter_here |= v.source[k] == nd.plane_source;
    if (!splitter_here) r.fail("structure", at + "no fragment of its plane's source is stored at it");
  }
  if (expected_first != M) r.fail("structure", "node ranges cover " + std::to_string(expected_first) + " of " + std::to_string(M) + " fragments");
  // Every node reachable exactly once from the root.
  if (N) {
    std::vector<char> seen(N, 0);
    std::vector<std::int32_t> stack{0};
    std::size_t reached = 0;
    while (!stack.empty()) {
      const auto i = static_cast<std::size_t>(stack.back());
      stack.pop_back();
      if (seen[i]++) {
        r.fail("structure", "node " + std::to_string(i) + " reached twice");
        break;
      }
      ++reached;
      for (std::int32_t c : {v.nodes[i].negative, v.nodes[i].positive})
        if (c >= 0 && static_cast<std::size_t>(c) < N) stack.push_back(c);
    }
    if (reached != N) r.fail("structure", std::to_string(N - reached) + " nodes unreachable from the root");
  }
  for (std::size_t i = 0; i < M; ++i) {
    const std::size_t n = v.node_of[i];
    if (n >= N || i < v.nodes[n].first || i >= v.nodes[n].first + v.nodes[n].count)
      r.fail("structure", "node_of_fragment(" + std::to_string(i) + ") is wrong");
    if (v.source[i] < v.source_face.size() && v.face[i] != v.source_face[v.source[i]])
      r.fail("structure", "fragment " + std::to_string(i) + " lost its face id");
  }
}

/// Each fragment lies in its node's plane and on the closed side side_in_parent of every
/// ancestor's plane, strictly off it somewhere (else it would have been stored there).
template <class E>
void check_node_planes(const tree_view<E>& v, check_report& r) {
  const std::size_t N = v.nodes.size();
  for (std::size_t i = 0; i < v.fragments.size(); ++i) {
    if (!v.finite[i] || v.node_of[i] >= N) continue;
    const auto& f = v.fragments[i];
    std::size_t at = v.node_of[i];
    const auto& own = v.sources[v.nodes[at].plane_source];
    for (const auto& p : f)
      if (CGAL::orientation(own[0], own[1], own[2], p) != CGAL::COPLANAR) {
        r.fail("node_plane", "fragment " + std::to_string(i) + " is off its node's plane");
        break;
      }
    std::size_t guard = 0;
    while (v.nodes[at].parent >= 0 && guard++ < N) {
      const int side = v.nodes[at].side_in_parent;
      const auto parent = static_cast<std::size_t>(v.nodes[at].parent);
      const auto& pl = v.sources[v.nodes[parent].plane_source];
      bool strictly = false, wrong = false;
      for (const auto& p : f) {
        const int o = static_cast<int>(CGAL::orientation(pl[0], pl[1], pl[2], p));
        wrong |= o * side < 0;
        strictly |= o * side > 0;
      }
      if (wrong || !strictly)
        r.fail("ancestor_side", "fragment " + std::to_string(i) + (wrong ? " crosses" : " lies in") + " the plane of ancestor node " +
                                    std::to_string(parent) + " (side " + std::to_string(side) + ")");
      at = parent;
    }
  }
}

/// Statistics against the tree and the input. `expected_heuristic` empty: not checked.
template <class E>
void check_stats(const tree_view<E>& v, const std::string& expected_kernel, const std::string& expected_heuristic,
                 check_report& r) {
  const auto& s = v.stats;
  std::size_t degenerate = 0;
  for (char d : v.degenerate) degenerate += d ? 1 : 0;
  std::size_t depth = 0;
  for (const auto& n : v.nodes) depth = std::max<std::size_t>(depth, n.depth);
  auto expect = [&](bool ok, const std::string& what) {
    if (!ok) r.fail("stats", what);
  };
  expect(s.input_triangles == v.sources.size(), "input_triangles " + std::to_string(s.input_triangles) + " != " + std::to_string(v.sources.size()));
  expect(s.degenerate_input == degenerate, "degenerate_input " + std::to_string(s.degenerate_input) + " != " + std::to_string(degenerate));
  expect(s.fragments == v.fragments.size(), "fragments != stored fragments");
  expect(s.nodes == v.nodes.size(), "nodes != node array size");
  expect(s.depth == depth, "depth " + std::to_string(s.depth) + " != longest path " + std::to_string(depth));
  const std::size_t base = s.input_triangles - std::min(s.input_triangles, s.degenerate_input);
  expect(s.fragments >= base + s.splits && s.fragments <= base + 2 * s.splits,
         "fragments " + std::to_string(s.fragments) + " not in [kept + splits, kept + 2 splits] = [" +
             std::to_string(base + s.splits) + ", " + std::to_string(base + 2 * s.splits) + "]");
  expect(s.kernel == expected_kernel, "kernel '" + s.kernel + "'");
  expect(expected_heuristic.empty() || s.heuristic == expected_heuristic, "heuristic '" + s.heuristic + "'");
}

/// An eye point or a direction of projection (from the eye into the scene).
template <class E>
struct viewpoint {
  bool is_eye = true;
  typename E::Point_3 eye;
  typename E::Vector_3 direction;
  std::string what;
};

/// The contract's traversal (DESIGN.md section 3), evaluated exactly on the view.
template <class E>
std::vector<std::uint32_t> reference_order(const tree_view<E>& v, const viewpoint<E>& vp) {
  std::vector<std::uint32_t> out;
  if (v.nodes.empty()) return out;
  struct task { std::int32_t node; bool emit; };
  std::vector<task> stack{{0, false}};
  while (!stack.empty()) {
    const task t = stack.back();
    stack.pop_back();
    const auto& nd = v.nodes[static_cast<std::size_t>(t.node)];
    if (t.emit) {
      for (std::uint32_t k = 0; k < nd.count; ++k) out.push_back(nd.first + k);
      continue;
    }
    const auto& p = v.sources[nd.plane_source];
    const int s = vp.is_eye ? static_cast<int>(CGAL::orientation(p[0], p[1], p[2], vp.eye))
                            : static_cast<int>(CGAL::sign(normal_of<E>(p) * (-vp.direction)));
    const std::int32_t first = s < 0 ? nd.positive : nd.negative;
    const std::int32_t second = s < 0 ? nd.negative : nd.positive;
    if (second >= 0) stack.push_back({second, false});
    stack.push_back({t.node, true});
    if (first >= 0) stack.push_back({first, false});
  }
  return out;
}

/// Interior sample points of the fragments for the ray checks: 4 per fragment (centroid and
/// (4,1,1)/6 rotations) while that stays within max_rays, else centroids of a stride.
template <class E>
std::vector<std::pair<std::size_t, typename E::Point_3>> ray_samples(const tree_view<E>& v, std::size_t max_rays) {
  using FT = typename E::FT;
  std::vector<std::pair<std::size_t, typename E::Point_3>> out;
  const std::size_t m = v.fragments.size();
  const bool four = 4 * m <= max_rays;
  const std::size_t stride = four || m <= max_rays ? 1 : (m + max_rays - 1) / max_rays;
  for (std::size_t i = 0; i < m; i += stride) {
    if (!v.finite[i]) continue;
    const auto& f = v.fragments[i];
    const auto e1 = f[1] - f[0], e2 = f[2] - f[0];
    out.emplace_back(i, f[0] + (e1 + e2) * (FT(1) / FT(3)));
    if (four) {
      out.emplace_back(i, f[0] + e1 * (FT(1) / FT(6)) + e2 * (FT(1) / FT(6)));
      out.emplace_back(i, f[0] + e1 * (FT(4) / FT(6)) + e2 * (FT(1) / FT(6)));
      out.emplace_back(i, f[0] + e1 * (FT(1) / FT(6)) + e2 * (FT(4) / FT(6)));
    }
  }
  return out;
}

/// Exact visibility check of a back-to-front order along rays: for the ray from the eye
/// through each sample point q (or the line through q along the direction of projection),
/// every fragment whose interior it crosses strictly in front of the eye is found with its
/// exact ray parameter t; a fragment hit nearer (smaller t) must be drawn after every
/// fragment hit farther. Returns the number of violated pairs reported.
template <class E>
std::size_t check_order_along_rays(const tree_view<E>& v, const viewpoint<E>& vp, const std::vector<std::uint32_t>& order,
                                   std::size_t max_rays, check_report& r) {
  using FT = typename E::FT;
  const std::size_t m = v.fragments.size();
  std::vector<std::size_t> pos(m);
  for (std::size_t k = 0; k < order.size(); ++k) pos[order[k]] = k;
  std::vector<typename E::Vector_3> normals(m);
  for (std::size_t i = 0; i < m; ++i)
    if (v.finite[i]) normals[i] = normal_of<E>(v.fragments[i]);
  std::size_t violations = 0;
  for (const auto& [j, q] : ray_samples(v, max_rays)) {
    const typename E::Point_3 from = vp.is_eye ? vp.eye : q;
    const typename E::Point_3 to = vp.is_eye ? q : q + vp.direction;
    if (from == to) continue;
    std::vector<std::pair<FT, std::size_t>> hits;
    for (std::size_t i = 0; i < m; ++i) {
      if (!v.finite[i]) continue;
      const auto& f = v.fragments[i];
      const auto o0 = CGAL::orientation(from, to, f[0], f[1]);
      if (o0 == CGAL::COPLANAR) continue;
      if (CGAL::orientation(from, to, f[1], f[2]) != o0 || CGAL::orientation(from, to, f[2], f[0]) != o0) continue;
      // The line crosses the interior of fragment i; where?
      const FT g_from = normals[i] * (from - f[0]), g_to = normals[i] * (to - f[0]);
      if (g_from == g_to) continue;  // parallel (cannot happen with a strict crossing)
      const FT t = g_from / (g_from - g_to);  // from + t (to - from) is on i's plane
      if (vp.is_eye && !(t > 0)) continue;    // behind (or at) the eye: not drawn over anything
      hits.emplace_back(t, i);
    }
    std::sort(hits.begin(), hits.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    // Nearer hits (smaller t) must all come later in the order than every farther hit.
    std::size_t min_pos_nearer = order.size();
    std::size_t nearest = 0;
    for (std::size_t g = 0; g < hits.size();) {
      std::size_t h = g;
      while (h < hits.size() && hits[h].first == hits[g].first) ++h;
      for (std::size_t k = g; k < h; ++k)
        if (pos[hits[k].second] > min_pos_nearer) {
          ++violations;
          r.fail("order", vp.what + ": fragment " + std::to_string(nearest) + " (face " +
                              std::to_string(v.face[nearest]) + ") is in front of fragment " +
                              std::to_string(hits[k].second) + " (face " + std::to_string(v.face[hits[k].second]) +
                              ") on the ray through a point of fragment " + std::to_string(j) +
                              " but is drawn before it");
        }
      for (std::size_t k = g; k < h; ++k)
        if (pos[hits[k].second] < min_pos_nearer) {
          min_pos_nearer = pos[hits[k].second];
          nearest = hits[k].second;
        }
      g = h;
    }
  }
  return violations;
}

/// Viewpoints for a view: a random eye, an eye exactly on a node's plane (outside its
/// triangle), an eye at a fragment vertex (a split point: on several planes), an eye at an
/// input vertex, a random direction and a direction parallel to a node's plane.
template <class E>
std::vector<viewpoint<E>> standard_viewpoints(const tree_view<E>& v, std::uint64_t seed) {
  using FT = typename E::FT;
  det_rng rng{seed};
  std::vector<viewpoint<E>> out;
  // Bounding box of the input, in double (only to place random eyes).
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const auto& t : v.sources)
    for (const auto& p : t)
      for (int k = 0; k < 3; ++k) {
        const double x = CGAL::to_double(p[k]);
        lo[k] = std::min(lo[k], x);
        hi[k] = std::max(hi[k], x);
      }
  if (v.sources.empty()) lo[0] = lo[1] = lo[2] = -1, hi[0] = hi[1] = hi[2] = 1;
  vec3d e;
  for (int k = 0; k < 3; ++k) {
    const double c = 0.5 * lo[k] + 0.5 * hi[k], h = std::max(hi[k] - lo[k], 1e-300);
    e[static_cast<std::size_t>(k)] = c + rng.uniform(-1.5, 1.5) * h;
  }
  out.push_back({true, exact_point<E>(e), {}, "random eye"});
  if (!v.nodes.empty()) {
    const auto& nd = v.nodes[rng.below(v.nodes.size())];
    const auto& p = v.sources[nd.plane_source];
    const int a = static_cast<int>(rng.below(5)) - 2, b = static_cast<int>(rng.below(5)) - 1;
    out.push_back({true, p[0] + (p[1] - p[0]) * FT(a) + (p[2] - p[0]) * FT(b), {}, "eye on the plane of a node"});
    out.push_back({false, CGAL::ORIGIN, p[1] - p[0], "direction parallel to a node's plane"});
  }
  if (!v.fragments.empty()) {
    const std::size_t i = rng.below(v.fragments.size());
    if (v.finite[i]) out.push_back({true, v.fragments[i][rng.below(3)], {}, "eye at a fragment vertex"});
  }
  if (!v.sources.empty()) out.push_back({true, v.sources[rng.below(v.sources.size())][rng.below(3)], {}, "eye at an input vertex"});
  typename E::Vector_3 d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
  if (d == CGAL::NULL_VECTOR) d = typename E::Vector_3(0, 0, -1);
  out.push_back({false, CGAL::ORIGIN, d, "random direction"});
  return out;
}

/// The tree's own order for a viewpoint; for inexact kernels the viewpoint's coordinates are
/// rounded to double first (callers round the viewpoint the same way).
template <class K, class E>
std::vector<std::uint32_t> tree_order(const exbsp::bsp_tree<K>& t, const viewpoint<E>& vp, bool back_to_front = true) {
  if constexpr (std::is_same_v<K, E>) {
    return vp.is_eye ? t.order_from_eye(vp.eye, back_to_front) : t.order_for_direction(vp.direction, back_to_front);
  } else {
    if (vp.is_eye)
      return t.order_from_eye(typename K::Point_3(CGAL::to_double(vp.eye.x()), CGAL::to_double(vp.eye.y()), CGAL::to_double(vp.eye.z())),
                              back_to_front);
    return t.order_for_direction(typename K::Vector_3(CGAL::to_double(vp.direction.x()), CGAL::to_double(vp.direction.y()),
                                                      CGAL::to_double(vp.direction.z())),
                                 back_to_front);
  }
}

template <class E>
viewpoint<E> rounded(const viewpoint<E>& vp) {
  viewpoint<E> out = vp;
  out.eye = typename E::Point_3(CGAL::to_double(vp.eye.x()), CGAL::to_double(vp.eye.y()), CGAL::to_double(vp.eye.z()));
  out.direction = typename E::Vector_3(CGAL::to_double(vp.direction.x()), CGAL::to_double(vp.direction.y()),
                                       CGAL::to_double(vp.direction.z()));
  return out;
}

/// p * 2^k, exactly.
template <class E>
typename E::Point_3 scaled_point(const typename E::Point_3& p, int k) {
  return CGAL::ORIGIN + (p - CGAL::ORIGIN) * typename E::FT(std::ldexp(1.0, k));
}

/// The exponent k that brings the largest input coordinate near 1 when the input is tiny or
/// huge (|x| < 2^-100 or > 2^100), else 0. Every invariant is invariant under the exact
/// similarity p -> p * 2^k, and near 1 the interval filters work again (near 1e-300 every
/// product underflows and each predicate would be evaluated in rationals).
template <class E>
int normalising_exponent(const tree_view<E>& v) {
  double big = 0;
  for (const auto& t : v.sources)
    for (const auto& p : t)
      for (int k = 0; k < 3; ++k) big = std::max(big, std::fabs(CGAL::to_double(p[k])));
  if (big == 0 || (big > 0x1p-100 && big < 0x1p100)) return 0;
  int e = 0;
  std::frexp(big, &e);
  return std::max(-1000, std::min(1000, -e));
}

template <class E>
tree_view<E> scaled_view(const tree_view<E>& v, int k) {
  tree_view<E> out = v;
  for (auto& t : out.fragments)
    for (auto& p : t) p = scaled_point<E>(p, k);
  for (auto& t : out.sources)
    for (auto& p : t) p = scaled_point<E>(p, k);
  return out;
}

/// All order checks for one viewpoint: a permutation, the contract's traversal, front-to-back
/// is the exact reverse, and the exact ray check. `v` may be the tree's view scaled by 2^k
/// (normalising_exponent); the tree itself is asked with the unscaled viewpoint.
template <class K, class E>
void check_orders(const exbsp::bsp_tree<K>& t, const tree_view<E>& v, viewpoint<E> vp, std::size_t max_rays, check_report& r,
                  int k = 0) {
  if constexpr (!std::is_same_v<K, E>) vp = rounded(vp);
  const auto order = tree_order<K>(t, vp, true);
  auto reverse = tree_order<K>(t, vp, false);
  if (k) vp.eye = scaled_point<E>(vp.eye, k);
  std::vector<char> seen(v.fragments.size(), 0);
  bool perm = order.size() == v.fragments.size();
  for (std::uint32_t i : order) perm = perm && i < seen.size() && !seen[i]++;
  if (!perm) {
    r.fail("structure", vp.what + ": the order is not a permutation of the fragments");
    return;
  }
  if (order != reference_order(v, vp)) r.fail("traversal", vp.what + ": order differs from the contract's traversal");
  std::reverse(reverse.begin(), reverse.end());
  if (reverse != order) r.fail("traversal", vp.what + ": front-to-back is not the reverse of back-to-front");
  check_order_along_rays(v, vp, order, max_rays, r);
}

/// Options of a full check.
struct check_options {
  std::uint64_t seed = 1;        ///< viewpoints
  std::size_t max_rays = 160;    ///< sample rays per viewpoint
  std::size_t viewpoints = 6;    ///< at most this many of standard_viewpoints
  std::string heuristic;         ///< expected in the stats (empty: not checked)
  std::vector<vec3d> eyes, directions;  ///< extra viewpoints, checked after the standard ones
};

/// Every invariant of tests/HARD_CASES.md for a built tree; the report says which broke.
template <class K>
check_report check_tree(const exbsp::bsp_tree<K>& t, const exbsp::triangle_soup& soup, const check_options& o) {
  using E = exact_kernel_of<K>;
  check_report r;
  const tree_view<E> v0 = view_of<E>(t, soup);
  if (v0.nonfinite) r.fail("nonfinite", std::to_string(v0.nonfinite) + " fragments with NaN/Inf coordinates");
  check_structure(v0, r);
  check_stats(v0, exbsp::to_string(exbsp::kernel_traits<K>::id), o.heuristic, r);
  if (!r.broken.count("structure")) {
    const int k = normalising_exponent(v0);
    const tree_view<E> v = k ? scaled_view(v0, k) : v0;
    check_source_planes(v, r);
    check_tiling(v, r);
    check_node_planes(v, r);
    auto vps = standard_viewpoints(v0, o.seed);
    if (vps.size() > o.viewpoints) vps.resize(o.viewpoints);
    for (const vec3d& e : o.eyes) vps.push_back({true, exact_point<E>(e), {}, "given eye"});
    for (const vec3d& d : o.directions)
      vps.push_back({false, CGAL::ORIGIN, typename E::Vector_3(d[0], d[1], d[2]), "given direction"});
    for (const auto& vp : vps) check_orders(t, v, vp, o.max_rays, r, k);
  }
  return r;
}

/// Builds the tree of `c` with `heuristic` in kernel K and checks it.
template <class K>
check_report build_and_check(const soup_case& c, const std::string& heuristic, const check_options& o,
                             std::uint64_t build_seed = 0) {
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

/// Inside a RapidCheck property: builds `c` with every heuristic in kernel K (the build seed
/// and the viewpoints drawn from RapidCheck) and fails the property on any broken invariant.
/// Tags the case with its generator and whether the tree needed splits.
template <class K>
void rc_assert_invariants_for_every_heuristic(const soup_case& c, std::size_t max_rays = 160,
                                              const check_options& extra = {}) {
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

}  // namespace exbsp_test
