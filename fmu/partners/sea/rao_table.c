/* rao_table.c - see rao_table.h. */
#include "rao_table.h"

#include "file_lookup.h"
#include "file_uri.h"
#include "partner.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double kPi = 3.14159265358979323846;
#define N_DOF PM_RAO_DOF

void pm_rao_free(PMRAOTable* t) {
    free(t->periods);
    free(t->headings);
    free(t->re);
    free(t->im);
    memset(t, 0, sizeof *t);
}

static int compare_doubles(const void* a, const void* b) {
    double x = *(const double*)a, y = *(const double*)b;
    return x < y ? -1 : x > y;
}

/* The sorted distinct values of v[0..n) in place; their number. */
static size_t unique_sorted(double* v, size_t n) {
    qsort(v, n, sizeof *v, compare_doubles);
    size_t m = 0;
    for (size_t i = 0; i < n; ++i)
        if (m == 0 || v[i] != v[m - 1]) v[m++] = v[i];
    return m;
}

static size_t find_index(const double* v, size_t n, double x) {
    for (size_t i = 0; i < n; ++i)
        if (v[i] == x) return i;
    return n;
}

static double normalized_heading(double deg) {
    double h = fmod(deg, 360.0);
    return h < 0.0 ? h + 360.0 : h;
}

int pm_rao_read(const char* path, PMRAOTable* table, char* msg, size_t msgSize) {
    memset(table, 0, sizeof *table);
    FILE* f = fopen(path, "r");
    if (f == NULL) {
        snprintf(msg, msgSize, "cannot open the RAO table %s", path);
        return 1;
    }
    size_t capacity = 0, nRows = 0;
    double* rows = NULL; /* 14 numbers per row */
    char line[1024];
    int lineNo = 0, header = 0, rc = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        ++lineNo;
        char* s = line;
        while (*s == ' ' || *s == '\t') ++s;
        if (*s == '#' || *s == '\n' || *s == '\r' || *s == '\0') continue;
        double v[14];
        int k = 0;
        char* p = s;
        for (; k < 14; ++k) {
            char* end;
            v[k] = strtod(p, &end);
            if (end == p) break;
            while (*end == ' ' || *end == '\t') ++end;
            p = end;
            if (k < 13) {
                if (*p != ',') { ++k; break; }
                ++p;
            }
        }
        while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') ++p;
        if (k == 0 && !header && nRows == 0) { /* the column names */
            header = 1;
            continue;
        }
        if (k != 14 || *p != '\0') {
            snprintf(msg, msgSize, "RAO table %s, line %d: expected 14 comma-separated numbers (period, heading, "
                     "amplitude and phase of surge, sway, heave, roll, pitch, yaw)", path, lineNo);
            rc = 1;
            break;
        }
        int bad = !(v[0] > 0.0) || !isfinite(v[0]) || !isfinite(v[1]);
        for (int j = 2; j < 14; ++j) bad |= !isfinite(v[j]) || (j % 2 == 0 && v[j] < 0.0);
        if (bad) {
            snprintf(msg, msgSize, "RAO table %s, line %d: a period must be positive, amplitudes non-negative and "
                     "every number finite", path, lineNo);
            rc = 1;
            break;
        }
        if (nRows == capacity) {
            capacity = capacity ? 2 * capacity : 256;
            double* grown = realloc(rows, capacity * 14 * sizeof *rows);
            if (grown == NULL) {
                snprintf(msg, msgSize, "RAO table %s: out of memory", path);
                rc = 1;
                break;
            }
            rows = grown;
        }
        v[1] = normalized_heading(v[1]);
        memcpy(rows + nRows * 14, v, sizeof v);
        ++nRows;
    }
    fclose(f);
    if (rc == 0 && nRows == 0) {
        snprintf(msg, msgSize, "RAO table %s has no rows", path);
        rc = 1;
    }
    if (rc == 0) {
        table->periods = malloc(nRows * sizeof(double));
        table->headings = malloc(nRows * sizeof(double));
        if (table->periods == NULL || table->headings == NULL) {
            snprintf(msg, msgSize, "RAO table %s: out of memory", path);
            rc = 1;
        }
    }
    if (rc == 0) {
        for (size_t r = 0; r < nRows; ++r) {
            table->periods[r] = rows[r * 14];
            table->headings[r] = rows[r * 14 + 1];
        }
        table->nPeriods = unique_sorted(table->periods, nRows);
        table->nHeadings = unique_sorted(table->headings, nRows);
        if (table->nPeriods * table->nHeadings != nRows) {
            snprintf(msg, msgSize, "RAO table %s: %zu rows are not one per period and heading (%zu periods x %zu "
                     "headings)", path, nRows, table->nPeriods, table->nHeadings);
            rc = 1;
        }
    }
    if (rc == 0) {
        const size_t size = nRows * N_DOF;
        table->re = calloc(size, sizeof(double));
        table->im = calloc(size, sizeof(double));
        char* seen = calloc(nRows, 1);
        if (table->re == NULL || table->im == NULL || seen == NULL) {
            snprintf(msg, msgSize, "RAO table %s: out of memory", path);
            rc = 1;
        }
        for (size_t r = 0; rc == 0 && r < nRows; ++r) {
            const double* v = rows + r * 14;
            const size_t cell = find_index(table->periods, table->nPeriods, v[0]) * table->nHeadings +
                                find_index(table->headings, table->nHeadings, v[1]);
            if (seen[cell]) {
                snprintf(msg, msgSize, "RAO table %s: period %g s and heading %g deg appear twice", path, v[0], v[1]);
                rc = 1;
                break;
            }
            seen[cell] = 1;
            for (int j = 0; j < N_DOF; ++j) {
                const double amplitude = v[2 + 2 * j] * (j >= 3 ? kPi / 180.0 : 1.0);
                const double lag = v[3 + 2 * j] * kPi / 180.0;
                table->re[cell * N_DOF + j] = amplitude * cos(lag);
                table->im[cell * N_DOF + j] = amplitude * sin(lag);
            }
        }
        free(seen);
    }
    free(rows);
    if (rc != 0) pm_rao_free(table);
    return rc;
}

/* Linear interpolation weights of x in the ascending v[0..n): i0, i1 and the weight of i1 (held beyond). */
static void bracket(const double* v, size_t n, double x, size_t* i0, size_t* i1, double* w) {
    if (n == 1 || x <= v[0]) {
        *i0 = *i1 = 0, *w = 0.0;
        return;
    }
    if (x >= v[n - 1]) {
        *i0 = *i1 = n - 1, *w = 0.0;
        return;
    }
    size_t i = 0;
    while (v[i + 1] < x) ++i;
    *i0 = i, *i1 = i + 1, *w = (x - v[i]) / (v[i + 1] - v[i]);
}

/* The same, periodic over [0, 360) degrees. */
static void bracket_heading(const double* v, size_t n, double x, size_t* i0, size_t* i1, double* w) {
    if (n == 1) {
        *i0 = *i1 = 0, *w = 0.0;
        return;
    }
    if (x >= v[0] && x <= v[n - 1]) {
        bracket(v, n, x, i0, i1, w);
        return;
    }
    const double span = v[0] + 360.0 - v[n - 1]; /* from the last heading round to the first */
    const double d = x >= v[n - 1] ? x - v[n - 1] : x + 360.0 - v[n - 1];
    *i0 = n - 1, *i1 = 0, *w = d / span;
}

/* The four table cells around (T, mu), the weights of the second period and heading and their slopes
   (per s and per deg; 0 where the table is held). */
typedef struct Cell {
    size_t c00, c01, c10, c11;
    double wp, wh, dwp, dwh;
} Cell;

static Cell cell_of(const PMRAOTable* t, double T, double mu) {
    size_t p0, p1, h0, h1;
    Cell c;
    bracket(t->periods, t->nPeriods, T, &p0, &p1, &c.wp);
    bracket_heading(t->headings, t->nHeadings, normalized_heading(mu), &h0, &h1, &c.wh);
    c.c00 = (p0 * t->nHeadings + h0) * N_DOF, c.c01 = (p0 * t->nHeadings + h1) * N_DOF;
    c.c10 = (p1 * t->nHeadings + h0) * N_DOF, c.c11 = (p1 * t->nHeadings + h1) * N_DOF;
    c.dwp = p1 != p0 ? 1.0 / (t->periods[p1] - t->periods[p0]) : 0.0;
    c.dwh = h1 == h0   ? 0.0
            : h1 > h0 ? 1.0 / (t->headings[h1] - t->headings[h0])
                      : 1.0 / (t->headings[0] + 360.0 - t->headings[t->nHeadings - 1]);
    return c;
}

/* The bilinear interpolation of the table's values v (re or im) of degree of freedom j. */
static double bilinear(const double* v, const Cell* c, int j) {
    return (1 - c->wp) * ((1 - c->wh) * v[c->c00 + j] + c->wh * v[c->c01 + j]) +
           c->wp * ((1 - c->wh) * v[c->c10 + j] + c->wh * v[c->c11 + j]);
}

void pm_rao_interpolate(const PMRAOTable* t, double T, double mu, double* re, double* im) {
    const Cell c = cell_of(t, T, mu);
    for (int j = 0; j < N_DOF; ++j) {
        re[j] = bilinear(t->re, &c, j);
        im[j] = bilinear(t->im, &c, j);
    }
}

/* d/dT, d/dmu and d2/dTdmu of the bilinear interpolation of v. */
static void slopes(const double* v, const Cell* c, int j, double* dT, double* dmu, double* dTmu) {
    const double v00 = v[c->c00 + j], v01 = v[c->c01 + j], v10 = v[c->c10 + j], v11 = v[c->c11 + j];
    *dT = c->dwp * ((1 - c->wh) * (v10 - v00) + c->wh * (v11 - v01));
    *dmu = c->dwh * ((1 - c->wp) * (v01 - v00) + c->wp * (v11 - v10));
    *dTmu = c->dwp * c->dwh * (v11 - v10 - v01 + v00);
}

void pm_rao_interpolate_rates(const PMRAOTable* t, double T, double mu, double dT, double dmu, double ddT,
                              double ddmu, double* re, double* im, double* dre, double* dim, double* ddre,
                              double* ddim) {
    const Cell c = cell_of(t, T, mu);
    const int heldT = c.dwp == 0.0; /* then the period's rates may be infinite: they do not count */
    for (int j = 0; j < N_DOF; ++j) {
        const double* v[2] = {t->re, t->im};
        double* out[2][3] = {{&re[j], &dre[j], &ddre[j]}, {&im[j], &dim[j], &ddim[j]}};
        for (int k = 0; k < 2; ++k) {
            double sT, sMu, sTMu;
            slopes(v[k], &c, j, &sT, &sMu, &sTMu);
            *out[k][0] = bilinear(v[k], &c, j);
            *out[k][1] = sMu * dmu + (heldT ? 0.0 : sT * dT);
            *out[k][2] = sMu * ddmu + (heldT ? 0.0 : sT * ddT + 2.0 * sTMu * dT * dmu);
        }
    }
}

/* The first of name's candidates (file_lookup.h) that opens, in a new buffer (free it); NULL with the paths
   tried, and why, in msg (file: the value of raoFile, for the message). */
static char* find_table(const char* resources, const char* file, const char* name, char* msg, size_t msgSize) {
    char* candidates[2] = {NULL, NULL};
    const int n = uc_file_candidates(name, resources, candidates);
    char tried[1024] = "";
    char* found = NULL;
    for (int k = 0; k < n; ++k) {
        FILE* f = found == NULL ? fopen(candidates[k], "r") : NULL;
        if (f != NULL) {
            fclose(f);
            found = candidates[k];
            continue;
        }
        if (found == NULL) uc_file_note_tried(tried, sizeof tried, candidates[k], errno);
        free(candidates[k]);
    }
    if (found == NULL) {
        snprintf(msg, msgSize, "raoFile = '%s' cannot be read: tried %s%s", file,
                 n > 0 ? tried : "nothing (out of memory)",
                 !uc_file_is_absolute(name) && resources == NULL ? "; no resources directory was given to fmi2Instantiate" : "");
    }
    return found;
}

int pm_rao_load(const char* resources, const char* file, PMRAOTable* table, char* msg, size_t msgSize) {
    memset(table, 0, sizeof *table);
    const char* name = file;                 /* the path to look up */
    char buffer[PM_STRING_CAPACITY + 64];    /* ... when it is not raoFile's value itself */
    if (file[0] == '\0') {                   /* the shipped table: in the resources only */
        if (resources == NULL) {
            snprintf(msg, msgSize, "raoFile = '': no resources directory was given to fmi2Instantiate: the shipped "
                     "RAO table " PM_RAO_FILE " is in the FMU's resources");
            return 1;
        }
        snprintf(buffer, sizeof buffer, "%s/%s", resources, PM_RAO_FILE);
        name = buffer;
    } else if (strncmp(file, "file:", 5) == 0) {
        if (uc_file_uri_to_path(file, buffer, sizeof buffer) != 0) {
            snprintf(msg, msgSize, "raoFile = '%s' is not a local file URI (file:///path)", file);
            return 1;
        }
        name = buffer;
    }
    char* path = find_table(resources, file, name, msg, msgSize);
    if (path == NULL) return 1;
    char reason[PM_RAO_MESSAGE_SIZE];
    const int rc = pm_rao_read(path, table, reason, sizeof reason);
    if (rc != 0) snprintf(msg, msgSize, "raoFile = '%s': %s", file, reason);
    free(path);
    return rc;
}

void pm_rao_point(const double* q, const double* p, double* out) {
    out[0] = q[0] + q[4] * p[2] - q[5] * p[1];
    out[1] = q[1] + q[5] * p[0] - q[3] * p[2];
    out[2] = q[2] + q[3] * p[1] - q[4] * p[0];
}
