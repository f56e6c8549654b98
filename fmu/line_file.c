/* line_file.c - see line_file.h. */
#include "line_file.h"

#include "file_lookup.h"
#include "file_uri.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define UC_NOTES_SIZE 8192

/* The whole file in a new NUL-terminated buffer (free it); NULL with *error set when it cannot be read. */
static char* read_file(const char* path, size_t* length, int* error) {
    FILE* f = fopen(path, "rb");
    if (f == NULL) {
        *error = errno;
        return NULL;
    }
    size_t capacity = 4096, n = 0;
    char* text = malloc(capacity);
    *error = 0;
    while (text != NULL) {
        n += fread(text + n, 1, capacity - n - 1, f);
        if (ferror(f)) {
            *error = errno != 0 ? errno : EIO;
            break;
        }
        if (feof(f)) break;
        if (capacity > UC_LINE_FILE_MAX_BYTES) {
            *error = EFBIG;
            break;
        }
        char* grown = realloc(text, 2 * capacity);
        if (grown == NULL) break;
        text = grown;
        capacity *= 2;
    }
    fclose(f);
    if (text == NULL || *error != 0) {
        if (*error == 0) *error = ENOMEM;
        free(text);
        return NULL;
    }
    text[n] = '\0';
    *length = n;
    return text;
}

/* The files next to the deck that its options and line types ask for (MoorDyn's current_profile.txt, a
 * tension-strain file, a SeafloorFile, ...): read from the deck's directory; a name with directories
 * (MoorDyn reads a SeafloorFile from its working directory, "Mooring/3D_seafloor/x.txt") is also tried there
 * without its leading directories, one at a time, then as it is from the working directory. One that cannot
 * be read is left out, and the reader refuses the deck naming it. */
#define UC_MAX_COMPANIONS 8
typedef struct Companions {
    UCLineFileCompanion files[UC_MAX_COMPANIONS];
    char* texts[UC_MAX_COMPANIONS];
    char* paths[UC_MAX_COMPANIONS]; /* where each was read from */
    char names[1024];
    int n;
} Companions;

static void read_companions(const char* path, const char* text, size_t length, Companions* c) {
    memset(c, 0, sizeof *c);
    uc_line_file_companions(text, length, c->names, sizeof c->names);
    size_t dir = strlen(path);
    while (dir > 0 && path[dir - 1] != '/' && path[dir - 1] != '\\') --dir;
    for (char* name = c->names; *name != '\0' && c->n < UC_MAX_COMPANIONS;) {
        char* end = strchr(name, '\n');
        if (end == NULL) break;
        *end = '\0';
        char* full = malloc(dir + strlen(name) + 1);
        if (full != NULL) {
            size_t n = 0;
            int error = 0;
            char* companion = NULL;
            for (const char* tail = name; companion == NULL && tail != NULL;) {
                memcpy(full, path, dir);
                strcpy(full + dir, tail);
                companion = read_file(full, &n, &error);
                tail = strpbrk(tail, "/\\");
                if (tail != NULL) ++tail;
            }
            if (companion == NULL) {
                companion = read_file(name, &n, &error);
                if (companion != NULL) strcpy(full, name);
            }
            if (companion != NULL) {
                c->paths[c->n] = full;
                full = NULL;
                c->texts[c->n] = companion;
                c->files[c->n].name = name;
                c->files[c->n].text = companion;
                c->files[c->n].length = n;
                ++c->n;
                /* the files it names in turn (a Syrope settings file's curve) join the list, read in their turn */
                char* tail = end + 1 + strlen(end + 1);
                const size_t room = sizeof c->names - (size_t)(tail - c->names);
                if (room > 1) uc_line_file_nested_companions(text, length, name, companion, n, tail, room);
            }
            free(full);
        }
        name = end + 1;
    }
}

static void free_companions(Companions* c) {
    for (int k = 0; k < c->n; ++k) {
        free(c->texts[k]);
        free(c->paths[k]);
    }
    c->n = 0;
}

/* The candidate paths of lineFile (file_lookup.h); the resources directory from fmuResourceLocation. */
static int candidate_paths(const UCInstance* inst, const char* lineFile, char* candidates[2]) {
    char* dir = NULL;
    if (inst->resourceLocation != NULL) {
        const size_t size = strlen(inst->resourceLocation) + 1;
        dir = malloc(size);
        if (dir != NULL && uc_file_uri_to_path(inst->resourceLocation, dir, size) != 0) {
            free(dir);
            dir = NULL;
        }
    }
    const int n = uc_file_candidates(lineFile, dir, candidates);
    free(dir);
    return n;
}

/* "warning: ...": a deck option the FMU honours otherwise than MoorDyn (line_file.h) */
static void log_notes(UCInstance* inst, const char* function, const char* path, const char* notes) {
    char prefix[1024];
    snprintf(prefix, sizeof prefix, "%s: lineFile %s, ", function, path);
    uc_log_lines(&inst->log, prefix, notes);
}

static fmi2Status apply_text(UCInstance* inst, UCParams* p, const char* function, const char* path,
                             const char* text, size_t length) {
    double vessel[3] = {0.0, 0.0, 0.0};
    char* notes = malloc(UC_NOTES_SIZE);
    inst->msg[0] = '\0';
    Companions companions;
    read_companions(path, text, length, &companions);
    const int rc = uc_line_file_apply_with(text, length, companions.files, companions.n, p, vessel, notes,
                                           notes != NULL ? UC_NOTES_SIZE : 0, inst->msg, sizeof inst->msg);
    /* a deck's SeafloorFile that is not a plane: likewise the path it was read from */
    if (rc == 0 && p->seabedFile[0] != '\0' && inst->params.seabedFile[0] == '\0') {
        for (int k = 0; k < companions.n; ++k) {
            if (strcmp(companions.files[k].name, p->seabedFile) == 0 && strlen(companions.paths[k]) < sizeof p->seabedFile) {
                strcpy(p->seabedFile, companions.paths[k]);
                break;
            }
        }
    }
    /* the deck's Currents 2 or 5 names its data file beside the deck: the path it was read from instead */
    if (rc == 0 && p->currentsMode != 0 && inst->params.currentsFile[0] == '\0') {
        for (int k = 0; k < companions.n; ++k) {
            if (strcmp(companions.files[k].name, p->currentsFile) == 0 &&
                strlen(companions.paths[k]) < sizeof p->currentsFile) {
                strcpy(p->currentsFile, companions.paths[k]);
                break;
            }
        }
    }
    free_companions(&companions);
    if (rc != 0 && uc_line_file_is_system(text, length)) {
        /* a mooring system: made from the text by uc_line_file_create_system */
        free(notes);
        p->mooringSystem = 1;
        uc_log(&inst->log, fmi2OK, UC_LOG_EVENTS, "%s: lineFile %s read (%zu bytes): a mooring system", function, path,
               length);
        return fmi2OK;
    }
    if (rc != 0) {
        uc_log_status(&inst->log, fmi2Error, "%s: lineFile %s, %s", function, path, inst->msg);
        free(notes);
        return fmi2Error;
    }
    p->mooringSystem = 0;
    uc_log(&inst->log, fmi2OK, UC_LOG_EVENTS, "%s: lineFile %s read (%zu bytes): %.17g m, %d elements", function,
           path, length, p->length, p->nElements);
    if (notes != NULL) log_notes(inst, function, path, notes);
    free(notes);
    const double* tow = inst->inputs.tow;
    if (tow[0] != vessel[0] || tow[1] != vessel[1] || tow[2] != vessel[2]) {
        uc_log(&inst->log, fmi2OK, UC_LOG_EVENTS,
               "%s: lineFile %s: the tow point follows the inputs tow.x/y/z = (%.9g, %.9g, %.9g), not the file's "
               "vessel point (%.9g, %.9g, %.9g)",
               function, path, tow[0], tow[1], tow[2], vessel[0], vessel[1], vessel[2]);
    }
    return fmi2OK;
}

/* The mooring system of the text (the parameters of each line are *p with its own). */
static fmi2Status create_system(UCInstance* inst, const UCParams* p, const char* function, const char* path,
                                const char* text, size_t length, UCCable** cable) {
    char* notes = malloc(UC_NOTES_SIZE);
    inst->msg[0] = '\0';
    Companions companions;
    read_companions(path, text, length, &companions);
    *cable = uc_create_system_with(p, text, length, companions.files, companions.n, notes,
                                   notes != NULL ? UC_NOTES_SIZE : 0, inst->msg, sizeof inst->msg);
    free_companions(&companions);
    if (*cable == NULL) {
        uc_log_status(&inst->log, fmi2Error, "%s: lineFile %s, %s", function, path, inst->msg);
        free(notes);
        return fmi2Error;
    }
    if (notes != NULL) log_notes(inst, function, path, notes);
    free(notes);
    return fmi2OK;
}

/* The text of the file `name` names (the parameter `label`: lineFile, waves.file), read from the first of its
 * candidate paths that can be read, with that path in *path (both freed by the caller); NULL after the
 * error "<label> = '<name>' cannot be read: tried ..." is logged. */
static char* read_named_file(UCInstance* inst, const char* label, const char* name, const char* function,
                             char** path, size_t* length) {
    char* candidates[2] = {NULL, NULL};
    const int n = candidate_paths(inst, name, candidates);
    char tried[1024] = "";
    char* text = NULL;
    *path = NULL;
    for (int k = 0; k < n; ++k) {
        int error = 0;
        if (text == NULL) {
            text = read_file(candidates[k], length, &error);
            if (text == NULL) {
                uc_file_note_tried(tried, sizeof tried, candidates[k], error);
            } else {
                *path = candidates[k];
                continue;
            }
        }
        free(candidates[k]);
    }
    if (text == NULL) {
        uc_log_status(&inst->log, fmi2Error, "%s: %s = '%s' cannot be read: tried %s%s", function, label, name,
                      n > 0 ? tried : "nothing (out of memory)",
                      !uc_file_is_absolute(name) && inst->resourceLocation == NULL
                          ? "; no resources directory was given to fmi2Instantiate"
                          : "");
    }
    return text;
}

/* Reads lineFile and hands its text to apply (p) or create (cable). */
static fmi2Status with_text(UCInstance* inst, UCParams* p, const UCParams* params, UCCable** cable,
                            const char* function) {
    /* the file the parameters in use name: a restore builds from its state's before it takes them */
    const char* lineFile = params != NULL ? params->lineFile : p->lineFile;
    char* path = NULL;
    size_t length = 0;
    char* text = read_named_file(inst, "lineFile", lineFile, function, &path, &length);
    if (text == NULL) return fmi2Error;
    const fmi2Status status = cable != NULL ? create_system(inst, params, function, path, text, length, cable)
                                            : apply_text(inst, p, function, path, text, length);
    free(text);
    free(path);
    return status;
}

/* The UC_DECK_KEEP_* bits of the parameters the importer set explicitly (docs/lines.md, "Seabed"):
 * those keep their value over the deck's. */
static int deck_keep(const UCInstance* inst) {
    static const struct {
        const char* name;
        int bit;
    } kept[] = {{"waterDepth", UC_DECK_KEEP_WATER_DEPTH},
                {"gravity", UC_DECK_KEEP_GRAVITY},
                {"waterDensity", UC_DECK_KEEP_WATER_DENSITY},
                {"enableSeabed", UC_DECK_KEEP_ENABLE_SEABED},
                {"seabedStiffness", UC_DECK_KEEP_SEABED_STIFFNESS},
                {"seabedDamping", UC_DECK_KEEP_SEABED_DAMPING},
                {"seabedFriction", UC_DECK_KEEP_SEABED_FRICTION},
                {"enableCompression", UC_DECK_KEEP_ENABLE_COMPRESSION}};
    int bits = 0;
    for (size_t k = 0; k < sizeof kept / sizeof kept[0]; ++k)
        if (uc_instance_was_set(inst, kept[k].name)) bits |= kept[k].bit;
    return bits;
}

fmi2Status uc_line_file_load(UCInstance* inst, UCParams* p, const char* function) {
    p->deckKeep = deck_keep(inst);
    return with_text(inst, p, NULL, NULL, function);
}

fmi2Status uc_line_file_create_system(UCInstance* inst, const UCParams* p, UCCable** cable, const char* function) {
    *cable = NULL;
    return with_text(inst, NULL, p, cable, function);
}

/* Reads the file `name` of the parameter `label` (looked up as lineFile's) and hands its text to apply, which
 * returns 0 with inst->msg = what it read, or non-zero with inst->msg = why not; logged either way. */
typedef int (*ApplyText)(UCInstance* inst, const char* text, size_t length, void* context);

static fmi2Status load_named_file(UCInstance* inst, const char* label, const char* name, const char* function,
                                  ApplyText apply, void* context) {
    char* path = NULL;
    size_t length = 0;
    char* text = read_named_file(inst, label, name, function, &path, &length);
    if (text == NULL) return fmi2Error;
    fmi2Status status = fmi2Error;
    inst->msg[0] = '\0';
    if (apply(inst, text, length, context) != 0) {
        uc_log_status(&inst->log, fmi2Error, "%s: %s %s, %s", function, label, path, inst->msg);
    } else {
        uc_log(&inst->log, fmi2OK, UC_LOG_EVENTS, "%s: %s %s read: %s", function, label, path, inst->msg);
        status = fmi2OK;
    }
    free(text);
    free(path);
    return status;
}

static int apply_waves(UCInstance* inst, const char* text, size_t length, void* context) {
    UCParams* p = context;
    if (uc_wave_file_apply(text, length, p, inst->msg, sizeof inst->msg) != 0) return 1;
    snprintf(inst->msg, sizeof inst->msg, "%d wave components", p->waveComponentCount);
    return 0;
}

fmi2Status uc_wave_file_load(UCInstance* inst, UCParams* p, const char* function) {
    return load_named_file(inst, "waves.file", p->wavesFile, function, apply_waves, p);
}

typedef struct CurrentTarget {
    const UCParams* p;
    UCCable* cable;
} CurrentTarget;

static int apply_currents(UCInstance* inst, const char* text, size_t length, void* context) {
    const CurrentTarget* target = context;
    const int mode = target->p->currentsMode;
    /* the refusal after "(currents.mode m), "; what was read without it */
    const size_t n = (size_t)snprintf(inst->msg, sizeof inst->msg, "(currents.mode %d), ", mode);
    if (uc_set_current_text(target->cable, mode, text, length, inst->msg + n, sizeof inst->msg - n) != 0) return 1;
    memmove(inst->msg, inst->msg + n, strlen(inst->msg + n) + 1);
    return 0;
}

fmi2Status uc_current_file_load(UCInstance* inst, const UCParams* p, UCCable* cable, const char* function) {
    if (p->currentsMode == 0) return fmi2OK;
    CurrentTarget target = {p, cable};
    return load_named_file(inst, "currents.file", p->currentsFile, function, apply_currents, &target);
}

static int apply_seabed(UCInstance* inst, const char* text, size_t length, void* context) {
    return uc_set_seabed_text((UCCable*)context, text, length, inst->msg, sizeof inst->msg);
}

fmi2Status uc_seabed_file_load(UCInstance* inst, const UCParams* p, UCCable* cable, const char* function) {
    if (p->seabedFile[0] == '\0') return fmi2OK;
    return load_named_file(inst, "seabed.file", p->seabedFile, function, apply_seabed, cable);
}
