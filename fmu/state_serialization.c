/* state_serialization.c - see state_serialization.h. */
#include "state_serialization.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "simulation.h"
#include "uc_guid.h"

#define UC_STATE_MAGIC "UCFMUST"  /* 8 bytes with the terminating NUL */
#define UC_GUID_FIELD_SIZE 64

/* The scalar fields of the adapter state, in serialized order: X(field, kind), kind i32 or f64. */
#define UC_ADAPTER_SCALARS(X) \
    X(startTime, f64) X(stopTimeDefined, i32) X(stopTime, f64) X(time, f64) X(lastSuccessfulTime, f64) \
    X(terminateRequested, i32)

typedef int32_t uc_i32;
typedef double uc_f64;

typedef struct UCSavedState {
    char magic[8];                /* UC_STATE_MAGIC: rejects pointers that are not our states */
    int32_t machineState;
#define UC_DECLARE_FIELD(field, kind) uc_##kind field;
    UC_ADAPTER_SCALARS(UC_DECLARE_FIELD)
#undef UC_DECLARE_FIELD
    UCParams params;
    UCParams coreParams;
    UCInputs inputs;
    UCOutputs outputs;
    size_t coreSize;              /* 0: no core (instantiated, initialization mode, or error) */
    unsigned char* core;
} UCSavedState;

/* ---- in-memory states ---------------------------------------------------------------------------- */

static int has_core_to_save(const UCInstance* inst) {
    const unsigned int afterInit = UC_STATE_STEP_COMPLETE | UC_STATE_STEP_FAILED | UC_STATE_STEP_CANCELED |
                                   UC_STATE_TERMINATED; /* not error: its core may be broken */
    return inst->coreReady && inst->cable != NULL && (inst->state & afterInit) != 0;
}

static void copy_adapter_state(UCSavedState* s, const UCInstance* inst) {
    memcpy(s->magic, UC_STATE_MAGIC, sizeof s->magic);
    s->machineState = (int32_t)inst->state;
#define UC_SAVE_FIELD(field, kind) s->field = inst->field;
    UC_ADAPTER_SCALARS(UC_SAVE_FIELD)
#undef UC_SAVE_FIELD
    memcpy(&s->params, &inst->params, sizeof s->params);
    memcpy(&s->coreParams, &inst->coreParams, sizeof s->coreParams);
    memcpy(&s->inputs, &inst->inputs, sizeof s->inputs);
    memcpy(&s->outputs, &inst->outputs, sizeof s->outputs);
}

static UCSavedState* as_saved_state(UCInstance* inst, fmi2FMUstate state, const char* function) {
    UCSavedState* s = (UCSavedState*)state;
    if (s == NULL || memcmp(s->magic, UC_STATE_MAGIC, sizeof s->magic) != 0) {
        uc_log_status(&inst->log, fmi2Error, "%s: FMUstate is NULL or not a state of this FMU", function);
        return NULL;
    }
    return s;
}

static void release_core(UCSavedState* s) {
    free(s->core);
    s->core = NULL;
    s->coreSize = 0;
}

static fmi2Status save_core(UCInstance* inst, UCSavedState* s) {
    size_t size = uc_state_size(inst->cable);
    s->core = malloc(size > 0 ? size : 1);
    if (s->core == NULL) {
        uc_log_status(&inst->log, fmi2Error, "fmi2GetFMUstate: out of memory for %zu bytes of cable state", size);
        return fmi2Error;
    }
    s->coreSize = size;
    if (uc_state_save(inst->cable, s->core, size) != 0) {
        uc_log_status(&inst->log, fmi2Error, "fmi2GetFMUstate: the cable core could not save its state");
        release_core(s);
        return fmi2Error;
    }
    return fmi2OK;
}

fmi2Status uc_state_get(UCInstance* inst, fmi2FMUstate* state) {
    if (state == NULL) {
        uc_log_status(&inst->log, fmi2Error, "fmi2GetFMUstate: FMUstate is NULL");
        return fmi2Error;
    }
    UCSavedState* s = *state != NULL ? as_saved_state(inst, *state, "fmi2GetFMUstate")
                                     : calloc(1, sizeof(UCSavedState));
    if (s == NULL) return fmi2Error;
    release_core(s);
    copy_adapter_state(s, inst);
    *state = s;
    if (has_core_to_save(inst)) return save_core(inst, s);
    return fmi2OK;
}

/* The core of the state into *core: the instance's own core restored in place when it was made with the same
 * parameters (the cheap path of a master that rolls back every step), otherwise a new core (for a mooring
 * system from the deck the state's lineFile names) that only replaces the instance's once the state is in it.
 * A refusal leaves the instance's core as it was: the core checks a state (size, version, a system's deck
 * values) before it changes anything. Only a state that passes those checks and then fails inside the core
 * in place (corrupted integrator history) leaves it unusable: it is dropped and the instance goes to the
 * error state. *core is set only on success. */
static fmi2Status restore_core(UCInstance* inst, const UCSavedState* s, UCCable** core) {
    const int inPlace = inst->cable != NULL && memcmp(&inst->coreParams, &s->coreParams, sizeof s->coreParams) == 0;
    UCCable* target = inst->cable;
    if (!inPlace && uc_sim_create_core(inst, &s->coreParams, &target, "fmi2SetFMUstate") != fmi2OK) return fmi2Error;
    const int rc = uc_state_restore(target, s->core, s->coreSize, inst->msg, sizeof inst->msg);
    if (rc != 0) {
        if (s->coreParams.mooringSystem) { /* the system was made from lineFile: name it */
            uc_log_status(&inst->log, fmi2Error, "fmi2SetFMUstate: lineFile %s: cannot restore the mooring system's "
                          "state: %s", s->coreParams.lineFile, inst->msg);
        } else {
            uc_log_status(&inst->log, fmi2Error, "fmi2SetFMUstate: cannot restore the cable state: %s", inst->msg);
        }
        if (!inPlace) {
            uc_free(target);
        } else if (rc == 2) { /* partly restored: neither the instance's nor the state's */
            uc_instance_drop_core(inst);
            inst->state = UC_STATE_ERROR;
        }
        return fmi2Error;
    }
    *core = target;
    return fmi2OK;
}

fmi2Status uc_state_set(UCInstance* inst, fmi2FMUstate state) {
    const UCSavedState* s = as_saved_state(inst, state, "fmi2SetFMUstate");
    if (s == NULL) return fmi2Error;
    UCCable* core = NULL;
    if (s->coreSize > 0 && restore_core(inst, s, &core) != fmi2OK) return fmi2Error; /* the instance unchanged */
    if (core != inst->cable) { /* commit: the state's core replaces the instance's (none without one) */
        uc_instance_drop_core(inst);
        inst->cable = core;
    }
    inst->state = (UCMachineState)s->machineState;
#define UC_RESTORE_FIELD(field, kind) inst->field = s->field;
    UC_ADAPTER_SCALARS(UC_RESTORE_FIELD)
#undef UC_RESTORE_FIELD
    memcpy(&inst->params, &s->params, sizeof s->params);
    memcpy(&inst->coreParams, &s->coreParams, sizeof s->coreParams);
    memcpy(&inst->inputs, &s->inputs, sizeof s->inputs);
    memcpy(&inst->outputs, &s->outputs, sizeof s->outputs);
    inst->coreReady = s->coreSize > 0;
    inst->outputsProvisional = 0;
    uc_log(&inst->log, fmi2OK, UC_LOG_EVENTS, "fmi2SetFMUstate: restored state %s at t = %.17g",
           uc_state_name(inst->state), inst->time);
    return fmi2OK;
}

fmi2Status uc_state_free(UCInstance* inst, fmi2FMUstate* state) {
    if (state == NULL || *state == NULL) return fmi2OK;
    UCSavedState* s = as_saved_state(inst, *state, "fmi2FreeFMUstate");
    if (s == NULL) return fmi2Error;
    release_core(s);
    memset(s->magic, 0, sizeof s->magic);
    free(s);
    *state = NULL;
    return fmi2OK;
}

/* ---- serialized form ----------------------------------------------------------------------------- */

typedef struct Writer {
    fmi2Byte* data; /* NULL: only count */
    size_t size;
} Writer;

static void put(Writer* w, const void* bytes, size_t n) {
    if (w->data != NULL) memcpy(w->data + w->size, bytes, n);
    w->size += n;
}
static void put_u32(Writer* w, uint32_t v) { put(w, &v, sizeof v); }
static void put_u64(Writer* w, uint64_t v) { put(w, &v, sizeof v); }
static void put_i32(Writer* w, int32_t v) { put(w, &v, sizeof v); }
static void put_f64(Writer* w, double v) { put(w, &v, sizeof v); }

/* A block of n bytes as runs: u32 zero words, u32 data words, the data words, ... until its 8-byte words are
 * all told (a last partial word counts as a word, its missing bytes zero). The structs and the core's state
 * are mostly zeros where a deck is smaller than the maxima (a mooring system's lines, bodies and points beyond
 * its own, wave components beyond those given): a state is sized by what it holds. */
enum { UC_RUN_WORD = 8, UC_RUN_MIN_ZEROS = 2 };

static int zero_word(const unsigned char* bytes, size_t n, size_t word) {
    const size_t from = word * UC_RUN_WORD;
    if (from + UC_RUN_WORD <= n) {
        uint64_t v;
        memcpy(&v, bytes + from, sizeof v);
        return v == 0;
    }
    for (size_t i = from; i < n; ++i)
        if (bytes[i] != 0) return 0;
    return 1;
}

static void put_runs(Writer* w, const void* block, size_t n) {
    const unsigned char* bytes = (const unsigned char*)block;
    const size_t words = (n + UC_RUN_WORD - 1) / UC_RUN_WORD;
    size_t at = 0;
    while (at < words) {
        size_t zeros = 0;
        while (at + zeros < words && zero_word(bytes, n, at + zeros)) ++zeros;
        size_t i = at + zeros; /* data up to a run of UC_RUN_MIN_ZEROS zero words or zeros to the end */
        while (i < words) {
            size_t run = 0;
            while (i + run < words && zero_word(bytes, n, i + run)) ++run;
            if (run >= UC_RUN_MIN_ZEROS || (run > 0 && i + run == words)) break;
            i += run > 0 ? run : 1;
        }
        const size_t data = i - (at + zeros);
        put_u32(w, (uint32_t)zeros);
        put_u32(w, (uint32_t)data);
        const size_t from = (at + zeros) * UC_RUN_WORD;
        const size_t to = (at + zeros + data) * UC_RUN_WORD < n ? (at + zeros + data) * UC_RUN_WORD : n;
        if (to > from) put(w, bytes + from, to - from);
        at += zeros + data;
    }
}

static void write_state(Writer* w, const UCSavedState* s) {
    char guid[UC_GUID_FIELD_SIZE] = {0};
    strncpy(guid, UC_GUID, sizeof guid - 1);
    put(w, UC_STATE_MAGIC, 8);
    put_u32(w, UC_STATE_FORMAT_VERSION);
    put(w, guid, sizeof guid);
    put_u32(w, UC_NUM_STATIONS);
    put_u32(w, (uint32_t)sizeof(UCParams));
    put_u32(w, (uint32_t)sizeof(UCInputs));
    put_u32(w, (uint32_t)sizeof(UCOutputs));
    put_u64(w, (uint64_t)s->coreSize);
    put_i32(w, s->machineState);
#define UC_PUT_FIELD(field, kind) put_##kind(w, s->field);
    UC_ADAPTER_SCALARS(UC_PUT_FIELD)
#undef UC_PUT_FIELD
    put_runs(w, &s->params, sizeof s->params);
    put_runs(w, &s->coreParams, sizeof s->coreParams);
    put_runs(w, &s->inputs, sizeof s->inputs);
    put_runs(w, &s->outputs, sizeof s->outputs);
    if (s->coreSize > 0) put_runs(w, s->core, s->coreSize);
}

fmi2Status uc_state_serialized_size(UCInstance* inst, fmi2FMUstate state, size_t* size) {
    const UCSavedState* s = as_saved_state(inst, state, "fmi2SerializedFMUstateSize");
    if (s == NULL) return fmi2Error;
    if (size == NULL) {
        uc_log_status(&inst->log, fmi2Error, "fmi2SerializedFMUstateSize: size is NULL");
        return fmi2Error;
    }
    Writer w = {NULL, 0};
    write_state(&w, s);
    *size = w.size;
    return fmi2OK;
}

fmi2Status uc_state_serialize(UCInstance* inst, fmi2FMUstate state, fmi2Byte buffer[], size_t size) {
    size_t needed = 0;
    if (uc_state_serialized_size(inst, state, &needed) != fmi2OK) return fmi2Error;
    if (buffer == NULL || size < needed) {
        uc_log_status(&inst->log, fmi2Error, "fmi2SerializeFMUstate: buffer of %zu bytes, %zu needed", size, needed);
        return fmi2Error;
    }
    Writer w = {buffer, 0};
    write_state(&w, (const UCSavedState*)state);
    return fmi2OK;
}

typedef struct Reader {
    const fmi2Byte* data;
    size_t size;
    size_t pos;
    int overrun;
} Reader;

static void get(Reader* r, void* bytes, size_t n) {
    if (r->overrun || n > r->size - r->pos) {
        r->overrun = 1;
        memset(bytes, 0, n);
        return;
    }
    memcpy(bytes, r->data + r->pos, n);
    r->pos += n;
}
static uint32_t get_u32(Reader* r) { uint32_t v; get(r, &v, sizeof v); return v; }
static uint64_t get_u64(Reader* r) { uint64_t v; get(r, &v, sizeof v); return v; }
static int32_t get_i32(Reader* r) { int32_t v; get(r, &v, sizeof v); return v; }
static double get_f64(Reader* r) { double v; get(r, &v, sizeof v); return v; }

/* The n bytes of a block written by put_runs into a zero-filled block (its zero runs are left as they are,
 * so that a block claimed larger than it is costs no memory it does not hold); a run beyond n or a short
 * buffer marks the reader overrun. */
static void get_runs(Reader* r, void* block, size_t n) {
    unsigned char* bytes = (unsigned char*)block;
    const size_t words = (n + UC_RUN_WORD - 1) / UC_RUN_WORD;
    size_t at = 0;
    while (at < words && !r->overrun) {
        const size_t zeros = get_u32(r), data = get_u32(r);
        if (r->overrun || zeros > words - at || data > words - at - zeros || zeros + data == 0) {
            r->overrun = 1;
            return;
        }
        const size_t from = (at + zeros) * UC_RUN_WORD;
        const size_t to = (at + zeros + data) * UC_RUN_WORD < n ? (at + zeros + data) * UC_RUN_WORD : n;
        if (to > from) get(r, bytes + from, to - from);
        at += zeros + data;
    }
}

static fmi2Status reject(UCInstance* inst, const char* what) {
    uc_log_status(&inst->log, fmi2Error, "fmi2DeSerializeFMUstate: %s", what);
    return fmi2Error;
}

/* Reads and checks the header; returns the core size through coreSize. */
static fmi2Status read_header(UCInstance* inst, Reader* r, uint64_t* coreSize) {
    char magic[8], guid[UC_GUID_FIELD_SIZE];
    get(r, magic, sizeof magic);
    if (r->overrun || memcmp(magic, UC_STATE_MAGIC, sizeof magic) != 0) {
        return reject(inst, "not a serialized UnderwaterCable state (bad magic)");
    }
    if (get_u32(r) != UC_STATE_FORMAT_VERSION) return reject(inst, "unsupported state format version");
    get(r, guid, sizeof guid);
    guid[sizeof guid - 1] = '\0';
    if (strcmp(guid, UC_GUID) != 0) {
        uc_log_status(&inst->log, fmi2Error, "fmi2DeSerializeFMUstate: state of guid %s, this FMU is %s", guid,
                      UC_GUID);
        return fmi2Error;
    }
    if (get_u32(r) != UC_NUM_STATIONS) return reject(inst, "number of output stations K differs");
    if (get_u32(r) != sizeof(UCParams) || get_u32(r) != sizeof(UCInputs) || get_u32(r) != sizeof(UCOutputs)) {
        return reject(inst, "parameter, input or output layout differs from this binary");
    }
    *coreSize = get_u64(r);
    if (r->overrun) return reject(inst, "truncated header");
    return fmi2OK;
}

static fmi2Status read_body(UCInstance* inst, Reader* r, UCSavedState* s) {
    s->machineState = get_i32(r);
#define UC_GET_FIELD(field, kind) s->field = get_##kind(r);
    UC_ADAPTER_SCALARS(UC_GET_FIELD)
#undef UC_GET_FIELD
    get_runs(r, &s->params, sizeof s->params);
    get_runs(r, &s->coreParams, sizeof s->coreParams);
    get_runs(r, &s->inputs, sizeof s->inputs);
    get_runs(r, &s->outputs, sizeof s->outputs);
    if (s->coreSize > 0) get_runs(r, s->core, s->coreSize);
    if (r->overrun) return reject(inst, "truncated state");
    if (r->pos != r->size) return reject(inst, "trailing bytes after the state");
    if (s->machineState < UC_STATE_INSTANTIATED || s->machineState > UC_STATE_FATAL ||
        (s->machineState & (s->machineState - 1)) != 0) {
        return reject(inst, "invalid machine state");
    }
    return fmi2OK;
}

fmi2Status uc_state_deserialize(UCInstance* inst, const fmi2Byte buffer[], size_t size, fmi2FMUstate* state) {
    Reader r = {buffer, size, 0, buffer == NULL};
    uint64_t coreSize = 0;
    if (state == NULL) return reject(inst, "FMUstate is NULL");
    if (read_header(inst, &r, &coreSize) != fmi2OK) return fmi2Error;
    if (coreSize > SIZE_MAX / 2) return reject(inst, "core size beyond this platform's memory");
    UCSavedState* s = calloc(1, sizeof *s); /* zero-filled: the blocks' runs of zeros are not written */
    if (s == NULL) return reject(inst, "out of memory");
    s->coreSize = (size_t)coreSize;
    s->core = coreSize > 0 ? calloc(1, (size_t)coreSize) : NULL;
    if (coreSize > 0 && s->core == NULL) {
        free(s);
        uc_log_status(&inst->log, fmi2Error, "fmi2DeSerializeFMUstate: out of memory for the %llu bytes of the "
                      "cable state", (unsigned long long)coreSize);
        return fmi2Error;
    }
    if (read_body(inst, &r, s) != fmi2OK) {
        free(s->core);
        free(s);
        return fmi2Error;
    }
    memcpy(s->magic, UC_STATE_MAGIC, sizeof s->magic);
    *state = s; /* a new state, whatever *state held on entry (importers may pass uninitialized memory) */
    return fmi2OK;
}
