// SPDX-License-Identifier: LGPL-3.0-or-later
// What the viewing pipeline needs to know about a view: the camera, the model-view and
// projection matrices, the viewport and where its picture goes in the output image
// (docs/contract.md "Scenes").
#pragma once
#include <exbsp/core/export.h>
#include <exbsp/view/camera.h>
#include <exbsp/view/matrix.h>
#include <exbsp/view/viewport.h>

namespace exbsp::view {

/// The four projection types of a scene (docs/contract.md "Scenes").
enum class projection_kind { perspective, frustum, orthographic, oblique };
/// "perspective", "frustum", "orthographic", "oblique".
EXBSP_EXPORT const char* to_string(projection_kind k);

/// Everything the stages need to know about the view.
struct EXBSP_EXPORT view_setup {
  projection_kind kind = projection_kind::perspective;
  camera cam;                          ///< gluLookAt input; cam.eye orders perspective views
  mat4 model_view = mat4::identity();  ///< look_at(cam)
  mat4 projection = mat4::identity();  ///< eye -> clip coordinates
  viewport vp;
  /// Parallel kinds only: unit direction of projection in WORLD space, from the eye into the
  /// scene (the gaze for orthographic, the oblique direction for oblique).
  vector3 direction;
  /// The output image and where the viewport's picture goes in it (window coordinates: x, y
  /// of its lower-left corner). 0 x 0: the image is the viewport. The render command's
  /// "place" stage composes it (placement.h).
  int image_width = 0, image_height = 0;
  int place_x = 0, place_y = 0;

  /// True when the image is larger than the viewport.
  bool needs_placement() const {
    return image_width > 0 &&
           (image_width != vp.width || image_height != vp.height || place_x != 0 || place_y != 0);
  }

  bool is_parallel() const {
    return kind == projection_kind::orthographic || kind == projection_kind::oblique;
  }
};

}  // namespace exbsp::view
