/*
 * rao_table.h - displacement RAOs of a vessel for the partner FMUs that move with the waves (VesselRAO, and
 * Vessel's superimposed wave motion): the table the parameter raoFile names (default: rao.csv of the FMU's
 * resources), its complex bilinear interpolation in period and heading, and the rigid-body motion of a
 * point at a lever arm.
 *
 * The table (docs/waves.md): comment lines (#), one line of column names, then rows of period [s], relative
 * heading [deg] (the waves' direction of travel relative to the bow: 0 following seas, 90 waves travelling
 * to port, 180 head seas), then amplitude and phase for surge, sway, heave (m/m), roll, pitch, yaw (deg/m),
 * phases in degrees as lags behind the wave crest at the reference point; one row per period and heading
 * of a full grid. A component of amplitude a with the phase theta of its elevation a cos(theta) at the
 * reference point moves degree of freedom j by a |R_j| cos(theta - phi_j) = a (re_j cos theta + im_j sin
 * theta), R_j = re_j + i im_j = |R_j| e^(i phi_j) the interpolated RAO.
 */
#ifndef UNDERWATERCABLE_RAO_TABLE_H
#define UNDERWATERCABLE_RAO_TABLE_H

#include <stddef.h>

#include "partner.h"

#ifdef __cplusplus
extern "C" {
#endif

#define PM_RAO_FILE "rao.csv"
#define PM_RAO_DOF 6
#define PM_RAO_MESSAGE_SIZE 512 /* enough for the messages of pm_rao_read with a path */

/* The variable-table entry of the parameter raoFile, the char[PM_STRING_CAPACITY] `field` of the model data
   type T (docs/waves.md). */
#define PM_RAO_FILE_VARIABLE(T, field)                                                                         \
    PM_STRING_PAR(T, field, "raoFile",                                                                         \
                  "Displacement RAO table (docs/waves.md): empty, the shipped generic table resources/rao.csv; "  \
                  "otherwise a path or a file:// URI, a relative path looked up in the FMU's resources "           \
                  "directory, then in the working directory")

typedef struct PMRAOTable {
    size_t nPeriods, nHeadings;
    double* periods;  /* ascending */
    double* headings; /* ascending in [0, 360) */
    double* re;       /* [(iPeriod * nHeadings + iHeading) * PM_RAO_DOF + j]: real and imaginary RAO, rad for angles */
    double* im;
} PMRAOTable;

/* Reads the table the parameter raoFile names (file): "" the shipped PM_RAO_FILE of the FMU's resources
   directory (a path; NULL: none was given); otherwise a path or a file: URI, a relative path looked up in
   the resources directory, then in the working directory (fmu/file_lookup.h, as the cable FMU's lineFile).
   0 on success, else a message naming raoFile and the paths tried, or the file and line. */
int pm_rao_load(const char* resources, const char* file, PMRAOTable* table, char* msg, size_t msgSize);

/* Reads the table from path; 0 on success, else a message naming the file and line. */
int pm_rao_read(const char* path, PMRAOTable* table, char* msg, size_t msgSize);

void pm_rao_free(PMRAOTable* table);

/* The complex RAO (re, im; rotations in rad/m) of every degree of freedom at period T [s] and relative
   heading mu [deg]: linear in period (held beyond the table's periods, T may be infinite), periodic in
   heading. */
void pm_rao_interpolate(const PMRAOTable* table, double T, double mu, double* re, double* im);

/* The same and its first and second time derivatives along a path T(t), mu(t) with the rates dT, dmu and
   ddT, ddmu, the interpolation's slopes held within the cell of the table (piecewise bilinear: the first
   derivatives jump where the path crosses a tabulated period or heading). Rates of T do not count where
   the table holds (T beyond its periods). */
void pm_rao_interpolate_rates(const PMRAOTable* table, double T, double mu, double dT, double dmu, double ddT,
                              double ddmu, double* re, double* im, double* dre, double* dim, double* ddre,
                              double* ddim);

/* The displacement of the point p (body axes, from the reference point) of a body whose reference point
   moves by q = (surge, sway, heave, roll, pitch, yaw), small rotations: q[0..2] + q[3..5] x p. Linear, so
   the same for rates and accelerations. */
void pm_rao_point(const double* q, const double* p, double* out);

#ifdef __cplusplus
}
#endif

#endif /* UNDERWATERCABLE_RAO_TABLE_H */
