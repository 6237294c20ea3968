#pragma once
// Where gpdr's triunsuitable() comes from, as Triangle's -u expects one:
//
//   * linked in, as with Triangle built with -DEXTERNAL_TEST: the user links
//     an object defining `int triunsuitable(double*, double*, double*, double)`
//     with libgpdr_main.a and libgpdr.a (README, "Grading with
//     triunsuitable()"); an ordinary gpdr has none;
//   * loaded at run time from a shared object named by --unsuitable PATH.so.
//
// When both are present --unsuitable wins: naming a library on the command
// line is the more specific request.

#include <string>

#include <gpdr/job.hpp>
#include <gpdr/options.hpp>

// The linked-in function, declared weak so that gpdr links without one (its
// address is then null).  Only main.cpp takes its address: the weak
// reference must sit in the object that holds main(), which the linker
// always pulls out of libgpdr_main.a, so that a user's strong definition
// given on the link line is the one the reference resolves to.
extern "C" int triunsuitable(double* org, double* dest, double* apex, double area)
    __attribute__((weak));

namespace gpdr::app {

// A shared object opened with dlopen(RTLD_NOW | RTLD_LOCAL), closed when this
// is destroyed: keep it alive for as long as the function it gave is used.
class SharedObject {
public:
    SharedObject() = default;
    // Throws gpdr::InputError "PATH: cannot load it as a shared object: <dlerror>".
    // A PATH without a '/' is taken relative to the current folder, not looked
    // up along LD_LIBRARY_PATH as dlopen() would do.
    explicit SharedObject(const std::string& path);
    ~SharedObject();
    SharedObject(SharedObject&& other) noexcept;
    SharedObject& operator=(SharedObject&& other) noexcept;
    SharedObject(const SharedObject&) = delete;
    SharedObject& operator=(const SharedObject&) = delete;

    // The address of the named symbol, or null when the object has none.
    void* symbol(const char* name) const;

private:
    void* handle_ = nullptr;
};

// The plug-ins for one run and the shared object that owns them.
struct LoadedPlugins {
    SharedObject library;  // empty unless --unsuitable was given
    JobPlugins plugins;
};

// Chooses the run's triunsuitable(): the one in options.unsuitable_library
// when named (throws gpdr::InputError "PATH: cannot load ..." or "PATH: has
// no function triunsuitable"), else `linked` (may be null).
LoadedPlugins load_plugins(const Options& options, Triunsuitable linked);

}  // namespace gpdr::app
