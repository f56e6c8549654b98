/*
 * logging.h - messages to the importer's logger callback (FMI 2.0 section 2.1.5).
 * Messages are formatted here, '%' and '#' are doubled (the importer treats the message as a printf
 * format and '#' as the value-reference escape), there is no trailing newline, and the category is one of
 * the <LogCategories> of modelDescription.xml. Messages of fmi2Warning and worse are always emitted;
 * fmi2OK messages only when logging is on and their category is enabled.
 */
#ifndef UNDERWATERCABLE_FMU_LOGGING_H
#define UNDERWATERCABLE_FMU_LOGGING_H

#include "fmi2FunctionTypes.h"

typedef enum {
    UC_LOG_EVENTS,
    UC_LOG_SOLVER,
    UC_LOG_STATUS_WARNING,
    UC_LOG_STATUS_DISCARD,
    UC_LOG_STATUS_ERROR,
    UC_LOG_STATUS_FATAL,
    UC_LOG_ALL,
    UC_LOG_CATEGORY_COUNT
} UCLogCategory;

typedef struct UCLogger {
    fmi2CallbackLogger callback;      /* never NULL (fmi2Instantiate rejects NULL) */
    fmi2ComponentEnvironment environment;
    const char* instanceName;         /* owned by the instance */
    int loggingOn;
    unsigned int enabled;             /* bit i: category i enabled */
} UCLogger;

/* The messages are formatted with the C99 printf (%zu, %lld): glibc's, or MinGW-w64's own on Windows
 * (__USE_MINGW_ANSI_STDIO, cmake/UcPlatform.cmake), which the compiler checks as gnu_printf. */
#if defined(__MINGW32__)
#define UC_PRINTF_FORMAT(fmt, args) __attribute__((format(gnu_printf, fmt, args)))
#else
#define UC_PRINTF_FORMAT(fmt, args) __attribute__((format(printf, fmt, args)))
#endif

const char* uc_log_category_name(UCLogCategory category);

/* Sets loggingOn and the enabled categories (nCategories == 0: all). fmi2Error (logged) for an unknown name. */
fmi2Status uc_log_configure(UCLogger* logger, int loggingOn, size_t nCategories, const fmi2String categories[]);

/* Logs with an explicit category (status fmi2OK: only if enabled). */
void uc_log(const UCLogger* logger, fmi2Status status, UCLogCategory category, const char* format, ...)
    UC_PRINTF_FORMAT(4, 5);

/* Logs with the logStatus* category that matches the status (Warning, Discard, Error, Fatal). */
void uc_log_status(const UCLogger* logger, fmi2Status status, const char* format, ...)
    UC_PRINTF_FORMAT(3, 4);

/* Logs each line of text (the core's events of a step, a deck's notes), each after prefix: a line that starts
 * "warning: " with status fmi2Warning (category logStatusWarning, the mark dropped), any other as an event
 * (fmi2OK, logEvents). Returns the number of warnings. */
int uc_log_lines(const UCLogger* logger, const char* prefix, const char* text);

/* The same through a logger callback before an instance exists (fmi2Instantiate); callback may be NULL. */
void uc_log_raw(fmi2CallbackLogger callback, fmi2ComponentEnvironment environment, const char* instanceName,
                fmi2Status status, UCLogCategory category, const char* message);

#endif /* UNDERWATERCABLE_FMU_LOGGING_H */
