/*
 * file_uri.h - the local path of a file: URI (the fmuResourceLocation an importer hands to
 * fmi2Instantiate), shared by the cable FMU and its partner FMUs.
 */
#ifndef UC_FILE_URI_H
#define UC_FILE_URI_H

#include <stddef.h>

/* file:///p, file://localhost/p or file:/p with percent-encoding decoded into path (size bytes); on Windows
 * file:///C:/p is the path C:/p.
 * Returns 0 on success, 1 when the URI is not a local file URI or the path does not fit. */
int uc_file_uri_to_path(const char* uri, char* path, size_t size);

#endif
