// SPDX-License-Identifier: LGPL-3.0-or-later
// Inputs the fuzzers found (tests/fuzz/crashes/): each must now end in a clear exbsp error.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include <exbsp/core/errors.h>
#include "scene/scene.h"
#include "support/test_helpers.h"

namespace {

using exbsp_test::read_file;

TEST(FuzzRegressions, scene_findings_are_scene_errors_naming_the_file) {
  const std::filesystem::path dir =
      std::filesystem::path(EXBSP_SOURCE_DIR) / "tests/fuzz/crashes/fuzz_scene";
  std::size_t checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    const std::string name = entry.path().filename().string();
    std::ostringstream warnings;
    try {
      exbsp::scene::parse_scene_text(read_file(entry.path()), name, &warnings);
      ADD_FAILURE() << name << ": accepted";
    } catch (const exbsp::scene_error& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << name << ": escaped as " << e.what();
    }
    ++checked;
  }
  EXPECT_GE(checked, 5u);
}

TEST(FuzzRegressions, json_number_overflow_is_a_scene_error) {
  EXPECT_THROW(exbsp::scene::parse_scene_text("1e400", "x.json", nullptr), exbsp::scene_error);
}

}  // namespace
