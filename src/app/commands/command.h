// SPDX-License-Identifier: LGPL-3.0-or-later
// One `exbsp` subcommand per file in this folder (docs/contract.md "Command line"): each adds
// its options to its subcommand when it is made and does its work in run(). main.cpp holds
// the table of commands (name, one-line description, factory), makes each subcommand and maps
// the library's exceptions to messages and exit codes. Every command file starts alike (a
// class deriving from command that adds its options in its constructor): the form is the
// interface, not copied logic.
#pragma once
#include <memory>

namespace CLI {
class App;
}

namespace exbsp::cli {

class command {
 public:
  /// `subcommand`: the command's own subcommand, made by main from the command table.
  explicit command(CLI::App& subcommand) : sub(&subcommand) {}
  virtual ~command() = default;
  /// Runs the command once the command line is parsed and this command chosen; returns the
  /// exit status. Library errors are thrown (main maps them to exit codes).
  virtual int run() = 0;
  /// True when the command builds a tree, so that a limit_error may be --max-fragments's.
  virtual bool builds_tree() const { return false; }
  /// The subcommand this command adds its options to.
  CLI::App* sub = nullptr;
};

/// Makes a command and adds its options to its subcommand.
using command_factory = std::unique_ptr<command> (*)(CLI::App& subcommand);

/// One row of main.cpp's command table.
struct command_row {
  const char* name;         ///< the subcommand's name, `exbsp NAME`
  const char* description;  ///< its one-line description in --help
  command_factory make;
};

std::unique_ptr<command> make_build_command(CLI::App& subcommand);     // commands/build.cpp
std::unique_ptr<command> make_order_command(CLI::App& subcommand);     // commands/order.cpp
std::unique_ptr<command> make_render_command(CLI::App& subcommand);    // commands/render.cpp
std::unique_ptr<command> make_section_command(CLI::App& subcommand);   // commands/section.cpp
std::unique_ptr<command> make_clip_command(CLI::App& subcommand);      // commands/clip.cpp
std::unique_ptr<command> make_drawing_command(CLI::App& subcommand);   // commands/drawing.cpp
std::unique_ptr<command> make_matrices_command(CLI::App& subcommand);  // commands/matrices.cpp

}  // namespace exbsp::cli
