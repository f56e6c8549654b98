/*
 * fmu_driver.c - runs the cable FMU's library on its own platform as an importer does (dlopen on Linux,
 * LoadLibrary on Windows, under wine64 in the tests) and records every Real output at every
 * communication point, so the binaries of two platforms can be compared byte for byte
 * (tests/platform/compare_platforms.py, docs/platforms.md). Plain C, the same source for every platform.
 *
 *   uc_fmu_driver LIBRARY SCENE OUT [--line-file VALUE] [--save-at T STATE] [--restore T STATE]
 *
 * SCENE   hopland  the Hopland acceleration: 1.1 kn to 2.4 kn in 60 s, held to 660 s (1321 points)
 *         mooring  a line of the deck given by --line-file (the lineFile parameter as given: a relative
 *                  path looked up in the working directory, an absolute path or a file: URI), the
 *                  vessel point surging 2 m at 20 s for 40 s
 *         waves    a steady 2 kn tow through a JONSWAP sea (Hs 4 m, Tp 9 s) for 60 s
 *         winch    a 1.5 kn tow, the winch paying out 1 m/s from 10 s to 40 s (the top element splits), 60 s
 * OUT     "UCDRIVE1", little-endian uint32s: the number of Real outputs n and the size of their names,
 *         the n names (each NUL-terminated), then for each communication point the time and the n outputs in
 *         value-reference order (IEEE doubles as stored)
 * --save-at T STATE   at the communication point T serializes the FMU state into the file STATE
 * --restore T STATE   instead of initializing: a fresh instance, fmi2DeSerializeFMUstate of STATE (saved
 *                     at the communication point T), fmi2SetFMUstate, then the scene from T on
 * Exit code 0 when every FMI call returned fmi2OK; messages of the FMU go to stderr.
 * uc_fmu_driver_fmi3 runs the FMI 3.0 variant's library the same way (fmi3_shims.h); FMI 3.0 has no input
 * derivatives in co-simulation, so there the tow point's acceleration is not passed.
 */
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef _WIN32
#include <direct.h>
#include <windows.h>
#define getcwd _getcwd
#else
#include <dlfcn.h>
#include <unistd.h>
#endif

#include "fmi2Functions.h"
#include "uc_guid.h"
#include "generated/uc_schema.h"

#define KNOT (1852.0 / 3600.0)

/* ---- the FMU's variables, from the schema ---------------------------------------------------------- */

typedef enum { T_REAL, T_INTEGER, T_BOOLEAN, T_STRING } VarType;
typedef enum { C_PARAMETER, C_INPUT, C_OUTPUT } Causality;
typedef struct {
    fmi2ValueReference vr;
    const char* name;
    VarType type;
    Causality causality;
} Variable;

#define REAL T_REAL
#define INTEGER T_INTEGER
#define BOOLEAN T_BOOLEAN
#define STRING T_STRING
#define PARAMETER C_PARAMETER
#define INPUT C_INPUT
#define OUTPUT C_OUTPUT
#define UC_DRIVER_VARIABLE(vr, name, type, causality, member) {vr, name, type, causality},
static const Variable kVariables[] = {UC_SCHEMA_VARIABLES(UC_DRIVER_VARIABLE)};
#undef UC_DRIVER_VARIABLE
#define N_VARIABLES (sizeof kVariables / sizeof kVariables[0])

static const Variable* variable(const char* name) {
    for (size_t k = 0; k < N_VARIABLES; ++k)
        if (strcmp(kVariables[k].name, name) == 0) return &kVariables[k];
    fprintf(stderr, "uc_fmu_driver: no variable %s\n", name);
    exit(2);
}

/* ---- loading the library ----------------------------------------------------------------------------- */

typedef struct {
    fmi2InstantiateTYPE* Instantiate;
    fmi2FreeInstanceTYPE* FreeInstance;
    fmi2SetupExperimentTYPE* SetupExperiment;
    fmi2EnterInitializationModeTYPE* EnterInitializationMode;
    fmi2ExitInitializationModeTYPE* ExitInitializationMode;
    fmi2SetRealTYPE* SetReal;
    fmi2SetIntegerTYPE* SetInteger;
    fmi2SetBooleanTYPE* SetBoolean;
    fmi2SetStringTYPE* SetString;
    fmi2GetRealTYPE* GetReal;
    fmi2SetRealInputDerivativesTYPE* SetRealInputDerivatives;
    fmi2DoStepTYPE* DoStep;
    fmi2GetFMUstateTYPE* GetFMUstate;
    fmi2SetFMUstateTYPE* SetFMUstate;
    fmi2FreeFMUstateTYPE* FreeFMUstate;
    fmi2SerializedFMUstateSizeTYPE* SerializedFMUstateSize;
    fmi2SerializeFMUstateTYPE* SerializeFMUstate;
    fmi2DeSerializeFMUstateTYPE* DeSerializeFMUstate;
} Api;

#ifdef _WIN32
typedef HMODULE Library;
static Library open_library(const char* path) { return LoadLibraryA(path); }
static void* symbol(Library lib, const char* name) { return (void*)(uintptr_t)GetProcAddress(lib, name); }
static void close_library(Library lib) { FreeLibrary(lib); }
#else
typedef void* Library;
static Library open_library(const char* path) { return dlopen(path, RTLD_NOW | RTLD_LOCAL); }
static void* symbol(Library lib, const char* name) { return dlsym(lib, name); }
static void close_library(Library lib) { dlclose(lib); }
#endif

static void* require(Library lib, const char* name) {
    void* f = symbol(lib, name);
    if (f == NULL) {
        fprintf(stderr, "uc_fmu_driver: the library does not export %s\n", name);
        exit(1);
    }
    return f;
}

#ifndef UC_DRIVER_FMI3
static void load_api(Library lib, Api* api) {
#define UC_LOAD(f) *(void**)&api->f = require(lib, "fmi2" #f);
    UC_LOAD(Instantiate) UC_LOAD(FreeInstance) UC_LOAD(SetupExperiment) UC_LOAD(EnterInitializationMode)
    UC_LOAD(ExitInitializationMode) UC_LOAD(SetReal) UC_LOAD(SetInteger) UC_LOAD(SetBoolean) UC_LOAD(SetString)
    UC_LOAD(GetReal) UC_LOAD(SetRealInputDerivatives) UC_LOAD(DoStep) UC_LOAD(GetFMUstate) UC_LOAD(SetFMUstate)
    UC_LOAD(FreeFMUstate) UC_LOAD(SerializedFMUstateSize) UC_LOAD(SerializeFMUstate) UC_LOAD(DeSerializeFMUstate)
#undef UC_LOAD
}
#else
#include "fmi3_shims.h"
#endif

/* ---- the run --------------------------------------------------------------------------------------- */

typedef struct {
    double tow[3], towVelocity[3], towAcceleration[3];
    double winchRate;
} Inputs;

typedef struct Scene Scene;
typedef struct {
    Api api;
    fmi2Component c;
    const Scene* scene;
    const char* lineFile;
} Driver;

struct Scene {
    const char* name;
    double duration, step;
    void (*parameters)(Driver* d);
    void (*inputs)(double t, Inputs* in);
};

static void check(fmi2Status status, const char* what) {
    if (status != fmi2OK) {
        fprintf(stderr, "uc_fmu_driver: %s returned status %d\n", what, (int)status);
        exit(1);
    }
}

static void set_real(Driver* d, const char* name, double value) {
    const Variable* v = variable(name);
    check(d->api.SetReal(d->c, &v->vr, 1, &value), name);
}

static void set_integer(Driver* d, const char* name, int value) {
    const Variable* v = variable(name);
    fmi2Integer x = value;
    if (v->type == T_BOOLEAN) {
        fmi2Boolean b = value != 0;
        check(d->api.SetBoolean(d->c, &v->vr, 1, &b), name);
    } else {
        check(d->api.SetInteger(d->c, &v->vr, 1, &x), name);
    }
}

static void set_string(Driver* d, const char* name, const char* value) {
    const Variable* v = variable(name);
    check(d->api.SetString(d->c, &v->vr, 1, &value), name);
}

static void set_inputs(Driver* d, double t) {
    Inputs in;
    memset(&in, 0, sizeof in);
    d->scene->inputs(t, &in);
    static const char* names[6] = {"tow.x", "tow.y", "tow.z", "tow.vx", "tow.vy", "tow.vz"};
    for (int k = 0; k < 3; ++k) {
        set_real(d, names[k], in.tow[k]);
        set_real(d, names[3 + k], in.towVelocity[k]);
    }
    set_real(d, "winch.rate", in.winchRate);
    fmi2ValueReference vrs[3];
    const fmi2Integer order[3] = {1, 1, 1};
    for (int k = 0; k < 3; ++k) vrs[k] = variable(names[3 + k])->vr;
    check(d->api.SetRealInputDerivatives(d->c, vrs, 3, order, in.towAcceleration), "fmi2SetRealInputDerivatives");
}

/* The scenes. */

static void hopland_parameters(Driver* d) { set_integer(d, "bottomEnd", 0); }
static void hopland_inputs(double t, Inputs* in) {
    const double v0 = 1.1 * KNOT, v1 = 2.4 * KNOT, ramp = 60.0;
    if (t < ramp) {
        in->tow[0] = v0 * t + 0.5 * (v1 - v0) / ramp * t * t;
        in->towVelocity[0] = v0 + (v1 - v0) * t / ramp;
        in->towAcceleration[0] = (v1 - v0) / ramp;
    } else {
        in->tow[0] = 0.5 * (v0 + v1) * ramp + v1 * (t - ramp);
        in->towVelocity[0] = v1;
    }
}

static void mooring_parameters(Driver* d) {
    if (d->lineFile == NULL) {
        fprintf(stderr, "uc_fmu_driver: the mooring scene needs --line-file\n");
        exit(2);
    }
    set_string(d, "lineFile", d->lineFile);
    set_integer(d, "lineFileElements", 30);
}
static void mooring_inputs(double t, Inputs* in) {
    /* the deck's vessel point (0, 0, -20) surging */
    const double a = 2.0, w = 2.0 * 3.14159265358979323846 / 20.0;
    in->tow[0] = a * sin(w * t);
    in->tow[2] = -20.0;
    in->towVelocity[0] = a * w * cos(w * t);
    in->towAcceleration[0] = -a * w * w * sin(w * t);
}

static void waves_parameters(Driver* d) {
    set_integer(d, "waves.mode", 2);
    set_real(d, "waves.height", 4.0);
    set_real(d, "waves.period", 9.0);
}
static void steady_tow(double t, double speedKnots, Inputs* in) {
    in->tow[0] = speedKnots * KNOT * t;
    in->towVelocity[0] = speedKnots * KNOT;
}
static void waves_inputs(double t, Inputs* in) { steady_tow(t, 2.0, in); }

static void winch_parameters(Driver* d) { set_integer(d, "winchMode", 1); }
static void winch_inputs(double t, Inputs* in) {
    steady_tow(t, 1.5, in);
    in->winchRate = t >= 10.0 && t < 40.0 ? 1.0 : 0.0;
}

static const Scene kScenes[] = {
    {"hopland", 660.0, 0.5, hopland_parameters, hopland_inputs},
    {"mooring", 40.0, 0.5, mooring_parameters, mooring_inputs},
    {"waves", 60.0, 0.2, waves_parameters, waves_inputs},
    {"winch", 60.0, 0.5, winch_parameters, winch_inputs},
};

/* The FMU's messages: to stderr, formatted (the message is a printf format for the importer). */
static void logger(fmi2ComponentEnvironment env, fmi2String instance, fmi2Status status, fmi2String category,
                   fmi2String message, ...) {
    (void)env;
    if (status == fmi2OK) return;
    va_list args;
    va_start(args, message);
    fprintf(stderr, "[%s %s %d] ", instance, category, (int)status);
    vfprintf(stderr, message, args);
    fputc('\n', stderr);
    va_end(args);
}

/* file:///<working directory>/resources, as importers pass it (Windows: file:///C:/...). */
static void resource_uri(char* uri, size_t size) {
    char cwd[2048];
    if (getcwd(cwd, sizeof cwd) == NULL) cwd[0] = '\0';
    for (char* p = cwd; *p; ++p)
        if (*p == '\\') *p = '/';
    snprintf(uri, size, "file://%s%s/resources", cwd[0] == '/' ? "" : "/", cwd);
}

static const char* name_of(fmi2ValueReference vr) {
    for (size_t k = 0; k < N_VARIABLES; ++k)
        if (kVariables[k].vr == vr && kVariables[k].causality == C_OUTPUT) return kVariables[k].name;
    return "?";
}

static size_t count_real_outputs(fmi2ValueReference* vrs) {
    size_t n = 0;
    for (size_t k = 0; k < N_VARIABLES; ++k)
        if (kVariables[k].type == T_REAL && kVariables[k].causality == C_OUTPUT) vrs[n++] = kVariables[k].vr;
    return n;
}

static void write_u32(FILE* f, uint32_t v) {
    unsigned char b[4] = {(unsigned char)v, (unsigned char)(v >> 8), (unsigned char)(v >> 16), (unsigned char)(v >> 24)};
    fwrite(b, 1, 4, f);
}

static void record(Driver* d, FILE* out, double t, const fmi2ValueReference* vrs, size_t n, double* values) {
    check(d->api.GetReal(d->c, vrs, n, values), "fmi2GetReal");
    fwrite(&t, sizeof t, 1, out);
    fwrite(values, sizeof *values, n, out);
}

static void save_state(Driver* d, const char* path) {
    fmi2FMUstate state = NULL;
    size_t size = 0;
    check(d->api.GetFMUstate(d->c, &state), "fmi2GetFMUstate");
    check(d->api.SerializedFMUstateSize(d->c, state, &size), "fmi2SerializedFMUstateSize");
    fmi2Byte* bytes = malloc(size);
    check(d->api.SerializeFMUstate(d->c, state, bytes, size), "fmi2SerializeFMUstate");
    FILE* f = fopen(path, "wb");
    if (f == NULL || fwrite(bytes, 1, size, f) != size || fclose(f) != 0) {
        fprintf(stderr, "uc_fmu_driver: cannot write %s\n", path);
        exit(1);
    }
    free(bytes);
    check(d->api.FreeFMUstate(d->c, &state), "fmi2FreeFMUstate");
}

static void restore_state(Driver* d, const char* path) {
    FILE* f = fopen(path, "rb");
    if (f == NULL) {
        fprintf(stderr, "uc_fmu_driver: cannot read %s\n", path);
        exit(1);
    }
    fseek(f, 0, SEEK_END);
    const long size = ftell(f);
    fseek(f, 0, SEEK_SET);
    fmi2Byte* bytes = malloc((size_t)size);
    if (bytes == NULL || fread(bytes, 1, (size_t)size, f) != (size_t)size) exit(1);
    fclose(f);
    fmi2FMUstate state = NULL;
    check(d->api.DeSerializeFMUstate(d->c, bytes, (size_t)size, &state), "fmi2DeSerializeFMUstate");
    check(d->api.SetFMUstate(d->c, state), "fmi2SetFMUstate");
    check(d->api.FreeFMUstate(d->c, &state), "fmi2FreeFMUstate");
    free(bytes);
}

static void usage(void) {
    fprintf(stderr, "usage: uc_fmu_driver LIBRARY SCENE OUT [--line-file VALUE] [--save-at T STATE] "
                    "[--restore T STATE]\n");
    exit(2);
}

int main(int argc, char** argv) {
    if (argc < 4) usage();
    Driver d;
    memset(&d, 0, sizeof d);
    for (size_t k = 0; k < sizeof kScenes / sizeof kScenes[0]; ++k)
        if (strcmp(kScenes[k].name, argv[2]) == 0) d.scene = &kScenes[k];
    if (d.scene == NULL) {
        fprintf(stderr, "uc_fmu_driver: unknown scene %s (hopland, mooring, waves, winch)\n", argv[2]);
        return 2;
    }
    double saveAt = -1.0, restoreAt = 0.0;
    const char *savePath = NULL, *restorePath = NULL;
    for (int k = 4; k < argc; ++k) {
        if (strcmp(argv[k], "--line-file") == 0 && k + 1 < argc) {
            d.lineFile = argv[++k];
        } else if (strcmp(argv[k], "--save-at") == 0 && k + 2 < argc) {
            saveAt = atof(argv[++k]);
            savePath = argv[++k];
        } else if (strcmp(argv[k], "--restore") == 0 && k + 2 < argc) {
            restoreAt = atof(argv[++k]);
            restorePath = argv[++k];
        } else {
            usage();
        }
    }
    Library lib = open_library(argv[1]);
    if (lib == NULL) {
        fprintf(stderr, "uc_fmu_driver: cannot load %s\n", argv[1]);
        return 1;
    }
    load_api(lib, &d.api);
    const fmi2CallbackFunctions callbacks = {logger, calloc, free, NULL, NULL};
    char uri[2200];
    resource_uri(uri, sizeof uri);
    d.c = d.api.Instantiate("cable", fmi2CoSimulation, UC_GUID, uri, &callbacks, fmi2False, fmi2False);
    if (d.c == NULL) {
        fprintf(stderr, "uc_fmu_driver: fmi2Instantiate failed\n");
        return 1;
    }
    fmi2ValueReference vrs[N_VARIABLES];
    const size_t n = count_real_outputs(vrs);
    double* values = malloc(n * sizeof *values);
    FILE* out = fopen(argv[3], "wb");
    if (out == NULL || values == NULL) {
        fprintf(stderr, "uc_fmu_driver: cannot write %s\n", argv[3]);
        return 1;
    }
    fwrite("UCDRIVE1", 1, 8, out);
    write_u32(out, (uint32_t)n);
    uint32_t namesSize = 0;
    for (size_t k = 0; k < n; ++k) namesSize += (uint32_t)strlen(name_of(vrs[k])) + 1;
    write_u32(out, namesSize);
    for (size_t k = 0; k < n; ++k) fwrite(name_of(vrs[k]), 1, strlen(name_of(vrs[k])) + 1, out);

    /* Communication points k h (never accumulated), the inputs of the point at the start of each step. */
    const double h = d.scene->step;
    const long steps = lround(d.scene->duration / h);
    long first = 0;
    if (restorePath != NULL) {
        restore_state(&d, restorePath);  /* a fresh instance: never initialized */
        first = lround(restoreAt / h);
    } else {
        d.scene->parameters(&d);
        set_inputs(&d, 0.0);
        check(d.api.SetupExperiment(d.c, fmi2False, 0.0, 0.0, fmi2True, d.scene->duration), "fmi2SetupExperiment");
        check(d.api.EnterInitializationMode(d.c), "fmi2EnterInitializationMode");
        check(d.api.ExitInitializationMode(d.c), "fmi2ExitInitializationMode");
        record(&d, out, 0.0, vrs, n, values);
    }
    for (long k = first; k < steps; ++k) {
        const double t = (double)k * h, next = (double)(k + 1) * h;
        set_inputs(&d, t);
        check(d.api.DoStep(d.c, t, h, fmi2True), "fmi2DoStep");
        record(&d, out, next, vrs, n, values);
        if (savePath != NULL && lround(saveAt / h) == k + 1) save_state(&d, savePath);
    }
    if (fclose(out) != 0) return 1;
    free(values);
    d.api.FreeInstance(d.c);
    close_library(lib);
    return 0;
}
