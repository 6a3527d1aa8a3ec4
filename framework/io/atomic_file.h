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

}  // namespace lpvlab
