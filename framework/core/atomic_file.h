#pragma once
// Writing outputs so that nothing is ever half-written: write to a temporary in the same
// directory ("out.exr" -> "out.tmp-<pid>-<n>.exr"), then rename over the target (atomic on POSIX
// within one file system). Missing parent directories are created.

#include <functional>
#include <string>

namespace lpvlab {

// Calls write(tempPath); on success renames tempPath to path; on exception removes it and
// rethrows. The temporary keeps the final extension (image writers pick the format from it).
void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write);

void writeTextAtomically(const std::string& path, const std::string& text);

// Removes the temporaries (above) that writers killed mid-write left in `directory` (not below
// it). Only where no other process is writing there: a reference cache entry under its lock, a
// run directory its one run resumes.
void removeLeftoverTemporaries(const std::string& directory);

// Checks, before any work is done, that `path` can become an output directory: it is one, or its
// nearest existing ancestor is one. Otherwise throws an Error naming `option` (e.g. "--out"), the
// path and the file in the way, instead of std::filesystem's "cannot create directories: Not a
// directory" after the work.
void requireOutputDirectory(const std::string& path, const std::string& option);

}  // namespace lpvlab
