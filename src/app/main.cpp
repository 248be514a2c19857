// SPDX-License-Identifier: LGPL-3.0-or-later
// exbsp command line (docs/contract.md "Command line"): glue only. The commands are in
// commands/, one file each; this file holds their table, parses the command line and maps
// library exceptions to messages "exbsp: error: ..." on stderr and exit codes: 2 bad input, bad
// usage or an output that cannot be written; 3 resource limit (--max-fragments, whose default
// comes from the available memory, or out of memory).
#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include <exbsp/core/errors.h>
#include <exbsp/core/version.h>
#include <exbsp/mesh/gmp_memory.h>
#include "app/cli_docs.h"
#include "app/cli_parse.h"
#include "app/commands/command.h"
#include "app/resources.h"
#include "core/name_list.h"

namespace {

/// The commands, in the order of `exbsp --help`: one row each (its rows are alike by design, the
/// form of a plug-in table).
const exbsp::cli::command_row commands[] = {
    {"build", "build the BSP tree of MESH and print its statistics",
     exbsp::cli::make_build_command},
    {"order", "write the back-to-front fragment order of MESH for an eye point or a direction",
     exbsp::cli::make_order_command},
    {"render",
     "render SCENE.json, a mesh with a view fitted to it, or the "
     "built-in demo scene to PNG, SVG or PDF",
     exbsp::cli::make_render_command},
    {"section", "cut MESH exactly by a plane: kept part, outline loops and (closed meshes) the cap",
     exbsp::cli::make_section_command},
    {"clip",
     "clip the segments and polygons of INPUT.json against its region "
     "(rect, box, convex, halfspaces)",
     exbsp::cli::make_clip_command},
    {"drawing",
     "a drawing sheet (ISO views, sections, title block) of a "
     "mesh, a scene or a folder of meshes, "
     "as SVG, PDF or DXF",
     exbsp::cli::make_drawing_command},
    {"matrices",
     "print every matrix of a scene's view: OpenGL's and the course's (M = Mvp Morth Mp Mv; "
     "Dpersp Sfar Sxy Mrot Ttrans), each chain with its product",
     exbsp::cli::make_matrices_command},
};

}  // namespace

int main(int argc, char** argv) {
  // First, before any GMP number exists: out of memory in GMP throws, never aborts.
  exbsp::install_gmp_memory_functions();
  exbsp::cli::fix_malloc_mmap_threshold();
  exbsp::cli::sanitize_omp_num_threads();
  exbsp::cli::start_thread_pool();
  CLI::App app{
      "exbsp: exact-predicate BSP trees of triangle meshes, back-to-front orders and rendering.\n"
      "Classification and splitting are exact (exbsp's own exact kernel by default), so trees and "
      "orders are\n"
      "the same on every machine."};
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", std::string("exbsp ") + exbsp::version_string,
                       "print the version and exit");
  std::vector<std::unique_ptr<exbsp::cli::command>> made;
  for (const exbsp::cli::command_row& row : commands)
    made.push_back(row.make(*app.add_subcommand(row.name, row.description)));
  // Hidden (no group): the man page and bash completion, made from the definitions above.
  bool man = false, completion = false;
  app.add_flag("--man", man, "print the man page (roff)")->group("");
  app.add_flag("--bash-completion", completion, "print a bash completion script")->group("");

  {
    std::vector<std::string> args(argv + 1, argv + argc);
    const std::string typo = exbsp::cli::misspelling(app, args);
    if (!typo.empty()) {
      std::cerr << "exbsp: error: " << typo << "\n"
                << "run 'exbsp --help' for usage\n";
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "exbsp: error: " << e.what() << "\n"
              << "run 'exbsp --help' for usage\n";
    return 2;
  }

  if (man || completion) {
    std::cout << (man ? exbsp::cli::man_page(app) : exbsp::cli::bash_completion(app));
    std::cout.flush();
    return std::cout ? 0 : 2;
  }
  exbsp::cli::command* chosen = nullptr;
  std::vector<std::string> command_names;
  for (const auto& c : made) {
    if (*c->sub) chosen = c.get();
    command_names.push_back(c->sub->get_name());
  }
  const std::string names = exbsp::name_list(command_names, "or");
  if (!chosen) {
    std::cerr << "exbsp: error: a command is required: " << names << "\n"
              << "run 'exbsp --help' for usage\n";
    return 2;
  }
  try {
    return chosen->run();
  } catch (const exbsp::limit_error& e) {
    std::cerr << "exbsp: error: " << e.what() << "\n";
    if (chosen->builds_tree() && std::string(e.what()).find("--max-fragments") != std::string::npos)
      std::cerr << "exbsp: the limit is --max-fragments (default: from the available memory); "
                   "raise it with "
                   "--max-fragments N, or 0 for no limit\n";
    return 3;
  } catch (const exbsp::error& e) {  // input, scene, usage and output errors
    std::cerr << "exbsp: error: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "exbsp: error: out of memory (lower --max-fragments, or use a smaller input)\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "exbsp: error: " << e.what() << "\n";
    return 1;
  }
}
