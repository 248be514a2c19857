// SPDX-License-Identifier: LGPL-3.0-or-later
// The mesh-reader fuzz targets (fuzz_off, fuzz_obj, fuzz_ply, fuzz_stl): one input = the
// complete contents of a mesh file, read with read_mesh_data (mesh/mesh_io.h).
//
// Oracle, besides "exbsp::error or nothing" (fuzz_check.h), for every soup a reader accepts
// (docs/contract.md "Input"):
//   - source is the name given; every coordinate is finite; every index is in range;
//   - faces are kept in file order and none is dropped: the face ids of the triangles run
//     0, 0, ..., 1, ..., face_count - 1 without a gap (a face of k vertices gives k - 2 >= 1
//     triangles), and there are no triangles when face_count is 0;
//   - round trip: the soup written as OFF (support/inputs.h off_text: triangles as faces,
//   coordinates with 17
//     significant digits, which identify a double uniquely) reads back with bit-identical
//     coordinates and the same triangles. This checks the exact number parsing of the OFF
//     reader on every double the other readers produce (binary floats, denormals, -0).
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include <exbsp/mesh/mesh_io.h>
#include <exbsp/mesh/soup.h>
#include "fuzz_check.h"
#include "support/inputs.h"

namespace exbsp::fuzz {

inline void check_soup(const triangle_soup& soup, const std::string& name) {
  require(soup.source == name, "soup.source is the file name");
  for (const vec3d& p : soup.vertices)
    require(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]),
            "every coordinate is finite");
  std::uint64_t faces_seen = 0;  // the id the next new face must have
  for (const soup_triangle& t : soup.triangles) {
    for (std::uint32_t v : t.v) require(v < soup.vertices.size(), "vertex index in range");
    if (faces_seen > 0 && t.face == faces_seen - 1) continue;  // next triangle of the same fan
    require(t.face == faces_seen, "face ids in file order without a gap (no face dropped)");
    ++faces_seen;
  }
  require(faces_seen == soup.face_count, "face_count = number of faces with triangles");
}

inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

inline void check_off_round_trip(const triangle_soup& soup) {
  const triangle_soup back =
      read_mesh_data(exbsp_test::off_text(soup), mesh_format::off, "round-trip.off");
  require(back.vertices.size() == soup.vertices.size(), "round trip keeps the vertex count");
  require(back.triangles.size() == soup.triangles.size(), "round trip keeps the triangle count");
  for (std::size_t i = 0; i < soup.vertices.size(); ++i)
    for (int a = 0; a < 3; ++a)
      require(same_bits(back.vertices[i][a], soup.vertices[i][a]),
              "round trip through OFF text gives bit-identical coordinates");
  for (std::size_t i = 0; i < soup.triangles.size(); ++i) {
    require(back.triangles[i].v == soup.triangles[i].v, "round trip keeps the triangles");
    require(back.triangles[i].face == i, "round trip: one face per triangle");
  }
}

/// The body of a mesh fuzz target.
inline int fuzz_mesh(const std::uint8_t* data, std::size_t size, mesh_format format,
                     const std::string& name) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  run_guarded([&] {
    const triangle_soup soup = read_mesh_data(text, format, name);
    check_soup(soup, name);
    // Throwing here (even exbsp::error) would be a finding: catch it as one.
    try {
      check_off_round_trip(soup);
    } catch (const exbsp::error& e) {
      std::fprintf(stderr, "exbsp fuzz: the OFF round trip was rejected: %s\n", e.what());
      std::abort();
    }
  });
  return 0;
}

}  // namespace exbsp::fuzz
