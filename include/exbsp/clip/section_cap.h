// SPDX-License-Identifier: GPL-3.0-or-later
// Sections with caps, and clipping with caps: the GPL component exbsp::gpl (libexbsp_gpl;
// find_package(exbsp COMPONENTS gpl), target exbsp::gpl). The caps are triangulated by CGAL's
// constrained Delaunay triangulation, which CGAL licenses under the GPL-3.0-or-later, so a
// program that links this component is distributed under the GPL-3.0-or-later
// (docs/licence.md). exbsp::section and exbsp::clip_soup of the LGPL core (section.h) do the
// same cuts without caps.
#pragma once
#include <vector>

#include <exbsp/core/export.h>

#include <exbsp/clip/section.h>

namespace exbsp {

/// exbsp::section (section.h) with the cap of a closed input: the region the outline encloses
/// (holes and nested islands included), triangulated exactly, facing -(A, B, C), with face id
/// section_result::cap_face, so that kept ∪ cap is closed again. Where loops of the outline
/// cross or overlap (non-conforming input), kept triangles and outline edges are subdivided
/// (section_stats::cap_steiner_points, split_constraints). Throws usage_error for a bad plane.
EXBSP_EXPORT section_result section_with_cap(const triangle_soup& soup, const section_plane& plane,
                                             const section_options& options = {});

/// exbsp::clip_soup (section.h) with caps: each plane that cuts a closed part adds its cap as
/// the new face soup.face_count + i (i = index of the plane), and later planes cut earlier caps
/// like any other face, so the result stays closed. face_count becomes soup.face_count +
/// planes.size(). Throws usage_error for a bad plane.
EXBSP_EXPORT triangle_soup clip_soup_with_caps(const triangle_soup& soup,
                                               const std::vector<section_plane>& planes);

}  // namespace exbsp
