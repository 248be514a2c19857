// SPDX-License-Identifier: LGPL-3.0-or-later
// exbsp: the whole public C++ API in one include (installed as <exbsp/exbsp.h>).
//
// Everything here is free of CGAL, Boost and OpenMP; exact arithmetic happens inside the
// library. Three optional headers are not included because they need third-party headers:
//   <exbsp/bsp/exact_gmp.h>          exact fragment coordinates as GMP rationals (gmpxx.h)
//   <exbsp/adapters/openmesh.h>      OpenMesh meshes to and from exbsp (target exbsp::openmesh)
//   <exbsp/adapters/cgal_face_graph.h>  any CGAL FaceGraph to and from exbsp (CGAL)
// and the two headers of the GPL component exbsp::gpl (docs/licence.md) are not included either:
//   <exbsp/clip/section_cap.h>       sections and clipping with caps
//   <exbsp/clip/convex_hull.h>       the convex hull of 3D points as half-spaces
// The rest is the LGPL components: exbsp::core (core/, mesh/, bsp/, clip/, scene/procedural.h,
// adapters/triangle_list.h) and exbsp::render (view/: cameras, projections, images, the one-call
// render_soup with its fitted view and headlight). The stage pipeline the renderer is made of
// (<exbsp/view/pipeline.h>, stages.h, standard_pipeline.h: the `frame` every stage reads and
// writes) is installed for programs that add stages of their own, but is not included here:
// it is the renderer's inside, and changes with it.
#pragma once
#include <exbsp/adapters/triangle_list.h>
#include <exbsp/bsp/distributed.h>
#include <exbsp/bsp/engine.h>
#include <exbsp/bsp/traversal.h>
#include <exbsp/clip/bbox.h>
#include <exbsp/clip/clip_types.h>
#include <exbsp/clip/cohen_sutherland.h>
#include <exbsp/clip/convex_region.h>
#include <exbsp/clip/homogeneous.h>
#include <exbsp/clip/homogeneous_segment.h>
#include <exbsp/clip/liang_barsky.h>
#include <exbsp/clip/section.h>
#include <exbsp/clip/sutherland_hodgman.h>
#include <exbsp/core/errors.h>
#include <exbsp/core/version.h>
#include <exbsp/mesh/gmp_memory.h>
#include <exbsp/mesh/mesh_io.h>
#include <exbsp/mesh/soup.h>
#include <exbsp/scene/procedural.h>
#include <exbsp/view/bezier.h>
#include <exbsp/view/camera.h>
#include <exbsp/view/image.h>
#include <exbsp/view/matrix.h>
#include <exbsp/view/phigs.h>
#include <exbsp/view/pipeline.h>
#include <exbsp/view/png_io.h>
#include <exbsp/view/projection.h>
#include <exbsp/view/render.h>
#include <exbsp/view/trackball.h>
#include <exbsp/view/transforms.h>
#include <exbsp/view/view_setup.h>
#include <exbsp/view/viewport.h>
