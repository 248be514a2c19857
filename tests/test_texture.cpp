// SPDX-License-Identifier: LGPL-3.0-or-later
// Textures (issue 29): texture coordinates read from OBJ (vt) and PLY (u/v, s/t, texture_u/v),
// carried through the BSP's exact splits (every fragment corner's UV equals the barycentric
// interpolation in its source triangle computed here in exact rationals, independently, and
// rounded once), sampled nearest and bilinear with repeat and clamp, the scene's "texture" key
// and its errors, and untextured scenes rendering byte-identical PNGs to the committed ones.
// The per-pixel comparison with Mesa's GL_TEXTURE_2D is in test_oracle_gl.cpp.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/core/errors.h>
#include <exbsp/mesh/mesh_io.h>
#include <exbsp/view/png_io.h>
#include <exbsp/view/stages.h>
#include <exbsp/view/texture.h>
#include "geom/rational.h"
#include "scene/render.h"
#include "scene/scene.h"
#include "support/test_helpers.h"
#include "view/texture_uvs.h"

namespace {

using namespace exbsp;
namespace fs = std::filesystem;
using uv3 = std::array<vec2d, 3>;

// ---- readers ----------------------------------------------------------------------------

TEST(TextureReaders, ObjFaceCornersTakeTheirVtIncludingNegativeIndices) {
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0.25 1 0\n"
      "f 1/1 2/2/1 3/-2 4/-1\n";
  const triangle_soup s = read_mesh_data(obj, mesh_format::obj, "q.obj");
  ASSERT_TRUE(s.has_uvs());
  ASSERT_EQ(s.triangles.size(), 2u);
  EXPECT_EQ(s.triangle_uvs[0], (uv3{{{0, 0}, {1, 0}, {1, 1}}}));
  EXPECT_EQ(s.triangle_uvs[1], (uv3{{{0, 0}, {1, 1}, {0.25, 1}}}));
  // "vt u" alone: v = 0.
  const triangle_soup u = read_mesh_data("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5\nf 1/1 2/1 3/1\n",
                                         mesh_format::obj, "u.obj");
  EXPECT_EQ(u.triangle_uvs.at(0)[2], (vec2d{0.5, 0}));
}

TEST(TextureReaders, ObjWithoutVtHasNoUvsAndFacesWithoutVtGetZeros) {
  const std::string plain = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1//1 2//1 3//1\n";
  EXPECT_FALSE(read_mesh_data(plain, mesh_format::obj, "p.obj").has_uvs());
  const triangle_soup mixed = read_mesh_data(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.5\nf 1 2 3\nf 1/1 2/1 3/1\n", mesh_format::obj, "m.obj");
  ASSERT_TRUE(mixed.has_uvs());
  EXPECT_EQ(mixed.triangle_uvs[0], uv3{});
  EXPECT_EQ(mixed.triangle_uvs[1][1], (vec2d{0.5, 0.5}));
}

TEST(TextureReaders, BadObjTextureCoordinatesNameFileAndLine) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const auto check = [&](const std::string& body, std::size_t line, const std::string& words) {
    const input_error e = exbsp_test::mesh_data_error(v + body, mesh_format::obj, "bad.obj");
    EXPECT_EQ(e.file(), "bad.obj");
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  };
  check("vt nan 0\n", 4, "not a finite number");
  check("vt 0 inf\n", 4, "not a finite number");
  check("vt 0 1e999\n", 4, "not a finite number");
  check("vt\n", 4, "expected u [v [w]]");
  check("vt 0 0\nf 1/1 2/2 3/1\n", 5, "texture coordinate index 2 out of range");
  check("vt 0 0\nf 1/1 2/-2 3/1\n", 5, "texture coordinate index -2 out of range");
  check("f 1/1 2/1 3/1\nvt 0 0\n", 4, "texture coordinate index 1 out of range");
  check("vt 0 0\nf 1/0 2/1 3/1\n", 5, "texture coordinate index 0 is invalid");
}

TEST(TextureReaders, PlyVertexUvStAndTextureUvProperties) {
  const auto ply = [](const std::string& a, const std::string& b, const std::string& type) {
    return "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
           "property float z\nproperty " +
           type + " " + a + "\nproperty " + type + " " + b +
           "\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
           "0 0 0 0 0\n1 0 0 1 0\n1 1 0 1 1\n0 1 0 0.125 1\n4 0 1 2 3\n";
  };
  for (const auto& names : {std::array<std::string, 2>{"u", "v"},
                            {"s", "t"},
                            {"texture_u", "texture_v"},
                            {"texture_s", "texture_t"}}) {
    const triangle_soup s =
        read_mesh_data(ply(names[0], names[1], "double"), mesh_format::ply, "t.ply");
    ASSERT_TRUE(s.has_uvs()) << names[0];
    EXPECT_EQ(s.triangle_uvs[1], (uv3{{{0, 0}, {1, 1}, {0.125, 1}}})) << names[0];
  }
  // One of a pair alone is not texture coordinates.
  EXPECT_FALSE(read_mesh_data(ply("u", "w", "float"), mesh_format::ply, "o.ply").has_uvs());
}

TEST(TextureReaders, PlyBinaryFloatUvsAndNonFiniteErrors) {
  // binary_little_endian: x y z u v as float32.
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float "
      "y\nproperty float z\nproperty float u\nproperty float v\nelement face 1\nproperty list "
      "uchar int vertex_indices\nend_header\n";
  const auto put_float = [&](float value) {
    char b[4];
    std::memcpy(b, &value, 4);
    ply.append(b, 4);
  };
  const float verts[3][5] = {{0, 0, 0, 0.5f, 0.25f}, {1, 0, 0, 1, 0}, {0, 1, 0, 0, 1}};
  for (const auto& vert : verts)
    for (float c : vert) put_float(c);
  ply += '\x03';
  for (int i : {0, 1, 2}) {
    char b[4];
    std::memcpy(b, &i, 4);
    ply.append(b, 4);
  }
  const triangle_soup s = read_mesh_data(ply, mesh_format::ply, "b.ply");
  ASSERT_TRUE(s.has_uvs());
  EXPECT_EQ(s.triangle_uvs[0], (uv3{{{0.5, 0.25}, {1, 0}, {0, 1}}}));
  // A NaN texture coordinate in the binary body: line 0, the element and byte offset named.
  std::string bad = ply;
  const float nan = std::nanf("");
  std::memcpy(&bad[bad.find("end_header\n") + 11 + 12], &nan, 4);
  const input_error e = exbsp_test::mesh_data_error(bad, mesh_format::ply, "b.ply");
  EXPECT_EQ(e.line(), 0u);
  EXPECT_NE(std::string(e.what()).find("texture coordinate 'u' is not finite"), std::string::npos)
      << e.what();
  // ascii: the line.
  const std::string ascii =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty "
      "double z\nproperty double s\nproperty double t\nelement face 1\nproperty list uchar int "
      "vertex_indices\nend_header\n0 0 0 0 0\n1 0 0 nan 0\n0 1 0 0 1\n3 0 1 2\n";
  const input_error a = exbsp_test::mesh_data_error(ascii, mesh_format::ply, "a.ply");
  EXPECT_EQ(a.line(), 13u) << a.what();
  EXPECT_NE(std::string(a.what()).find("texture coordinate 's'"), std::string::npos) << a.what();
}

TEST(TextureReaders, SoupAppendKeepsUvsAlignedWithTriangles) {
  triangle_soup a, b;
  a.add_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  b.vertices = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  b.add_polygon({0, 1, 2}, {{0.5, 0.5}, {1, 0.5}, {0.5, 1}}, 0);
  triangle_soup c = a;
  c.append(b);
  ASSERT_TRUE(c.has_uvs());
  EXPECT_EQ(c.triangle_uvs[0], uv3{});
  EXPECT_EQ(c.triangle_uvs[1], b.triangle_uvs[0]);
  b.append(a);
  ASSERT_TRUE(b.has_uvs());
  EXPECT_EQ(b.triangle_uvs[1], uv3{});
  EXPECT_FALSE(a.has_uvs());
}

// ---- exact UVs through splits ----------------------------------------------------------

using q3 = std::array<mpq_class, 3>;

/// The UV at exact point p of triangle (a, b, c): barycentric coordinates from the Gram system
/// of the edge vectors (not the 2D projection texture_uvs uses), exact, then rounded once.
vec2d reference_uv(const q3& p, const std::array<vec3d, 3>& t, const uv3& uv) {
  q3 e1, e2, d;
  for (int k = 0; k < 3; ++k) {
    e1[k] = mpq_class(t[1][k]) - mpq_class(t[0][k]);
    e2[k] = mpq_class(t[2][k]) - mpq_class(t[0][k]);
    d[k] = p[k] - mpq_class(t[0][k]);
  }
  const auto dot = [](const q3& x, const q3& y) {
    return mpq_class(x[0] * y[0] + x[1] * y[1] + x[2] * y[2]);
  };
  const mpq_class g11 = dot(e1, e1), g12 = dot(e1, e2), g22 = dot(e2, e2);
  const mpq_class r1 = dot(e1, d), r2 = dot(e2, d);
  const mpq_class det = g11 * g22 - g12 * g12;
  const mpq_class lb = (r1 * g22 - r2 * g12) / det, lc = (g11 * r2 - g12 * r1) / det;
  // p lies in the plane: the residual of the solution is exactly zero.
  for (int k = 0; k < 3; ++k) EXPECT_EQ(mpq_class(lb * e1[k] + lc * e2[k]), d[k]);
  // uv(p) = uv_a + l_b (uv_b - uv_a) + l_c (uv_c - uv_a), exactly, then one rounding.
  vec2d out;
  for (int c = 0; c < 2; ++c) {
    const mpq_class origin(uv[0][c]);
    mpq_class value = lb * (mpq_class(uv[1][c]) - origin);
    value += lc * (mpq_class(uv[2][c]) - origin);
    value += origin;
    out[c] = geom::rational_to_double(value.get_mpq_t());
  }
  return out;
}

/// The face id of the textured quad in split_quad_frame.
constexpr std::uint32_t quad_face = 3;

/// A textured quad (two triangles, UVs with awkward fractions; mesh 1, face quad_face) after
/// three slanted cutting triangles (mesh 0, untextured), at split parameters that are not
/// dyadic, so that the exact UVs need rounding. The naive heuristic takes the triangles in
/// order as splitters: the cutters' planes split the quad.
view::frame split_quad_frame(kernel_id kernel) {
  triangle_soup s;
  exbsp_test::add_quad(s, {-0.3, -2, -1}, {0.2, 2, -1}, {0.1, 2, 1}, {-0.4, -2, 1});
  s.add_triangle({-2, 0.3, -1}, {2, 0.1, 1.3}, {0, 0.7, 1.1});
  s.add_triangle({-2, -0.7, 0.9}, {2, 0.4, -1.3}, {1, -0.2, 1});
  const auto base = static_cast<std::uint32_t>(s.vertices.size());
  s.vertices.insert(s.vertices.end(),
                    {{-1, -1, 0}, {1.1, -0.9, 0.05}, {1, 1.3, 0.1}, {-0.9, 1, 0}});
  s.add_polygon({base, base + 1, base + 2, base + 3},
                {{0.1, 0.3}, {2.7, -0.2}, {3.3, 1.9}, {-0.4, 2.2}}, quad_face);
  view::frame f;
  f.soup = std::move(s);
  f.build.kernel = kernel;
  f.build.heuristic = "naive";
  const auto tex = std::make_shared<const view::texture>(view::image(2, 2, {10, 20, 30}),
                                                         view::texture::filter_kind::nearest,
                                                         view::texture::wrap_kind::repeat);
  f.mesh_textures = {nullptr, tex};
  f.mesh_face_offsets = {0, quad_face, f.soup.face_count};
  return f;
}

class TextureExactUvs : public ::testing::TestWithParam<kernel_id> {};

TEST_P(TextureExactUvs, EveryFragmentCornerIsTheExactBarycentricUvRoundedOnce) {
  view::frame f = split_quad_frame(GetParam());
  view::build_stage(f);
  ASSERT_EQ(f.fragment_uvs.size(), f.fragments.size());
  std::size_t quad_fragments = 0, inexact = 0;
  for (std::size_t i = 0; i < f.fragments.size(); ++i) {
    const std::uint32_t src = f.tree->fragment_source(i);
    if (f.fragments[i].face != quad_face) {
      EXPECT_EQ(f.fragment_uvs[i], uv3{}) << "untextured mesh, fragment " << i;
      continue;
    }
    ++quad_fragments;
    const auto& tv = f.soup.triangles[src].v;
    const std::array<vec3d, 3> t = {f.soup.vertices[tv[0]], f.soup.vertices[tv[1]],
                                    f.soup.vertices[tv[2]]};
    const exact_triangle e = f.tree->fragment_exact(i);
    for (int k = 0; k < 3; ++k) {
      const q3 p = {mpq_class(e[k][0]), mpq_class(e[k][1]), mpq_class(e[k][2])};
      const vec2d want = reference_uv(p, t, f.soup.triangle_uvs[src]);
      EXPECT_EQ(f.fragment_uvs[i][k], want) << "fragment " << i << " corner " << k;
      // Rounding once from the exact corner differs from interpolating at the double corner
      // somewhere: the exactness is observable.
      const q3 pd = {mpq_class(f.fragments[i].v[k][0]), mpq_class(f.fragments[i].v[k][1]),
                     mpq_class(f.fragments[i].v[k][2])};
      if (pd != p) ++inexact;
    }
  }
  EXPECT_GT(quad_fragments, 4u) << "the quad must be split";
  EXPECT_GT(inexact, 0u) << "some split point must not be a double";
}

INSTANTIATE_TEST_SUITE_P(ExactKernels, TextureExactUvs,
                         ::testing::Values(kernel_id::exact, kernel_id::epeck, kernel_id::gmpq),
                         [](const ::testing::TestParamInfo<kernel_id>& p) {
                           return to_string(p.param);
                         });

TEST(TextureUvs, InexactKernelsInterpolateAtTheirDoubleCorners) {
  view::frame f = split_quad_frame(kernel_id::epick);
  view::build_stage(f);
  for (std::size_t i = 0; i < f.fragments.size(); ++i) {
    if (f.fragments[i].face != quad_face) continue;
    for (int k = 0; k < 3; ++k) {
      // Close to the exact plane's interpolation (the double corner is off the plane by a
      // rounding error); no exact value exists.
      const vec2d& uv = f.fragment_uvs[i][k];
      EXPECT_TRUE(std::isfinite(uv[0]) && std::isfinite(uv[1]));
      EXPECT_LT(std::abs(uv[0]), 10.0);
    }
  }
}

TEST(TextureUvs, NoTextureNoUvsAndNoCost) {
  view::frame f = split_quad_frame(kernel_id::exact);
  f.mesh_textures.clear();
  view::build_stage(f);
  EXPECT_TRUE(f.fragment_uvs.empty());
}

TEST(TextureUvs, DepthSortTeachingViewUsesTheTrianglesOwnUvs) {
  view::frame f = split_quad_frame(kernel_id::exact);
  f.visibility = view::visibility_order::depth_sort_centroid;  // no tree: the input triangles
  view::build_stage(f);
  ASSERT_EQ(f.fragment_uvs.size(), f.soup.triangles.size());
  for (std::size_t t = 0; t < f.soup.triangles.size(); ++t) {
    if (f.soup.triangles[t].face == quad_face) {
      EXPECT_EQ(f.fragment_uvs[t], f.soup.triangle_uvs[t]);
    }
  }
}

// ---- sampling ---------------------------------------------------------------------------

view::texture two_by_two(view::texture::filter_kind f, view::texture::wrap_kind w) {
  view::image img(2, 2, {0, 0, 0});
  img.set_pixel(0, 0, {0, 0, 0});    // bottom left: (u, v) in [0, 1/2)^2
  img.set_pixel(1, 0, {200, 0, 0});  // bottom right
  img.set_pixel(0, 1, {0, 100, 0});  // top left
  img.set_pixel(1, 1, {0, 0, 255});  // top right
  return view::texture(img, f, w);
}

TEST(TextureSampling, NearestPicksTheTexelUnderTheCoordinateBottomRowFirst) {
  using tk = view::texture;
  const tk t = two_by_two(tk::filter_kind::nearest, tk::wrap_kind::repeat);
  EXPECT_EQ(t.sample(0.25, 0.25), (view::rgb8{0, 0, 0}));
  EXPECT_EQ(t.sample(0.75, 0.25), (view::rgb8{200, 0, 0}));
  EXPECT_EQ(t.sample(0.25, 0.75), (view::rgb8{0, 100, 0}));
  EXPECT_EQ(t.sample(0.5, 0.5), (view::rgb8{0, 0, 255}));  // a boundary belongs to the next texel
  EXPECT_EQ(t.sample(1.75, -0.75), (view::rgb8{200, 0, 0}));  // repeat
  const tk c = two_by_two(tk::filter_kind::nearest, tk::wrap_kind::clamp);
  EXPECT_EQ(c.sample(7.0, -3.0), (view::rgb8{200, 0, 0}));
  EXPECT_EQ(t.mean, (view::rgb8{50, 25, 64}));
}

TEST(TextureSampling, BilinearWeightsTheFourNearestTexelCentres) {
  using tk = view::texture;
  const tk t = two_by_two(tk::filter_kind::linear, tk::wrap_kind::clamp);
  EXPECT_EQ(t.sample(0.5, 0.5), (view::rgb8{50, 25, 64}));  // the four centres, equally
  EXPECT_EQ(t.sample(0.25, 0.25), (view::rgb8{0, 0, 0}));   // a texel centre
  EXPECT_EQ(t.sample(0.5, 0.25), (view::rgb8{100, 0, 0}));  // half way along the bottom row
  EXPECT_EQ(t.sample(0.0, 0.25), (view::rgb8{0, 0, 0}));    // clamp: the edge texel alone
  const tk r = two_by_two(tk::filter_kind::linear, tk::wrap_kind::repeat);
  EXPECT_EQ(r.sample(0.0, 0.25), (view::rgb8{100, 0, 0}));  // repeat: wraps to the right column
  // 3/8 along u: alpha = 0.25 between the two bottom texels.
  EXPECT_EQ(t.sample(0.375, 0.25), (view::rgb8{50, 0, 0}));
}

TEST(TextureSampling, ModulateKeepsTheTexelUnderWhite) {
  for (int c = 0; c < 256; c += 15) {
    const auto b = static_cast<std::uint8_t>(c);
    EXPECT_EQ(view::modulate({b, b, b}, {255, 255, 255}), (view::rgb8{b, b, b}));
  }
  EXPECT_EQ(view::modulate({200, 100, 255}, {128, 0, 255}), (view::rgb8{100, 0, 255}));
}

// ---- scenes -----------------------------------------------------------------------------

struct scene_dir {
  fs::path dir = exbsp_test::make_temp_dir("test_texture");
  fs::path write(const std::string& name, const std::string& text) const {
    exbsp_test::write_file(dir / name, text);
    return dir / name;
  }
  std::string scene(const std::string& mesh, const std::string& texture) const {
    return R"({"meshes": [{"file": ")" + mesh + R"(", "texture": )" + texture +
           R"(}], "camera": {"eye": [0.5, -2, 2], "look_at": [0.5, 0.5, 0], "up": [0, 0, 1]},
         "projection": {"type": "perspective", "fovy_deg": 50, "near": 0.5, "far": 20},
         "viewport": {"width": 64, "height": 48}})";
  }
};

const char* quad_obj =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 2 0\nvt 2 2\nvt 0 2\nf 1/1 2/2 3/3 4/4\n";

TEST(TextureScene, KeyErrorsNameTheKey) {
  const scene_dir d;
  d.write("quad.obj", quad_obj);
  d.write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  view::write_png(view::image(2, 2, {255, 0, 0}), (d.dir / "red.png").string());
  d.write("garbage.png", "not a png");
  const auto key = [&](const std::string& mesh, const std::string& tex) {
    const fs::path p = d.write("s.json", d.scene(mesh, tex));
    return exbsp_test::error_key([&] { scene::load_geometry(scene::load_scene(p.string())); });
  };
  EXPECT_EQ(key("quad.obj", R"({"png": "red.png"})"), "(no error)");
  EXPECT_EQ(key("quad.obj", R"({"png": "missing.png"})"), "/meshes/0/texture/png");
  EXPECT_EQ(key("quad.obj", R"({"png": "garbage.png"})"), "/meshes/0/texture/png");
  EXPECT_EQ(key("quad.obj", R"({"png": ""})"), "/meshes/0/texture/png");
  EXPECT_EQ(key("quad.obj", R"({"filter": "linear"})"), "/meshes/0/texture/png");
  EXPECT_EQ(key("quad.obj", R"({"png": "red.png", "filter": "cubic"})"),
            "/meshes/0/texture/filter");
  EXPECT_EQ(key("quad.obj", R"({"png": "red.png", "wrap": "mirror"})"), "/meshes/0/texture/wrap");
  EXPECT_EQ(key("quad.obj", R"("red.png")"), "/meshes/0/texture");
  std::string message;
  const fs::path p = d.write("s.json", d.scene("plain.obj", R"({"png": "red.png"})"));
  EXPECT_EQ(
      exbsp_test::error_key([&] { scene::load_geometry(scene::load_scene(p.string())); }, &message),
      "/meshes/0/texture");
  EXPECT_NE(message.find("no texture coordinates"), std::string::npos) << message;
}

TEST(TextureScene, TransformsAreTheTextureMatrixAppliedToEveryCorner) {
  // glMatrixMode(GL_TEXTURE); glTranslated(0.5, 0, 0); glScaled(2, 3, 1): (s, t) ->
  // (2 s + 0.5, 3 t), per vertex as OpenGL applies it, before any interpolation.
  const scene_dir d;
  d.write("quad.obj", quad_obj);
  view::write_png(view::image(2, 2, {255, 0, 0}), (d.dir / "red.png").string());
  const fs::path p = d.write(
      "s.json", d.scene("quad.obj", R"({"png": "red.png", "transforms": [{"translate": [0.5, 0, 0]},
                                                             {"scale": [2, 3, 1]}]})"));
  const scene::scene_geometry g = scene::load_geometry(scene::load_scene(p.string()));
  ASSERT_TRUE(g.soup.has_uvs());
  EXPECT_EQ(g.soup.triangle_uvs[0], (uv3{{{0.5, 0}, {4.5, 0}, {4.5, 6}}}));
  EXPECT_EQ(g.soup.triangle_uvs[1], (uv3{{{0.5, 0}, {4.5, 6}, {0.5, 6}}}));
  // A projective texture matrix (q != 1) is refused, naming the key.
  const fs::path q = d.write(
      "q.json",
      d.scene("quad.obj", R"({"png": "red.png", "transforms": [{"matrix": [1, 0, 0, 0, 0, 1, 0, 0,
              0, 0, 1, 0, 0.5, 0, 0, 1], "order": "row-major"}]})"));
  EXPECT_EQ(exbsp_test::error_key([&] { scene::load_scene(q.string()); }),
            "/meshes/0/texture/transforms");
}

TEST(TextureScene, PngSamplesTheTextureSvgFillsWithItsMean) {
  const scene_dir d;
  d.write("quad.obj", quad_obj);
  view::image checker(2, 2, {250, 250, 250});
  checker.set_pixel(0, 0, {10, 10, 200});
  checker.set_pixel(1, 1, {10, 10, 200});
  view::write_png(checker, (d.dir / "checker.png").string());
  const fs::path p = d.write("s.json", d.scene("quad.obj", R"({"png": "checker.png"})"));
  std::ostringstream log;
  render_command({p.string(), (d.dir / "out.png").string()}, log);
  const view::image img = view::read_png((d.dir / "out.png").string());
  const auto colours = exbsp_test::colours_of(img);
  EXPECT_TRUE(colours.count({10, 10, 200})) << "the texture's blue squares are drawn";
  EXPECT_TRUE(colours.count({250, 250, 250}));
  EXPECT_FALSE(colours.count({160, 160, 160})) << "no untextured default grey";
  render_command({p.string(), (d.dir / "out.svg").string()}, log);
  const std::string svg = exbsp_test::read_file(d.dir / "out.svg");
  EXPECT_NE(svg.find("#8282e1"), std::string::npos) << "the texture's mean (130, 130, 225)";
}

// ---- untextured scenes are unchanged ----------------------------------------------------

class UntexturedScenePictures : public ::testing::TestWithParam<std::string> {};

TEST_P(UntexturedScenePictures, AreByteIdenticalToTheCommittedOnes) {
  const std::string src = EXBSP_SOURCE_DIR;
  const fs::path out = exbsp_test::make_temp_dir("test_texture_bytes") / (GetParam() + ".png");
  std::ostringstream log;
  render_command({src + "/scenes/" + GetParam() + ".json", out.string()}, log);
  EXPECT_TRUE(exbsp_test::read_file(out) ==
              exbsp_test::read_file(src + "/scenes/images/" + GetParam() + ".png"))
      << GetParam() << ": the PNG differs from scenes/images/" << GetParam() << ".png";
}

INSTANTIATE_TEST_SUITE_P(Committed, UntexturedScenePictures,
                         ::testing::Values("effects_lighting", "effects_smooth", "groups",
                                           "camera_look"));

}  // namespace
