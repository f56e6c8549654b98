/*
 * load_cycles.c - loads the FMU library, instantiates and frees an instance, and unloads the library, many
 * times, as an importer that unloads after the last instance does (fmpy), and reports how much the heap in
 * use grew per cycle (docs/platforms.md, "Loading and unloading"). Plain C for every platform: glibc's
 * mallinfo2 on Linux, the C runtime's heap walk on Windows (under wine64 in the tests).
 *
 *   uc_load_cycles LIBRARY [CYCLES] [MAX_BYTES_PER_CYCLE]       (uc_load_cycles_fmi3: the FMI 3.0 variant)
 *
 * Exit code 1 when the growth over CYCLES cycles, after as many to settle, exceeds MAX_BYTES_PER_CYCLE per
 * cycle (default 64 bytes: smaller than any allocation of the FMU's that could stay behind; the C++ runtime's
 * emergency exception pool, which stayed behind before it was released at unload, is 71 KiB).
 */
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "fmi2Functions.h"
#include "uc_guid.h"

#ifdef _WIN32
#include <malloc.h>
#include <windows.h>
typedef HMODULE Library;
static Library open_library(const char* path) { return LoadLibraryA(path); }
static void* symbol(Library lib, const char* name) { return (void*)(uintptr_t)GetProcAddress(lib, name); }
static void close_library(Library lib) { FreeLibrary(lib); }
static long long heap_in_use(void) {
    _HEAPINFO info;
    info._pentry = NULL;
    long long used = 0;
    while (_heapwalk(&info) == _HEAPOK)
        if (info._useflag == _USEDENTRY) used += (long long)info._size;
    return used;
}
#else
#include <dlfcn.h>
#include <malloc.h>
typedef void* Library;
static Library open_library(const char* path) { return dlopen(path, RTLD_NOW | RTLD_LOCAL); }
static void* symbol(Library lib, const char* name) { return dlsym(lib, name); }
static void close_library(Library lib) { dlclose(lib); }
static long long heap_in_use(void) { return (long long)mallinfo2().uordblks; }
#endif

#ifdef UC_LOAD_FMI3
/* The FMI 3.0 variant (built with its uc_guid.h: the instantiation token). */
typedef void* (*Instantiate3)(const char*, const char*, const char*, bool, bool, bool, bool, const uint32_t*, size_t,
                              void*, void (*)(void*, int, const char*, const char*), void*);
static void logger3(void* env, int status, const char* category, const char* message) {
    (void)env, (void)status, (void)category, (void)message;
}

static void* instantiate(Library lib) {
    Instantiate3 instantiate3;
    *(void**)&instantiate3 = symbol(lib, "fmi3InstantiateCoSimulation");
    return instantiate3 ? instantiate3("cable", UC_GUID, NULL, false, false, false, false, NULL, 0, NULL, logger3, NULL)
                        : NULL;
}
#define UC_FREE_INSTANCE "fmi3FreeInstance"
#else
static void logger(fmi2ComponentEnvironment env, fmi2String instance, fmi2Status status, fmi2String category,
                   fmi2String message, ...) {
    (void)env, (void)instance, (void)status, (void)category, (void)message;
}

static void* instantiate(Library lib) {
    fmi2InstantiateTYPE* instantiate2;
    *(void**)&instantiate2 = symbol(lib, "fmi2Instantiate");
    const fmi2CallbackFunctions callbacks = {logger, calloc, free, NULL, NULL};
    return instantiate2 ? instantiate2("cable", fmi2CoSimulation, UC_GUID, NULL, &callbacks, fmi2False, fmi2False) : NULL;
}
#define UC_FREE_INSTANCE "fmi2FreeInstance"
#endif

/* One cycle; 0 on success. */
static int cycle(const char* path) {
    Library lib = open_library(path);
    if (lib == NULL) return 1;
    void (*freeInstance)(void*);
    *(void**)&freeInstance = symbol(lib, UC_FREE_INSTANCE);
    void* c = instantiate(lib);
    if (c == NULL || freeInstance == NULL) return 1;
    freeInstance(c);
    close_library(lib);
    return 0;
}

int main(int argc, char** argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: uc_load_cycles LIBRARY [CYCLES] [MAX_BYTES_PER_CYCLE]\n");
        return 2;
    }
    const int cycles = argc > 2 ? atoi(argv[2]) : 200;
    const double limit = argc > 3 ? atof(argv[3]) : 64.0;
    /* Two runs of CYCLES cycles: the first settles what the process keeps once (the loader's and the C
       runtime's bookkeeping), the growth over the second is what each cycle leaves behind. */
    long long heap[3];
    for (int run = 0; run < 3; ++run) {
        heap[run] = heap_in_use();
        for (int k = 0; run < 2 && k < cycles; ++k)
            if (cycle(argv[1]) != 0) {
                fprintf(stderr, "uc_load_cycles: cannot load %s and instantiate\n", argv[1]);
                return 1;
            }
    }
    const double perCycle = (double)(heap[2] - heap[1]) / cycles;
    printf("heap in use: %lld bytes more after %d load/unload cycles, %lld more after %d further ones "
           "(%.1f bytes per cycle, limit %.0f)\n", heap[1] - heap[0], cycles, heap[2] - heap[1], cycles, perCycle, limit);
    return perCycle <= limit ? 0 : 1;
}
