// SPDX-License-Identifier: LGPL-3.0-or-later
// The matrices of a scene's view (notation in matrices_command.h and view/course_matrices.h).
#include "scene/matrices_command.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include <exbsp/view/viewport.h>
#include "view/course_matrices.h"

namespace exbsp::scene {

namespace {

namespace course = view::course;
using view::mat4;

/// A chain from its factors: the product is taken left to right.
matrix_chain chain(std::string name, std::string formula, std::string target,
                   std::vector<named_matrix> factors) {
  mat4 product = mat4::identity();
  for (const named_matrix& f : factors) product = product * f.m;
  return {std::move(name), std::move(formula), std::move(target), std::move(factors), product};
}

/// The rigid model_view's basis (its rows) and the eye it moves to the origin.
struct rigid_parts {
  view::camera_basis basis;
  view::point3 eye;
};

rigid_parts parts_of(const mat4& mv) {
  const auto row = [&](int r) {
    return view::vector3{mv.m[4 * r], mv.m[4 * r + 1], mv.m[4 * r + 2]};
  };
  const view::vector3 u = row(0), v = row(1), w = row(2);
  const double tu = mv.m[3], tv = mv.m[7], tw = mv.m[11];
  // mv = [R | t] with R orthonormal: the eye is -R^T t.
  const view::vector3 e = -(tu * u + tv * v + tw * w);
  return {{u, v, w}, {e.x, e.y, e.z}};
}

/// The PHIGS normalisation step by step (view::phigs_normalisation), the last step leftmost.
matrix_chain phigs_chain(const view::phigs_view& p) {
  std::vector<view::phigs_step> steps = view::phigs_normalisation(p);
  std::vector<named_matrix> factors;
  std::string formula;
  for (auto it = steps.rbegin(); it != steps.rend(); ++it) {
    factors.push_back(
        {it->name, it->meaning + (it->space.empty() ? "" : "; now in the " + it->space + " space"),
         it->m});
    formula += it->name + " * ";
  }
  return chain("phigs_normalisation", "N = " + formula + "p",
               "the normalised view volume, the cube [-1,1]^3 with the front plane at z = +1 and "
               "the back plane at -1 (OpenGL's NDC with z negated), after / w",
               std::move(factors));
}

/// A teaching scene drawn in an intermediate space: the matrix that moved it there.
void add_space_chain(const scene& s, scene_matrices& out) {
  if (!s.teaching.space_matrix) return;
  out.chains.push_back(
      chain("teaching_space", "p_drawn = N_" + s.teaching.space + " * p",
            "the " + s.teaching.space +
                " space of the observed PHIGS camera (/teaching/view_volume), "
                "where the scene is drawn",
            {{"N_" + s.teaching.space,
              "the observed camera's normalisation up to the " + s.teaching.space + " space",
              *s.teaching.space_matrix}}));
}

/// The chains of the scene's own view.
scene_matrices view_chains(const scene& s) {
  const view::view_setup v = make_view_setup(s);
  scene_matrices out;
  out.scene = s.path;
  out.projection =
      s.projection_matrix ? "matrix" : view::to_string(s.phigs ? v.kind : s.projection.kind);
  out.x = v.vp.x;
  out.y = v.vp.y;
  out.width = v.vp.width;
  out.height = v.vp.height;
  out.chains.push_back(chain(
      "opengl", "window = Mviewport * Mprojection * Mmodelview * p, then / w",
      "window coordinates: x, y in pixels (pixel centres at i + 1/2), z the depth in [0, 1]",
      {{"Mviewport", "normalised device coordinates [-1,1]^3 to the window (glViewport)",
        view::viewport_matrix(v.vp)},
       {"Mprojection", "eye to clip coordinates (gluPerspective, glFrustum, glOrtho, oblique)",
        v.projection},
       {"Mmodelview", "world to eye coordinates (the camera, gluLookAt)", v.model_view}}));
  if (s.phigs) {
    out.chains.push_back(chain("phigs", "clip = M * O * p",
                               "clip coordinates (the view volume is -w <= x, y, z <= w)",
                               {{"M", "view mapping: VRC to clip coordinates", s.phigs->mapping},
                                {"O", "view orientation: world to VRC", s.phigs->orientation}}));
    out.chains.push_back(phigs_chain(*s.phigs_parameters));
    out.notes.push_back(
        "viewing, normalisation: a PHIGS camera defines its own projection (see phigs and "
        "phigs_normalisation)");
    return out;
  }
  if (s.projection_matrix) {
    out.notes.push_back(
        "viewing, normalisation: the scene gives its projection as a matrix (glLoadMatrix), "
        "which has no decomposition into the documents' steps");
    return out;
  }
  const projection_spec& p = s.projection;
  double l = p.left, r = p.right, b = p.bottom, t = p.top;
  if (p.kind == view::projection_kind::perspective) {
    const perspective_lens lens = lens_of(p, v.vp.width, v.vp.height);
    t = p.near_dist * std::tan(lens.fovy_deg * M_PI / 360);
    b = -t;
    r = t * lens.aspect;
    l = -r;
  }
  const double n = -p.near_dist, f = -p.far_dist;
  const bool perspective =
      p.kind == view::projection_kind::perspective || p.kind == view::projection_kind::frustum;
  const named_matrix mvp{"Mvp", "canonical x, y to pixels, pixel centres at integers",
                         course::viewport_mvp(v.vp.width, v.vp.height)};
  const named_matrix morth{"Morth", "the box [l,r] x [b,t] x [f,n] to the canonical [-1,1]^3",
                           course::orthographic(l, r, b, t, n, f)};
  const named_matrix mv{"Mv", "world to camera coordinates (basis u, v, w; eye e)", v.model_view};
  if (p.kind == view::projection_kind::oblique) {
    out.notes.push_back(
        "viewing: an oblique view shears before Morth (see Mprojection), not in this chain");
  } else if (perspective) {
    out.chains.push_back(
        chain("viewing", "M = Mvp * Morth * Mp * Mv (n = -near, f = -far)",
              "screen: x, y in pixels with centres at integers (OpenGL's window x, y minus 1/2), "
              "z in [-1, 1] with the near plane at +1, after / w",
              {mvp,
               morth,
               {"Mp", "the frustum to the box [l,r] x [b,t] x [f,n] (x, y scaled by n / z)",
                course::perspective_mp(n, f)},
               mv}));
  } else {
    out.chains.push_back(chain("viewing", "M = Mvp * Morth * Mv (n = -near, f = -far)",
                               "screen: x, y in pixels with centres at integers (OpenGL's "
                               "window x, y minus 1/2), z in [-1, 1] with the near plane at +1",
                               {mvp, morth, mv}));
  }
  const bool symmetric = p.kind == view::projection_kind::perspective ||
                         (p.kind == view::projection_kind::frustum && l == -r && b == -t);
  if (!symmetric) {
    out.notes.push_back(
        perspective ? "normalisation: the six-parameter camera's view volume is symmetric; this "
                      "frustum is not (a shear would come first)"
                    : "normalisation: defined for perspective views (the six-parameter camera)");
    return out;
  }
  const rigid_parts camera = parts_of(v.model_view);
  const double k = p.near_dist / p.far_dist;
  out.chains.push_back(
      chain("normalisation", "p' = Dpersp * Sfar * Sxy * Mrot * Ttrans * p (k = near / far)",
            "the canonical parallel volume [-1,1]^2 x [0,1], near at z = 0, far at 1, after / w",
            {{"Dpersp", "the truncated pyramid between z = -k and -1 to the parallel volume",
              course::perspective_dpersp(k)},
             {"Sfar", "scale by 1 / far: the far plane at z = -1", course::scale_far(p.far_dist)},
             {"Sxy", "scale x, y: the side planes through (+-1, +-1) at distance 1",
              course::scale_xy(r / p.near_dist, t / p.near_dist)},
             {"Mrot", "rotate the camera's axes u, v, w onto x, y, z (looking down -z)",
              course::rotation_of(camera.basis)},
             {"Ttrans", "translate the camera's position to the origin",
              course::translation_to_origin(camera.eye)}}));
  return out;
}

}  // namespace

scene_matrices matrices_of(const scene& s) {
  scene_matrices out = view_chains(s);
  add_space_chain(s, out);
  return out;
}

namespace {

std::string matrix_text(const mat4& m) {
  std::string out;
  char cell[32];
  for (int r = 0; r < 4; ++r) {
    out += "  [";
    for (int c = 0; c < 4; ++c) {
      std::snprintf(cell, sizeof cell, " %13.6g", m.m[4 * r + c] == 0 ? 0.0 : m.m[4 * r + c]);
      out += cell;
    }
    out += " ]\n";
  }
  return out;
}

nlohmann::json matrix_json(const mat4& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 4; ++r)
    rows.push_back({m.m[4 * r], m.m[4 * r + 1], m.m[4 * r + 2], m.m[4 * r + 3]});
  return rows;
}

}  // namespace

std::string matrices_text(const scene_matrices& m) {
  std::string out = (m.scene.empty() ? std::string("the demo scene") : m.scene) + ": " +
                    m.projection + ", viewport " + std::to_string(m.width) + "x" +
                    std::to_string(m.height) + " at (" + std::to_string(m.x) + ", " +
                    std::to_string(m.y) + ")\n";
  for (const matrix_chain& c : m.chains) {
    out += "\n" + c.name + ": " + c.formula + "\n  gives " + c.target + "\n";
    for (const named_matrix& f : c.factors)
      out += f.name + " (" + f.meaning + ") =\n" + matrix_text(f.m);
    out += "product =\n" + matrix_text(c.product);
  }
  for (const std::string& note : m.notes) out += "\nnot shown: " + note + "\n";
  return out;
}

std::string matrices_json(const scene_matrices& m) {
  nlohmann::json chains = nlohmann::json::array();
  for (const matrix_chain& c : m.chains) {
    nlohmann::json factors = nlohmann::json::array();
    for (const named_matrix& f : c.factors)
      factors.push_back({{"name", f.name}, {"meaning", f.meaning}, {"rows", matrix_json(f.m)}});
    chains.push_back({{"name", c.name},
                      {"formula", c.formula},
                      {"target", c.target},
                      {"factors", factors},
                      {"product", matrix_json(c.product)}});
  }
  const nlohmann::json doc = {{"scene", m.scene},
                              {"projection", m.projection},
                              {"viewport", {m.x, m.y, m.width, m.height}},
                              {"chains", chains},
                              {"notes", m.notes}};
  return doc.dump(1) + "\n";
}

}  // namespace exbsp::scene
