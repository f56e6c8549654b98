/*
 * partner.h - the interface between the generic FMI 2.0 co-simulation adapter of the partner FMUs
 * (partner_fmi.c) and one partner model (vessel/vessel.c, towed_body/towed_body.c): the same split as
 * the cable's (fmu/ <-> src/api/cable_api.h). The model knows no FMI call sequence, the adapter no physics.
 *
 * A model keeps everything in one plain struct of doubles, its "data": parameters, inputs, states and
 * outputs. Saving an FMU state is then a byte copy. Its variables are one table (name, causality,
 * place in the data, start value, admissible range, unit, description); the adapter's value references
 * are the table positions, and the model description is written from the same table at build time
 * (model_description.c), so the two cannot drift apart.
 */
#ifndef UNDERWATERCABLE_PARTNER_H
#define UNDERWATERCABLE_PARTNER_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A Boolean is stored as 0.0 / 1.0 in the data, an Integer as a double holding an integer, a String as
   char[PM_STRING_CAPACITY] (start "", zero-filled beyond its end so that equal strings are equal bytes). */
typedef enum { PM_REAL, PM_BOOLEAN, PM_INTEGER, PM_STRING } PMType;

#define PM_STRING_CAPACITY 4096 /* bytes of a String parameter with its NUL: a path */

typedef enum { PM_PARAMETER, PM_INPUT, PM_OUTPUT } PMCausality;

typedef struct PMVariable {
    const char* name;        /* FMU name (structured naming convention) */
    PMType type;
    PMCausality causality;
    size_t offset;           /* byte offset of the double (String: the char array) in the model's data */
    double start;            /* parameters and inputs: the start value */
    double min, max;         /* parameters: the admissible closed interval */
    const char* why;         /* parameters: the reason printed when a value is outside [min, max] */
    const char* unit;        /* one of the units of model_description.c, NULL when dimensionless */
    const char* description;
    int feedthrough;         /* outputs: 1 if the output depends directly on the inputs (ModelStructure) */
} PMVariable;

/* Every function returns 0 on success, otherwise non-zero with a one-line reason in msg.
 *
 * A model may also keep derived data: tables built from its parameters and from files in the FMU's
 * resources directory (the MuJoCo "model" next to the "data"). The adapter builds them before the
 * initialization (build), hands them to initialize and do_step read-only, and rebuilds them from the
 * restored parameters after an FMU state is restored, so they are never part of a saved state. A model
 * without derived data leaves build and release NULL and receives derived = NULL. */
typedef struct PMModel {
    const char* identifier;  /* model identifier = name of the shared library */
    const char* description;
    size_t dataSize;         /* sizeof the model's data struct */
    const PMVariable* variables;
    size_t nVariables;
    /* Conditions between parameters that no single range expresses (called after the range checks). */
    int (*check)(const void* data, char* msg, size_t msgSize);
    /* The states at t0 from the parameters (and inputs), then the outputs. */
    int (*initialize)(void* data, const void* derived, double t0, char* msg, size_t msgSize);
    /* From t to t + h with the inputs held constant; the outputs at t + h. */
    int (*do_step)(void* data, const void* derived, double t, double h, char* msg, size_t msgSize);
    /* The derived data of the parameters in data; resources: the FMU's resources directory (a path, NULL
       when the importer gave none). NULL with a reason in msg when they cannot be built. */
    void* (*build)(const void* data, const char* resources, char* msg, size_t msgSize);
    void (*release)(void* derived);
} PMModel;

/* The one model linked into this FMU (defined by the model's source file). */
extern const PMModel kPartnerModel;

/* Variable declaration helpers for the models' tables (T: the model's data type). */
#define PM_PAR(T, field, name, start, min, max, unit, why, description) \
    {name, PM_REAL, PM_PARAMETER, offsetof(T, field), start, min, max, why, unit, description, 0}
#define PM_BOOL_PAR(T, field, name, start, description) \
    {name, PM_BOOLEAN, PM_PARAMETER, offsetof(T, field), start, 0.0, 1.0, "a Boolean", NULL, description, 0}
#define PM_INT_PAR(T, field, name, start, min, max, why, description) \
    {name, PM_INTEGER, PM_PARAMETER, offsetof(T, field), start, min, max, why, NULL, description, 0}
#define PM_STRING_PAR(T, field, name, description) \
    {name, PM_STRING, PM_PARAMETER, offsetof(T, field), 0.0, 0.0, 0.0, NULL, NULL, description, 0}
#define PM_IN(T, field, name, unit, description) \
    {name, PM_REAL, PM_INPUT, offsetof(T, field), 0.0, 0.0, 0.0, NULL, unit, description, 0}
#define PM_OUT(T, field, name, unit, feedthrough, description) \
    {name, PM_REAL, PM_OUTPUT, offsetof(T, field), 0.0, 0.0, 0.0, NULL, unit, description, feedthrough}

#ifdef __cplusplus
}
#endif

#endif /* UNDERWATERCABLE_PARTNER_H */
