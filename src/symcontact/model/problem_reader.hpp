#pragma once
/// \file problem_reader.hpp
/// Reads a TOML problem file (the schema is documented key by key in docs/input.md) into a
/// ProblemSpec (problem_spec.hpp). The reader checks everything that can be checked without loading
/// a mesh:
///
/// - syntax (toml++ parse errors, reported with line and column) and encoding (UTF-8), through the
///   guarded parser of toml_parse.hpp (toml++ 3.3 alone has undefined behaviour on some non-ASCII text);
/// - unknown keys in every table (the message lists the keys allowed there);
/// - types (an integer is accepted where a number is expected, never the other way round);
/// - values: every number finite (TOML allows nan and inf), ranges (E > 0, −1 < ν < 0.5, …),
///   vector lengths (`problem.dimension` components), per-load factor arrays as long as
///   `steps.load_factors`, unique body names, mesh files that exist and end in .geo or .msh;
/// - contact ([[contact]], [contact_solver], [ipopt]): contact surfaces "<body>.<boundary>" naming a
///   declared body, exactly one of `b` and `[contact.obstacle]`, obstacle keys that belong to the
///   obstacle's type (circle only in 2D, sphere only in 3D, a nonzero plane normal), `slave` only with
///   mode = "one-pass", unique contact names; friction = "none" | "tresca" | "coulomb" with `tau` ≥ 0
///   required for (and only allowed with) Tresca, `mu` ≥ 0 likewise for Coulomb, `alpha` > 0 optional
///   with either law; positive tolerances and iteration counts ≥ 1 in [contact_solver]; [ipopt] values
///   are strings, integers or floats; read_problem_file() (not parse_problem()) also sets them on an
///   IPOPT application, so that an unknown option or a value IPOPT rejects is an InputError with key
///   "ipopt.<name>" before any work;
/// - the problem file itself: a regular file (not a FIFO, a device, a folder or a symbolic link loop)
///   of at most 64 MiB (input_file.hpp), checked before it is opened; mesh files likewise regular files.
///
/// Every failure throws InputError(file, key, message) where `key` is the TOML path of the offending
/// value with bodies counted from 0 ("body[1].material.nu", "body[0].dirichlet[2]") and `message`
/// says what was expected and what was found ("expected a number in (-1, 0.5), got 0.5"). Syntax
/// errors have an empty key and a message starting "line L, column C: ".
///
/// Physical group names (body `group`, `boundary`, the group part of a contact surface) are only
/// checked for being non-empty strings: whether they exist in the mesh is checked when the meshes
/// are loaded, using the `key` of each spec item.

#include <string>

#include <toml++/toml.h>

#include "symcontact/model/problem_spec.hpp"

namespace symcontact {

/// Reads and validates the problem file at `path`. Mesh paths are resolved against the folder of
/// `path` (made absolute). Throws InputError (file = `path`) if the file cannot be read or is invalid.
ProblemSpec read_problem_file(const std::string& path);

/// Sets the options of [ipopt] (spec.contact_solver.friction.contact.ipopt) on an IPOPT application, as the contact
/// solve will: throws InputError(spec.file, "ipopt.<name>", IPOPT's objection) for the first option IPOPT
/// does not know or whose value it rejects. read_problem_file() calls it; parse_problem() does not.
void check_ipopt_section(const ProblemSpec& spec);

/// Validates the TOML document `toml_text`. `file_name` is used in error messages and stored in
/// ProblemSpec::file; relative mesh paths are resolved against `base_dir` (a folder; "" means the
/// current folder). Throws InputError on the first error found.
ProblemSpec parse_problem(const std::string& toml_text, const std::string& file_name, const std::string& base_dir);

/// parse_problem() on a document already parsed (parse_toml(), toml_parse.hpp): the same checks and
/// messages. For callers that edit a problem as a TOML document (the Python module).
ProblemSpec read_problem_table(const toml::table& root, const std::string& file_name, const std::string& base_dir);

/// The text of the problem file at `path`, after the checks of read_problem_file() on the file itself
/// (a regular file of at most 64 MiB, readable). Throws InputError(path, "", ...).
std::string read_problem_text(const std::string& path);

/// The folder read_problem_file() resolves `path`'s mesh paths against: its parent folder, absolute.
std::string problem_folder(const std::string& path);

}  // namespace symcontact
