#pragma once
// A GL library opened at run time (dlopen) instead of linked: lpvlab starts, and its other
// backends work, on a machine without it. A GPU machine needs no Mesa and no LLVM (libOSMesa's
// 117 MB), a software one no EGL; the portable bundle (scripts/bundle.sh) carries OSMesa and takes
// EGL and the GPU's driver from the system.
//
// A library, once opened, stays loaded for the process: GL contexts may outlive any one caller,
// and the sanitizers' reports name frames of libraries that are still mapped.

#include <string>
#include <vector>

namespace lpvlab::gl_detail {

class SharedLibrary {
public:
  // Opens the first of `names` (sonames, searched as the dynamic loader does) that loads; throws
  // an Error beginning with `backend` naming every name tried and what the loader said, and
  // `hint` (what to install) when none does.
  SharedLibrary(const std::string& backend, const std::vector<std::string>& names,
                const std::string& hint);

  // The symbol `name` as a function pointer of type F; an Error naming the library if missing.
  template <class F>
  F function(const char* name) const {
    return reinterpret_cast<F>(address(name));
  }
  const std::string& name() const { return name_; }

private:
  void* address(const char* symbol) const;
  std::string backend_, name_;
  void* handle_ = nullptr;
};

}  // namespace lpvlab::gl_detail
