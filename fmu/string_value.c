/* string_value.c - see string_value.h. */
#include "string_value.h"

#include <string.h>

int uc_store_string(const UCLogger* log, const char* function, const char* name, char* target, size_t size,
                    const char* value) {
    if (value == NULL) {
        uc_log_status(log, fmi2Error, "%s: %s: the value is a NULL pointer (an empty string is \"\")", function,
                      name);
        return -1;
    }
    /* memchr stops at the first NUL (C11 7.24.5.1): never reads past the end of a short string. */
    const char* end = memchr(value, '\0', size);
    if (end == NULL) {
        uc_log_status(log, fmi2Error, "%s: %s: the string is longer than the %zu bytes this FMU keeps", function,
                      name, size - 1);
        return -1;
    }
    if (strcmp(target, value) == 0) return 0;
    memset(target, 0, size);
    memcpy(target, value, (size_t)(end - value));
    return 1;
}
