// SPDX-License-Identifier: LGPL-3.0-or-later
// Parts of the scene parser kept out of scene.cpp (notation in scene.h; internal to
// src/scene): the modelling hierarchy ("meshes", "groups", "transforms"), the camera forms,
// "viewport"/"image"/"aspect", "lines" and "trackball". Each throws scene_error naming its key.
#pragma once
#include <string>

#include "scene/scene.h"
#include "scene/json_reader.h"

namespace exbsp::scene::detail {

/// "meshes" and "groups" (at least one of them present) into s.meshes, each with its matrix.
void parse_mesh_tree(const reader& r, const json& doc, const std::string& path, scene& s);

/// "camera" in any form into s.camera (and s.view_matrix / s.phigs / s.form). A phigs camera
/// also fills s.projection; "camera" may be absent only for an ortho2d projection, which must
/// then be parsed first (needs_camera false).
void parse_any_camera(const reader& r, const json& doc, scene& s);

/// "camera" (parse_any_camera) and "projection" (none for a phigs camera, which defines its own).
void parse_camera_and_projection(const reader& r, const json& doc, scene& s);

/// "teaching" (notation in scene.h; teaching.cpp): the depth-sort painter, the near-plane rule
/// and the observed camera's view volume, drawn as lines appended to s.curves. Needs the
/// viewport, effects, curves and lines parsed first.
void parse_teaching(const reader& r, const json& doc, scene& s);

/// True when "projection" is {"type": "ortho2d", ...} (the camera is then optional).
bool is_ortho2d(const json& doc);

/// "viewport" (width, height, x, y), "image" and "aspect".
void parse_viewport_and_image(const reader& r, const json& doc, scene& s);

/// v.vp (the viewport, letterboxed for aspect "fit") and where it lies in the image
/// (v.image_width, v.image_height, v.place_x, v.place_y).
void place_viewport(const scene& s, view::view_setup& v);

/// A row-major 4x4 matrix: an array of 16 numbers at `key` (scene_error naming the entry).
view::mat4 parse_row_major(const reader& r, const json& v, const std::string& key);

/// The points of a curve or line: the member `name` of `entry` (at pointer `key`), an array of
/// `min` to `max` points [x, y, z]; `noun` names one point in messages ("control point").
std::vector<vec3d> parse_points(const reader& r, const json& entry, const std::string& key,
                                const char* name, std::size_t min, std::size_t max,
                                const char* noun);

/// "lines" appended to s.curves as polylines.
void parse_lines(const reader& r, const json& doc, scene& s);

/// "trackball": "arcball" | "virtual".
void parse_trackball(const reader& r, const json& doc, scene& s);

}  // namespace exbsp::scene::detail
