// SPDX-License-Identifier: LGPL-3.0-or-later
// `exbsp matrices SCENE.json`: every matrix of a scene's viewing pipeline, in OpenGL's terms
// (the matrices the pipeline multiplies) and in the course material's (view/course_matrices.h:
// M = Mvp * Morth * Mp * Mv, and p' = Dpersp * Sfar * Sxy * Mrot * Ttrans * p), each chain
// with its product, so that a student can check one against the other.
#pragma once
#include <string>
#include <vector>

#include <exbsp/view/matrix.h>
#include "scene/scene.h"

namespace exbsp::scene {

/// One factor of a chain: its name in the chain's notation, what it does, its value.
struct named_matrix {
  std::string name, meaning;
  view::mat4 m;
};

/// A chain of matrices whose product takes a world point to the chain's target.
struct matrix_chain {
  std::string name;     ///< "opengl", "viewing", "normalisation", "phigs", "phigs_normalisation"
                        ///< or "teaching_space"
  std::string formula;  ///< e.g. "M = Mvp * Morth * Mp * Mv"
  std::string target;   ///< where the product takes a world point
  std::vector<named_matrix> factors;  ///< in the formula's order, left to right
  view::mat4 product;                 ///< the factors multiplied
};

/// The chains of a scene's view, and notes on the chains that do not apply to it.
struct scene_matrices {
  std::string scene;       ///< the scene's path ("" for the demo scene)
  std::string projection;  ///< "perspective", "frustum", "orthographic" or "oblique"
  int x = 0, y = 0, width = 0, height = 0;  ///< the viewport
  std::vector<matrix_chain> chains;
  std::vector<std::string> notes;
};

/// The chains of `s` (scene_error as make_view_setup gives for a bad camera or projection).
scene_matrices matrices_of(const scene& s);

/// The report as text: each chain's factors, then its product, 6 significant digits.
std::string matrices_text(const scene_matrices& m);

/// The report as one JSON object: {"scene", "projection", "viewport": [x, y, w, h], "chains":
/// [{"name", "formula", "target", "factors": [{"name", "meaning", "rows"}], "product"}],
/// "notes"}, each matrix as 4 rows of 4 numbers (shortest text that reads back the same double).
std::string matrices_json(const scene_matrices& m);

}  // namespace exbsp::scene
