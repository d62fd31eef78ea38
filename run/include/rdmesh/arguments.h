// The command line as users type it: single-dash (Gmsh-style) flags refused up
// front, CLI11's parse errors reworded to name the option and what it allows,
// and the command line quoted back for the report.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace rdmesh::run {

/// The first argument that looks like a Gmsh-style single-dash option
/// (`-optimize`, `-order`, `-3`... but not a number after an option, `--size -0.5`, nor the short
/// options `-o`, `-q`, `-h` themselves): CLI11 would read `-optimize` as
/// `-o ptimize`. Arguments after `--` are files. `allowed_short`: the letters of
/// the command's short options.
std::optional<std::string> single_dash_option(int argc, const char* const* argv,
                                              const std::string& allowed_short);

/// "unknown option '-optimize' (rdmesh's options start with two dashes, e.g.
/// --size; the short ones are -o, -q and -h; rdmesh --help lists them)".
std::string unknown_single_dash_message(const std::string& arg, const std::string& command);

/// A parse error as one sentence naming the option and what it accepts.
std::string parse_error_message(const CLI::ParseError& e, const CLI::App& app,
                                const std::string& command);

/// The arguments joined by spaces, each quoted for a POSIX shell when needed.
std::string command_line_text(int argc, const char* const* argv);

/// Validator of a finite number, with the option's own wording.
CLI::Validator finite_number();

}  // namespace rdmesh::run
