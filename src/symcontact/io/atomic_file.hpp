#pragma once
/// \file atomic_file.hpp
/// Writing output files so that a reader (ParaView, a script polling a results folder) never sees a
/// half-written file, and a run killed mid-write leaves every file it had finished intact.

#include <functional>
#include <iosfwd>
#include <string>

namespace symcontact {

/// Writes a file by calling `writer` on a stream, all or nothing.
///
/// The content goes to the temporary file `path + ".tmp-<pid>"` in the same folder (so the final
/// rename stays on one file system); the stream is flushed, closed and checked, and the temporary
/// file is then renamed over `path` with std::rename, which is atomic on POSIX. An existing `path`
/// is replaced; until the rename it keeps its previous content.
///
/// Errors: if the temporary file cannot be opened, the stream is bad after writing, or the rename
/// fails, throws std::runtime_error naming `path`. If `writer` throws, its exception propagates.
/// In every failing case the temporary file is removed and `path` is left as it was.
///
/// Limits: the data are not fsync'ed, so a power loss (not a killed process) may still lose the
/// newest file. The folder of `path` must exist (see ensure_directory()). The stream is opened in
/// binary mode: no newline translation.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& writer);

/// Creates the folder `dir` and its missing parents; does nothing if it already exists or `dir` is
/// empty (the current folder). Throws std::runtime_error naming `dir` when it cannot be created or
/// when `dir` (or one of its parents) exists and is not a folder.
void ensure_directory(const std::string& dir);

/// Removes the temporary files (`NAME.tmp-<pid>`, see write_file_atomically()) that a killed run left
/// in `dir`: those whose process no longer exists (kill(pid, 0) fails with ESRCH), so that a run still
/// writing into the same folder keeps its own. Returns how many were removed; a folder that cannot be
/// listed is left alone (0).
int remove_stale_temporaries(const std::string& dir);

}  // namespace symcontact
