// SPDX-License-Identifier: LGPL-3.0-or-later
// The module layout (docs/architecture.md, docs/contract.md section 1), checked on the source
// tree: every #include line of src/ and include/exbsp/ is listed with the module of the file
// that holds it and the module (or outside library) it names, and each floor may only include
// what lies below it. geom is the floor under bsp and clip, which are siblings (issue 26).
//
// One include dialect (issue 26): a public header, in include/exbsp/, is always named
// <exbsp/module/x.h>; a private one, in src/, "module/x.h" (rooted at src/, never "../" or a
// bare "x.h"); a public header includes no private one.
//
// Notation: a file's module is its first folder under src/ or include/exbsp/ ("" for
// include/exbsp/exbsp.h); an include's target is the module it names: the second component of
// <exbsp/module/x.h>, the first of "module/x.h"; for other <...> includes it is the first path
// component ("nlohmann", "CGAL", "vector").
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct include_line {
  std::string file;     ///< path under the source tree (src/... or include/exbsp/...)
  int line = 0;         ///< 1-based
  std::string module;   ///< the file's module
  bool quoted = false;  ///< "..." rather than <...>
  std::string named;    ///< the path as written between the quotes or brackets
  std::string target;   ///< the included module or library
  std::string text;     ///< the line as written
};

std::string first_component(const fs::path& p) {
  return p.begin() == p.end() ? std::string() : p.begin()->string();
}

/// Every #include line of the C++ files under `folder` (src or include/exbsp).
void list_includes(const fs::path& folder, std::vector<include_line>& out) {
  const fs::path root(EXBSP_SOURCE_DIR);
  static const std::regex include_re(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])");
  for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
    if (!entry.is_regular_file()) continue;
    const std::string ext = entry.path().extension().string();
    if (ext != ".h" && ext != ".cpp" && ext != ".in") continue;
    const fs::path rel = entry.path().lexically_relative(root / folder);
    const std::string module = rel.has_parent_path() ? first_component(rel) : "";
    std::ifstream in(entry.path());
    std::string text;
    int number = 0;
    while (std::getline(in, text)) {
      ++number;
      std::smatch m;
      if (!std::regex_search(text, m, include_re)) continue;
      const fs::path named(m[2].str());
      std::string target = first_component(named);
      if (m[1] == "<" && target == "exbsp")
        target = first_component(named.lexically_relative("exbsp"));
      out.push_back({(folder / rel).generic_string(), number, module, m[1] == "\"", m[2].str(),
                     target, text});
    }
  }
}

/// Every #include line of src/ and include/exbsp/.
std::vector<include_line> src_includes() {
  std::vector<include_line> out;
  list_includes("src", out);
  list_includes(fs::path("include") / "exbsp", out);
  return out;
}

/// The include lines of `module` whose target is one of `forbidden`, one per line of text.
std::string violations(const std::string& module, const std::set<std::string>& forbidden) {
  std::string found;
  for (const include_line& i : src_includes())
    if (i.module == module && forbidden.count(i.target))
      found += "  " + i.file + ":" + std::to_string(i.line) + ": " + i.text + "\n";
  return found;
}

TEST(Layout, the_include_lines_of_src_are_listed) {
  const std::vector<include_line> all = src_includes();
  // A sanity check of the listing itself: the modules and targets it must see.
  std::set<std::string> modules, targets;
  for (const include_line& i : all) {
    modules.insert(i.module);
    targets.insert(i.target);
  }
  for (const char* m : {"core", "mesh", "geom", "bsp", "clip", "view", "scene", "app"}) {
    EXPECT_TRUE(modules.count(m)) << m;
    EXPECT_TRUE(targets.count(m)) << m;
  }
  EXPECT_TRUE(targets.count("CGAL"));
  EXPECT_GT(all.size(), 500u);
}

TEST(Layout, one_include_dialect) {
  const fs::path root(EXBSP_SOURCE_DIR);
  std::string found;
  for (const include_line& i : src_includes()) {
    const bool in_public = i.file.rfind("include/", 0) == 0;
    if (i.quoted) {
      // Private headers only, rooted at src/; and never from a public header.
      if (in_public || !fs::path(i.named).has_parent_path() || i.named.rfind("../", 0) == 0 ||
          !fs::exists(root / "src" / i.named))
        found += "  " + i.file + ":" + std::to_string(i.line) + ": " + i.text + "\n";
    } else if (i.named.rfind("exbsp/", 0) == 0) {
      // A public header, in include/ (version.h and export.h are generated into build/include).
      const bool generated = i.named == "exbsp/core/version.h" || i.named == "exbsp/core/export.h";
      if (!generated && !fs::exists(root / "include" / i.named))
        found += "  " + i.file + ":" + std::to_string(i.line) + ": " + i.text + "\n";
    }
  }
  EXPECT_EQ(found, "") << "public headers as <exbsp/module/x.h>, private ones as \"module/x.h\"";
}

TEST(Layout, public_headers_live_in_include_only) {
  // A header of src/ that has the name of a public one would shadow it or be shadowed.
  const fs::path root(EXBSP_SOURCE_DIR);
  std::string found;
  for (const auto& entry : fs::recursive_directory_iterator(root / "include" / "exbsp"))
    if (entry.is_regular_file() &&
        fs::exists(root / "src" / entry.path().lexically_relative(root / "include" / "exbsp")))
      found += "  " + entry.path().lexically_relative(root).generic_string() + "\n";
  EXPECT_EQ(found, "");
}

TEST(Layout, clip_includes_no_bsp_header) {
  EXPECT_EQ(violations("clip", {"bsp"}), "") << "clip and bsp are siblings on geom";
}

TEST(Layout, bsp_includes_no_clip_header) {
  EXPECT_EQ(violations("bsp", {"clip"}), "") << "clip and bsp are siblings on geom";
}

TEST(Layout, geom_includes_nothing_above_it) {
  EXPECT_EQ(violations("geom", {"bsp", "clip", "view", "scene", "app", "adapters", "python"}), "")
      << "geom lies under bsp and clip";
}

TEST(Layout, core_and_mesh_include_nothing_above_them) {
  const std::set<std::string> above{"geom", "bsp", "clip", "view", "scene", "app"};
  EXPECT_EQ(violations("core", above), "");
  EXPECT_EQ(violations("mesh", above), "");
}

// Issue 26: JSON stops at scene; view takes typed settings (effect parameters are read by
// scene/effect_parameters.cpp).
TEST(Layout, view_includes_no_json_library) {
  EXPECT_EQ(violations("view", {"nlohmann"}), "") << "JSON stops at scene (issue 26)";
  EXPECT_EQ(violations("geom", {"nlohmann"}), "");
  EXPECT_EQ(violations("clip", {"nlohmann"}), "");
}

}  // namespace
