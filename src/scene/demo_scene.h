// SPDX-License-Identifier: LGPL-3.0-or-later
// The built-in demo scene of `exbsp render` without a scene file: everything it draws is
// generated in code, so it works without any mesh file.
#pragma once
#include "scene/scene.h"

namespace exbsp::scene {

/// The demo: a cube pierced by a tilted slab (intersecting parts), three planks in cyclic
/// overlap (no depth sort can order them; the BSP splits one), and a CAD-style part (a gear
/// with a bore on a hexagonal shaft); perspective camera, 800 x 600, path "(built-in demo)".
scene demo_scene();

}  // namespace exbsp::scene
