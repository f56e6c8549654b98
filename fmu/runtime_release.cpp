// runtime_release.cpp - gives back, when the FMU library is unloaded, what the C++ runtime linked into it
// statically allocates once per load and would otherwise keep for the life of the process: libstdc++'s
// emergency pool for exceptions thrown when memory is exhausted (about 71 KiB). An importer that loads
// and unloads the library repeatedly (fmpy unloads it after the last instance) grew by that much per
// cycle (docs/platforms.md, "Loading and unloading"). The only C++ in the FMU's adapter.

// libstdc++'s own release function (eh_alloc.cc; what valgrind calls at exit), not declared in its headers.
namespace __gnu_cxx {
void __freeres() noexcept;
}

namespace {

// A static object of this library: destroyed when the library is unloaded (dlclose, FreeLibrary) or the
// process exits, after every instance is gone.
struct RuntimeRelease {
    ~RuntimeRelease() { __gnu_cxx::__freeres(); }
} runtimeRelease;

}  // namespace
