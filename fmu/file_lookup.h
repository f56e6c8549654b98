/*
 * file_lookup.h - where a String parameter naming a file is looked for (the cable FMU's lineFile, the
 * partner FMUs' raoFile): an absolute path or a file: URI is itself; a relative path is looked up in the FMU's resources
 * directory (fmuResourceLocation of fmi2Instantiate) first, then in the working directory.
 */
#ifndef UC_FILE_LOOKUP_H
#define UC_FILE_LOOKUP_H

#include <stddef.h>

/* 1 when name is an absolute path: /p, and on Windows also C:\p, C:/p, \\server\share\p and \p. */
int uc_file_is_absolute(const char* name);

/* The candidate paths of name, in the order they are tried (a file: URI is the one path it names); resources: the resources directory as a
 * path (NULL: none was given). Returns how many were made (0..2; fewer when out of memory); free each. */
int uc_file_candidates(const char* name, const char* resources, char* candidates[2]);

/* Appends "path (reason)" for the errno value error to the list in tried (size bytes), comma-separated. */
void uc_file_note_tried(char* tried, size_t size, const char* path, int error);

#endif
