#include "cli/plugins.hpp"

#include <dlfcn.h>

#include <filesystem>

#include "engine/error.hpp"

namespace pdq::cli {

void loadPlugins(const std::vector<std::string>& libraries) {
  for (const auto& lib : libraries) {
    if (!std::filesystem::exists(lib)) throw InputError(lib, 0, "cannot load plugin: no such file");
    // A path with a slash makes dlopen load that file rather than search the library path.
    const std::string path = lib.find('/') == std::string::npos ? "./" + lib : lib;
    // RTLD_GLOBAL: the plugin's models register into the registry of the libpdq this
    // executable already uses.
    if (!dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL))
      throw InputError(lib, 0, std::string("cannot load plugin: ") + dlerror());
  }
}

}  // namespace pdq::cli
