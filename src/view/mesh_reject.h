// SPDX-License-Identifier: LGPL-3.0-or-later
// The "reject" stage: whole meshes outside the view volume are dropped before any
// per-triangle work (the BSP build included), by the bounding-box trivial reject.
//
// Notation: for mesh k (faces [face_offsets[k], face_offsets[k+1]) of the soup) B_k is the
// axis-aligned box of its triangles' vertices (clip/bbox.h); its eight corners c go to clip
// coordinates P Mv c, and the mesh is rejected when all eight lie outside one common clip
// plane (clip/homogeneous.h, homogeneous_trivially_rejected). The box contains the mesh and
// the view volume is convex, so a rejected mesh has no visible point; a mesh that is not
// rejected may still be invisible (the test is conservative). Removing a mesh's triangles
// from the soup keeps every face id, so colours and the order of the others are unchanged
// (a BSP of a subset orders that subset correctly).
#pragma once
#include <string>

#include <exbsp/view/pipeline.h>

namespace exbsp::view {

/// Removes from f.soup the triangles of every mesh of f.mesh_face_offsets whose box is
/// outside the view volume of f.view, and lists those meshes in f.rejected_meshes.
/// No-op without offsets. Returns a note for the verbose log.
std::string mesh_reject_stage(frame& f);

}  // namespace exbsp::view
