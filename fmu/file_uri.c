/* file_uri.c - see file_uri.h. */
#include "file_uri.h"

#include <ctype.h>
#include <string.h>

static int hex_value(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

int uc_file_uri_to_path(const char* uri, char* path, size_t size) {
    if (uri == NULL || path == NULL || size == 0 || strncmp(uri, "file:", 5) != 0) return 1;
    const char* s = uri + 5;
    if (strncmp(s, "//", 2) == 0) { /* an authority: empty or localhost */
        s += 2;
        if (strncmp(s, "localhost", 9) == 0) s += 9;
        if (*s != '/') return 1;
    }
    if (*s != '/') return 1;
    size_t n = 0;
    for (; *s != '\0'; ++s) {
        char c = *s;
        if (c == '%') {
            const int hi = hex_value(s[1]), lo = hi < 0 ? -1 : hex_value(s[2]);
            if (hi < 0 || lo < 0 || (hi == 0 && lo == 0)) return 1;
            c = (char)(hi * 16 + lo);
            s += 2;
        }
        if (n + 1 >= size) return 1;
        path[n++] = c;
    }
    path[n] = '\0';
#ifdef _WIN32
    /* file:///C:/dir names the path C:/dir (RFC 8089, appendix E.2): drop the slash before the drive. */
    if (n >= 3 && path[0] == '/' && isalpha((unsigned char)path[1]) && path[2] == ':') memmove(path, path + 1, n);
#endif
    return 0;
}
