/* string_value.c - see string_value.h. */
#include "string_value.h"

#include <string.h>

int uc_string_fits(const UCLogger* log, const char* function, const char* name, size_t size, const char* value) {
    if (value == NULL) {
        uc_log_status(log, fmi2Error, "%s: %s: the value is a NULL pointer (an empty string is \"\")", function,
                      name);
        return -1;
    }
    /* memchr stops at the first NUL (C11 7.24.5.1): never reads past the end of a short string. */
    if (memchr(value, '\0', size) == NULL) {
        uc_log_status(log, fmi2Error, "%s: %s: the string is longer than the %zu bytes this FMU keeps", function,
                      name, size - 1);
        return -1;
    }
    return 0;
}

int uc_store_string(const UCLogger* log, const char* function, const char* name, char* target, size_t size,
                    const char* value) {
    if (uc_string_fits(log, function, name, size, value) != 0) return -1;
    if (strcmp(target, value) == 0) return 0;
    memset(target, 0, size);
    memcpy(target, value, strlen(value));
    return 1;
}
