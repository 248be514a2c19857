// SPDX-License-Identifier: LGPL-3.0-or-later
// One `exbsp` subcommand per file in this folder (docs/contract.md "Command line"): each adds
// its options to the command line when it is made and does its work in run(). main.cpp holds
// the table of commands and maps the library's exceptions to messages and exit codes. Every
// command file starts alike (a class deriving from command that adds its subcommand in its
// constructor): the form is the interface, not copied logic.
#pragma once
#include <memory>

namespace CLI {
class App;
}

namespace exbsp::cli {

class command {
 public:
  virtual ~command() = default;
  /// Runs the command once the command line is parsed and this command chosen; returns the
  /// exit status. Library errors are thrown (main maps them to exit codes).
  virtual int run() = 0;
  /// True when the command builds a tree, so that a limit_error may be --max-fragments's.
  virtual bool builds_tree() const { return false; }
  /// The subcommand this command added to the command line.
  CLI::App* sub = nullptr;
};

/// Makes a command and adds its subcommand and options to `app`.
using command_factory = std::unique_ptr<command> (*)(CLI::App& app);

std::unique_ptr<command> make_build_command(CLI::App& app);    // commands/build.cpp
std::unique_ptr<command> make_order_command(CLI::App& app);    // commands/order.cpp
std::unique_ptr<command> make_render_command(CLI::App& app);   // commands/render.cpp
std::unique_ptr<command> make_section_command(CLI::App& app);  // commands/section.cpp
std::unique_ptr<command> make_clip_command(CLI::App& app);     // commands/clip.cpp
std::unique_ptr<command> make_drawing_command(CLI::App& app);  // commands/drawing.cpp

}  // namespace exbsp::cli
