/* file_lookup.c - see file_lookup.h. */
#include "file_lookup.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "file_uri.h"

static int is_separator(char c) {
#ifdef _WIN32
    return c == '/' || c == '\\';
#else
    return c == '/';
#endif
}

int uc_file_is_absolute(const char* name) {
    if (is_separator(name[0])) return 1;
#ifdef _WIN32
    if (isalpha((unsigned char)name[0]) && name[1] == ':' && is_separator(name[2])) return 1;
#endif
    return 0;
}

/* dir + "/" + name in a new buffer (free it); NULL when out of memory. */
static char* join_path(const char* dir, const char* name) {
    const size_t d = strlen(dir), n = strlen(name);
    const int slash = d > 0 && !is_separator(dir[d - 1]);
    char* path = malloc(d + (size_t)slash + n + 1);
    if (path == NULL) return NULL;
    memcpy(path, dir, d);
    if (slash) path[d] = '/';
    memcpy(path + d + slash, name, n + 1);
    return path;
}

int uc_file_candidates(const char* name, const char* resources, char* candidates[2]) {
    int n = 0;
    if (strncmp(name, "file:", 5) == 0) {
        /* a URI that is no local file URI stays as it is: opening it fails and the message names it */
        const size_t size = strlen(name) + 1;
        char* path = malloc(size);
        if (path != NULL && uc_file_uri_to_path(name, path, size) != 0) memcpy(path, name, size);
        candidates[n] = path;
        return path != NULL ? 1 : 0;
    }
    if (uc_file_is_absolute(name)) {
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
