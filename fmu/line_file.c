/* line_file.c - see line_file.h. */
#include "line_file.h"

#include "file_uri.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define UC_NOTES_SIZE 8192

/* dir + "/" + name in a new buffer (free it); NULL when out of memory. */
static char* join_path(const char* dir, const char* name) {
    const size_t d = strlen(dir), n = strlen(name);
    const int slash = d > 0 && dir[d - 1] != '/';
    char* path = malloc(d + (size_t)slash + n + 1);
    if (path == NULL) return NULL;
    memcpy(path, dir, d);
    if (slash) path[d] = '/';
    memcpy(path + d + slash, name, n + 1);
    return path;
}

static const char* reason(int error) {
    switch (error) {
        case ENOENT: return "no such file";
        case EACCES: return "permission denied";
        case EISDIR: return "a directory";
        case EFBIG: return "larger than 16 MiB";
        case ENOMEM: return "out of memory";
        default: return "cannot be read";
    }
}

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

/* The candidate paths of lineFile, in order: resources directory, then working directory (relative
 * paths), or the path itself (absolute). Returns how many were made (0..2); free each. */
static int candidate_paths(const UCInstance* inst, char* candidates[2]) {
    const char* name = inst->params.lineFile;
    int n = 0;
    if (name[0] == '/') {
        candidates[n] = join_path("", name);
        return candidates[n] != NULL ? 1 : 0;
    }
    if (inst->resourceLocation != NULL) {
        const size_t size = strlen(inst->resourceLocation) + 1;
        char* dir = malloc(size);
        if (dir != NULL && uc_file_uri_to_path(inst->resourceLocation, dir, size) == 0) {
            candidates[n] = join_path(dir, name);
            if (candidates[n] != NULL) ++n;
        }
        free(dir);
    }
    char cwd[4096];
    candidates[n] = join_path(getcwd(cwd, sizeof cwd) != NULL ? cwd : "", name);
    if (candidates[n] != NULL) ++n;
    return n;
}

static void log_notes(UCInstance* inst, const char* function, const char* path, const char* notes) {
    for (const char* line = notes; *line != '\0';) {
        const char* end = strchr(line, '\n');
        const int length = end != NULL ? (int)(end - line) : (int)strlen(line);
        uc_log(&inst->log, fmi2OK, UC_LOG_EVENTS, "%s: lineFile %s, %.*s", function, path, length, line);
        line += length + (end != NULL);
    }
}

static fmi2Status apply_text(UCInstance* inst, UCParams* p, const char* function, const char* path,
                             const char* text, size_t length) {
    double vessel[3] = {0.0, 0.0, 0.0};
    char* notes = malloc(UC_NOTES_SIZE);
    inst->msg[0] = '\0';
    const int rc = uc_line_file_apply(text, length, p, vessel, notes, notes != NULL ? UC_NOTES_SIZE : 0, inst->msg,
                                      sizeof inst->msg);
    if (rc != 0) {
        uc_log_status(&inst->log, fmi2Error, "%s: lineFile %s, %s", function, path, inst->msg);
        free(notes);
        return fmi2Error;
    }
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

fmi2Status uc_line_file_load(UCInstance* inst, UCParams* p, const char* function) {
    char* candidates[2] = {NULL, NULL};
    const int n = candidate_paths(inst, candidates);
    char tried[1024] = "";
    fmi2Status status = fmi2Error;
    int done = 0;
    for (int k = 0; k < n && !done; ++k) {
        size_t length = 0;
        int error = 0;
        char* text = read_file(candidates[k], &length, &error);
        if (text == NULL) {
            const size_t used = strlen(tried);
            snprintf(tried + used, sizeof tried - used, "%s%s (%s)", used > 0 ? ", " : "", candidates[k],
                     reason(error));
            continue;
        }
        status = apply_text(inst, p, function, candidates[k], text, length);
        free(text);
        done = 1;
    }
    if (!done) {
        uc_log_status(&inst->log, fmi2Error, "%s: lineFile = '%s' cannot be read: tried %s%s", function,
                      inst->params.lineFile, n > 0 ? tried : "nothing (out of memory)",
                      inst->params.lineFile[0] != '/' && inst->resourceLocation == NULL
                          ? "; no resources directory was given to fmi2Instantiate"
                          : "");
    }
    for (int k = 0; k < n; ++k) free(candidates[k]);
    return status;
}
