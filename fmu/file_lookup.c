/* file_lookup.c - see file_lookup.h. */
#include "file_lookup.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

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

int uc_file_candidates(const char* name, const char* resources, char* candidates[2]) {
    int n = 0;
    if (name[0] == '/') {
        candidates[n] = join_path("", name);
        return candidates[n] != NULL ? 1 : 0;
    }
    if (resources != NULL) {
        candidates[n] = join_path(resources, name);
        if (candidates[n] != NULL) ++n;
    }
    char cwd[4096];
    candidates[n] = join_path(getcwd(cwd, sizeof cwd) != NULL ? cwd : "", name);
    if (candidates[n] != NULL) ++n;
    return n;
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

void uc_file_note_tried(char* tried, size_t size, const char* path, int error) {
    const size_t used = strlen(tried);
    if (used < size) snprintf(tried + used, size - used, "%s%s (%s)", used > 0 ? ", " : "", path, reason(error));
}
