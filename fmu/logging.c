/* logging.c - see logging.h. */
#include "logging.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#define UC_LOG_MESSAGE_SIZE 1024

static const char* const kCategoryNames[UC_LOG_CATEGORY_COUNT] = {
    "logEvents", "logSolver", "logStatusWarning", "logStatusDiscard", "logStatusError", "logStatusFatal", "logAll",
};

const char* uc_log_category_name(UCLogCategory category) { return kCategoryNames[category]; }

static int category_from_name(const char* name) {
    for (int i = 0; i < UC_LOG_CATEGORY_COUNT; ++i) {
        if (name != NULL && strcmp(name, kCategoryNames[i]) == 0) return i;
    }
    return -1;
}

fmi2Status uc_log_configure(UCLogger* logger, int loggingOn, size_t nCategories, const fmi2String categories[]) {
    const unsigned int all = (1u << UC_LOG_CATEGORY_COUNT) - 1u;
    unsigned int enabled = nCategories == 0 ? all : 0u;
    if (nCategories > 0 && categories == NULL) {
        uc_log_status(logger, fmi2Error, "fmi2SetDebugLogging: categories is NULL but nCategories = %zu", nCategories);
        return fmi2Error;
    }
    for (size_t i = 0; i < nCategories; ++i) {
        int c = category_from_name(categories[i]);
        if (c < 0) {
            uc_log_status(logger, fmi2Error, "fmi2SetDebugLogging: unknown log category \"%s\"",
                          categories[i] ? categories[i] : "(null)");
            return fmi2Error;
        }
        enabled |= (c == UC_LOG_ALL) ? all : (1u << c);
    }
    logger->loggingOn = loggingOn != 0;
    logger->enabled = enabled;
    return fmi2OK;
}

/* Doubles '%' and '#' and drops trailing newlines; out has room for 2 * strlen(in) + 1. */
static void escape_message(const char* in, char* out) {
    char* o = out;
    for (const char* c = in; *c != '\0'; ++c) {
        if (*c == '%' || *c == '#') *o++ = *c;
        *o++ = *c;
    }
    while (o > out && (o[-1] == '\n' || o[-1] == '\r')) --o;
    *o = '\0';
}

void uc_log_raw(fmi2CallbackLogger callback, fmi2ComponentEnvironment environment, const char* instanceName,
                fmi2Status status, UCLogCategory category, const char* message) {
    char escaped[2 * UC_LOG_MESSAGE_SIZE + 1];
    char truncated[UC_LOG_MESSAGE_SIZE];
    if (callback == NULL) return;
    snprintf(truncated, sizeof truncated, "%s", message);
    escape_message(truncated, escaped);
    callback(environment, instanceName ? instanceName : "", status, kCategoryNames[category], escaped);
}

static int is_emitted(const UCLogger* logger, fmi2Status status, UCLogCategory category) {
    if (status != fmi2OK) return 1;
    return logger->loggingOn && (logger->enabled & (1u << category)) != 0;
}

static void log_va(const UCLogger* logger, fmi2Status status, UCLogCategory category, const char* format,
                   va_list args) {
    char message[UC_LOG_MESSAGE_SIZE];
    if (logger == NULL || !is_emitted(logger, status, category)) return;
    vsnprintf(message, sizeof message, format, args);
    uc_log_raw(logger->callback, logger->environment, logger->instanceName, status, category, message);
}

void uc_log(const UCLogger* logger, fmi2Status status, UCLogCategory category, const char* format, ...) {
    va_list args;
    va_start(args, format);
    log_va(logger, status, category, format, args);
    va_end(args);
}

static UCLogCategory category_of_status(fmi2Status status) {
    switch (status) {
        case fmi2Warning: return UC_LOG_STATUS_WARNING;
        case fmi2Discard: return UC_LOG_STATUS_DISCARD;
        case fmi2Error: return UC_LOG_STATUS_ERROR;
        case fmi2Fatal: return UC_LOG_STATUS_FATAL;
        default: return UC_LOG_EVENTS;
    }
}

void uc_log_status(const UCLogger* logger, fmi2Status status, const char* format, ...) {
    va_list args;
    va_start(args, format);
    log_va(logger, status, category_of_status(status), format, args);
    va_end(args);
}

int uc_log_lines(const UCLogger* logger, const char* prefix, const char* text) {
    int warnings = 0;
    for (const char* line = text; line != NULL && *line != '\0';) {
        const char* end = strchr(line, '\n');
        const int length = end != NULL ? (int)(end - line) : (int)strlen(line);
        if (strncmp(line, "warning: ", 9) == 0) {
            uc_log_status(logger, fmi2Warning, "%s%.*s", prefix, length - 9, line + 9);
            ++warnings;
        } else if (length > 0) {
            uc_log(logger, fmi2OK, UC_LOG_EVENTS, "%s%.*s", prefix, length, line);
        }
        line += length + (end != NULL);
    }
    return warnings;
}
