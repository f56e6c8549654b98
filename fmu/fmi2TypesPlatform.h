/*
 * fmi2TypesPlatform.h - FMI 2.0 platform-dependent base types (FMI 2.0.x specification, section 2.1.2).
 * Written from the type definitions of the specification; ABI-compatible with the standard header
 * for the "default" platform (LP64 Linux).
 */
#ifndef fmi2TypesPlatform_h
#define fmi2TypesPlatform_h

/* Compatible platform: always "default" for the standard types below. */
#define fmi2TypesPlatform "default"

typedef void* fmi2Component;            /* pointer to the model instance */
typedef void* fmi2ComponentEnvironment; /* pointer to the environment of the importer */
typedef void* fmi2FMUstate;             /* pointer to an internal FMU state */
typedef unsigned int fmi2ValueReference;
typedef double fmi2Real;
typedef int fmi2Integer;
typedef int fmi2Boolean;
typedef char fmi2Char;
typedef const fmi2Char* fmi2String;
typedef char fmi2Byte;

#define fmi2True 1
#define fmi2False 0

#endif /* fmi2TypesPlatform_h */
