/*
 * string_value.h - the value of a String variable, shared by the cable FMU and its partner FMUs: a
 * zero-filled char array in the instance, into which fmi2SetString copies the caller's string (the
 * caller's memory is only valid during the call and is never kept).
 */
#ifndef UC_STRING_VALUE_H
#define UC_STRING_VALUE_H

#include <stddef.h>

#include "logging.h"

/* Copies value into target (size bytes), zero-filled beyond the string so that equal strings are equal
 * bytes (as the saved states compare and copy them). Returns 1 if target changed, 0 if it held value
 * already, -1 (logged as fmi2Error naming function and the variable name) for NULL or a string longer
 * than size - 1 bytes. */
/* 0 if value can be stored in size bytes; -1 (logged as uc_store_string does) for NULL or too long. */
int uc_string_fits(const UCLogger* log, const char* function, const char* name, size_t size, const char* value);

int uc_store_string(const UCLogger* log, const char* function, const char* name, char* target, size_t size,
                    const char* value);

#endif
