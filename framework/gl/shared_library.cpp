#include "framework/gl/shared_library.h"

#include <dlfcn.h>

#include "framework/core/error.h"

namespace lpvlab::gl_detail {

SharedLibrary::SharedLibrary(const std::string& backend, const std::vector<std::string>& names,
                             const std::string& hint)
    : backend_(backend) {
  std::string tried;
  for (const std::string& name : names) {
    handle_ = ::dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle_) {
      name_ = name;
      return;
    }
    const char* why = ::dlerror();
    tried += (tried.empty() ? "" : "; ") + (why ? std::string(why) : name + ": not found");
  }
  throwAt(backend, "cannot load " + names.front() + " (" + tried + "): " + hint);
}

void* SharedLibrary::address(const char* symbol) const {
  ::dlerror();
  void* found = ::dlsym(handle_, symbol);
  if (!found) throwAt(backend_, name_ + " has no " + symbol);
  return found;
}

}  // namespace lpvlab::gl_detail
