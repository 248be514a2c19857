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
// adapters/triangle_list.h) and exbsp::render (view/).
#pragma once
#include "core/errors.h"
#include "core/version.h"
#include "mesh/soup.h"
#include "mesh/mesh_io.h"
#include "mesh/gmp_memory.h"
#include "bsp/engine.h"
#include "bsp/traversal.h"
#include "clip/clip_types.h"
#include "clip/bbox.h"
#include "clip/cohen_sutherland.h"
#include "clip/liang_barsky.h"
#include "clip/sutherland_hodgman.h"
#include "clip/convex_region.h"
#include "clip/homogeneous.h"
#include "clip/homogeneous_segment.h"
#include "clip/section.h"
#include "view/matrix.h"
#include "view/camera.h"
#include "view/phigs.h"
#include "view/projection.h"
#include "view/viewport.h"
#include "view/transforms.h"
#include "view/image.h"
#include "view/png_io.h"
#include "view/pipeline.h"
#include "view/stages.h"
#include "view/standard_pipeline.h"
#include "view/trackball.h"
#include "view/bezier.h"
#include "scene/procedural.h"
#include "adapters/triangle_list.h"
