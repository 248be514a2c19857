// SPDX-License-Identifier: LGPL-3.0-or-later
// The man page and the bash completion of `exbsp`, generated from the command line's own CLI11
// definitions (its commands, options, descriptions, value sets and defaults), so that they
// never drift from it: `exbsp --man` and `exbsp --bash-completion` print them, and the build
// installs them (share/man/man1/exbsp.1, share/bash-completion/completions/exbsp).
#pragma once
#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace exbsp::cli {

/// The man page (roff, section 1) of `app` and its subcommands.
std::string man_page(const CLI::App& app);

/// A bash completion script for `app`: commands, each command's options, the values of
/// options that take one of a set ({a,b,c} in CLI11's type name) and file names elsewhere.
std::string bash_completion(const CLI::App& app);

/// The values an option takes when its type name lists them ("TEXT:{exact,epeck}"), else {}.
std::vector<std::string> option_choices(const CLI::Option& option);

}  // namespace exbsp::cli
