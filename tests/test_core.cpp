// SPDX-License-Identifier: LGPL-3.0-or-later
// Tests of src/core that no other module's tests cover: file kinds by extension
// (core/file_name.h), the one rule render, clip, section, the scene-or-mesh choice and the
// mesh reader share.
#include <gtest/gtest.h>

#include <string>

#include <exbsp/core/errors.h>
#include <exbsp/mesh/mesh_io.h>
#include "core/file_name.h"

namespace {

using exbsp::file_extension;
using exbsp::has_extension;

TEST(FileName, NoExtension) {
  EXPECT_EQ(file_extension(""), "");
  EXPECT_EQ(file_extension("out"), "");
  EXPECT_EQ(file_extension("a.b/out"), "");  // the dot belongs to a directory
  EXPECT_FALSE(has_extension("", ".png"));
  EXPECT_FALSE(has_extension("png", ".png"));
  EXPECT_FALSE(has_extension("a.png/out", ".png"));
}

TEST(FileName, LastDotAfterTheLastSlash) {
  EXPECT_EQ(file_extension("out.tar.png"), ".png");
  EXPECT_EQ(file_extension("a.b/x.svg"), ".svg");
  EXPECT_EQ(file_extension("dir/.png"), ".png");
  EXPECT_EQ(file_extension("trailing."), ".");
  EXPECT_TRUE(has_extension("out.tar.png", ".png"));
  EXPECT_FALSE(has_extension("out.png.tar", ".png"));
  EXPECT_FALSE(has_extension("out.pngx", ".png"));
  EXPECT_FALSE(has_extension("outpng", ".png"));
}

TEST(FileName, CaseIsIgnoredAsWritten) {
  EXPECT_EQ(file_extension("SCENE.Json"), ".Json");  // kept as written, for messages
  EXPECT_TRUE(has_extension("SCENE.Json", ".json"));
  EXPECT_TRUE(has_extension("x.PDF", ".pdf"));
  EXPECT_FALSE(has_extension("x.pdf", ".svg"));
}

TEST(FileName, MeshFormatsFollowTheSameRule) {
  EXPECT_EQ(exbsp::mesh_format_for_path("a.b/M.OFF"), exbsp::mesh_format::off);
  EXPECT_EQ(exbsp::mesh_format_for_path("m.Stl"), exbsp::mesh_format::stl);
  EXPECT_THROW(exbsp::mesh_format_for_path("a.off/mesh"), exbsp::input_error);
  try {
    exbsp::mesh_format_for_path("mesh.XYZ");
    FAIL() << "no error";
  } catch (const exbsp::input_error& e) {
    EXPECT_NE(std::string(e.what()).find("'.XYZ'"), std::string::npos) << e.what();
  }
}

}  // namespace
