#pragma once
/// \file output_folder.hpp
/// Whether results can be written to a folder, found before any work (the CLI's --out), so that a run
/// does not mesh and solve for minutes and then fail on its first file.

#include <string>

namespace symcontact {

/// Returns "" when the folder `dir` exists and is writable, or can be created; otherwise why not, as a
/// clause to append to the folder's name:
/// - "is a file, not a folder" (any existing non-folder, after following symbolic links);
/// - "is under 'P', which is a file, not a folder";
/// - "is too long (N characters, at most M ...)" when the absolute path leaves less than NAME_MAX
///   characters below PATH_MAX for the file names written in it, or "has a part of N characters, more
///   than the limit of 255" for a single component longer than NAME_MAX;
/// - "is not writable: 'A' ..." when the folder, or its nearest existing parent A (where it would be
///   created), does not let us create entries: checked with access(W_OK | X_OK) and then by creating and
///   removing an empty folder in A, which also catches read-only file systems and root's limits.
/// The check leaves nothing behind. "" is returned for "" (the current folder) when that is writable.
std::string output_folder_problem(const std::string& dir);

}  // namespace symcontact
