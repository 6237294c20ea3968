// Loads triunsuitable() for --unsuitable (see unsuitable.hpp).  dlopen's
// RTLD_NOW makes a library with unresolved symbols fail here, with
// dlerror()'s explanation, rather than in the middle of refinement;
// RTLD_LOCAL keeps its symbols from leaking into anything loaded later.
#include "unsuitable.hpp"

#include <utility>

#include <dlfcn.h>

#include <gpdr/errors.hpp>

namespace gpdr::app {
namespace {

std::string last_dl_error() {
    const char* text = dlerror();
    return text != nullptr ? text : "unknown reason";
}

}  // namespace

SharedObject::SharedObject(const std::string& path) {
    // dlopen() searches the library path for a bare name; a user who types
    // --unsuitable grading.so means the file in front of them.
    const std::string name = path.find('/') == std::string::npos ? "./" + path : path;
    handle_ = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle_ == nullptr)
        throw InputError(path, 0, "cannot load it as a shared object: " + last_dl_error());
}

SharedObject::~SharedObject() {
    if (handle_ != nullptr) dlclose(handle_);
}

SharedObject::SharedObject(SharedObject&& other) noexcept
    : handle_(std::exchange(other.handle_, nullptr)) {}

SharedObject& SharedObject::operator=(SharedObject&& other) noexcept {
    if (this != &other) {
        if (handle_ != nullptr) dlclose(handle_);
        handle_ = std::exchange(other.handle_, nullptr);
    }
    return *this;
}

void* SharedObject::symbol(const char* name) const {
    if (handle_ == nullptr) return nullptr;
    dlerror();  // clear any earlier error so a null below is this lookup's
    return dlsym(handle_, name);
}

LoadedPlugins load_plugins(const Options& options, Triunsuitable linked) {
    LoadedPlugins loaded;
    loaded.plugins.triunsuitable = linked;
    if (options.unsuitable_library.empty()) return loaded;

    const std::string& path = options.unsuitable_library;
    loaded.library = SharedObject(path);
    void* address = loaded.library.symbol("triunsuitable");
    if (address == nullptr)
        throw InputError(path, 0,
                         "has no function triunsuitable (a C++ definition needs extern \"C\")");
    // POSIX guarantees that a dlsym() result for a function converts to a
    // function pointer; C++ calls this conversion conditionally supported.
    loaded.plugins.triunsuitable = reinterpret_cast<Triunsuitable>(address);
    return loaded;
}

}  // namespace gpdr::app
