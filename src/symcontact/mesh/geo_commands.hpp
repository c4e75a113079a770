#pragma once
/// \file geo_commands.hpp
/// What a .geo file says before Gmsh runs it: the commands that run other programs (refused), and the
/// constants a problem file may set (mesh_parameters).
///
/// Gmsh's .geo language can run other programs: `SystemCall "cmd"` (also spelt `System`),
/// `NonBlockingSystemCall "cmd"` and `OnelabRun("name", "cmd")` hand a command to the shell while the
/// file is parsed, that is during `symcontact check` as well as `run`. A problem file and its meshes are
/// data; a .geo from someone else must not run commands on the reader's machine. This check refuses such
/// a file before Gmsh sees it (the CLI's --allow-geo-commands skips it).
///
/// The scan reads the file as Gmsh's lexer does: comments (`//`, `/* */`) and string literals are
/// skipped, and any identifier equal to one of the command keywords is refused, with `Shell` too for
/// safety. Files pulled in with `Include "f"` or `Merge "f.geo"` are scanned the same way (relative
/// paths against the including file's folder); an Include or a Merge whose file name is computed (not a
/// string literal) cannot be followed and is refused as well.

#include <set>
#include <string>

namespace symcontact {

/// Throws InputError(file, "line L", message naming the command) for the first command that runs a
/// program in `path` or a file it includes; returns when there is none.
void check_geo_commands(const std::string& path);

/// The names declared by `DefineConstant[ name = value, ... ]` in `path` and the .geo files it includes
/// (read with the same lexical rules; an Include with a computed name is not followed). These are the
/// names Gmsh's `-setnumber name value` overrides: -setnumber defines the variable before the file is
/// parsed and DefineConstant keeps an existing value, whereas a plain assignment `name = value;`
/// replaces it. Throws InputError(file) for a file that cannot be read.
std::set<std::string> geo_defined_constants(const std::string& path);

/// True when `name` is a Gmsh identifier: a letter or '_', then letters, digits and '_'.
bool is_geo_identifier(const std::string& name);

}  // namespace symcontact
