/*
 * cable_api.h - the only interface between the FMI adapter (fmu/, C) and the
 * physics core (src/, C++17). No FMI knowledge on this side; no physics on the other.
 *
 * Life cycle:  uc_params_default -> (caller edits fields) -> uc_params_check
 *              -> uc_create -> uc_initialize -> uc_do_step ... -> uc_free;
 *              inputs start from uc_inputs_default.
 * Every function that can fail returns 0 on success and non-zero on failure and
 * then writes a one-line, human-readable reason into msg (never NULL-terminated
 * past msgSize). No function throws, prints, aborts or keeps global state.
 *
 * Units are SI throughout (m, s, kg, N, rad). Earth frame: x, y horizontal, z up,
 * free surface at z = 0. Arc length s = 0 at the tow point, s = length at the far end.
 */
#ifndef UNDERWATERCABLE_CABLE_API_H
#define UNDERWATERCABLE_CABLE_API_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The structs UCParams, UCInputs, UCOutputs and the constants of their fields: model/parameters.h. */
#include "model/parameters.h"

typedef struct UCCable UCCable;

/* The line of a MoorDyn v2 input file (docs/lines.md), given as its text (length bytes, no terminating
 * NUL needed), written into *p: line properties, element count (from NumSegs, or p->lineFileElements),
 * far end (anchor), water depth, gravity and density; the other parameters are kept. towPoint (may be
 * NULL) receives the deck's vessel point. notes (may be NULL) receives what was ignored or adjusted, one
 * "line <n>: ..." per line of text. Returns 0, or 1 with msg = "line <n>: <what is wrong or unsupported>". */
int uc_line_file_apply(const char* text, size_t length, UCParams* p, double towPoint[3], char* notes,
                       size_t notesSize, char* msg, size_t msgSize);

/* 1 when the deck's text describes a mooring system (several lines, points on bodies or a BODIES section;
 * docs/systems_mooring.md) rather than one line (uc_line_file_apply). */
int uc_line_file_is_system(const char* text, size_t length);

/* A mooring system from the deck's text: every line takes the parameters *p (checked per line) with its
 * own properties, far end and the deck's environment. The single-line outputs are line 1's; the system's
 * are line[k].*, body[k].*, point[k].*; its inputs body[k].*, point[k].* (and current, ...). The other
 * calls take the result as they take a cable. NULL on failure (msg says why, "line <n>: ..." for a line
 * of the text); notes as for uc_line_file_apply. */
UCCable* uc_create_system(const UCParams* p, const char* text, size_t length, char* notes, size_t notesSize,
                          char* msg, size_t msgSize);

/* A file MoorDyn reads from the deck's directory (current_profile.txt, wave_frequencies.txt): its name and
 * its text (length bytes). */
typedef struct UCLineFileCompanion {
    const char* name;
    const char* text;
    size_t length;
} UCLineFileCompanion;

/* The names of the files next to the deck that its kinematics options ask for (docs/lines.md), each
 * followed by '\n', into names (NUL-terminated; may be NULL). Returns their number. */
int uc_line_file_companions(const char* text, size_t length, char* names, size_t namesSize);
/* The files the companion `name` of that deck (its text: companion, companionLength) names in turn (a Syrope
 * settings file's original working curve), relative to the deck, as uc_line_file_companions. */
int uc_line_file_nested_companions(const char* text, size_t length, const char* name, const char* companion,
                                   size_t companionLength, char* names, size_t namesSize);

/* uc_line_file_apply and uc_create_system with the companion files read (n of them; a file the deck needs
 * and the caller could not read is left out: the deck is then refused naming it). */
int uc_line_file_apply_with(const char* text, size_t length, const UCLineFileCompanion* companions, int n,
                            UCParams* p, double towPoint[3], char* notes, size_t notesSize, char* msg, size_t msgSize);
UCCable* uc_create_system_with(const UCParams* p, const char* text, size_t length,
                               const UCLineFileCompanion* companions, int n, char* notes, size_t notesSize,
                               char* msg, size_t msgSize);

/* The wave components of a waves.file (docs/waves.md, "Given components": rows omega amplitude phase
 * [direction]), given as its text (length bytes), written into *p (waveComponentCount, waveComponents;
 * a row without a direction takes p->wavesDirection). Returns 0, or 1 with msg = "line <n>: <what>". */
int uc_wave_file_apply(const char* text, size_t length, UCParams* p, char* msg, size_t msgSize);

/* The current given as data (currents.mode 2 or 5, docs/waves.md "A current given as data"): the text of
 * its file in MoorDyn's format (current_profile_dynamic.txt for mode 2, current_profile_4d.txt for 5), read
 * and given to every line of c, in place of any it had (a deck's). Call it after uc_create or
 * uc_create_system and before uc_initialize or uc_state_restore (the data are not in the saved state).
 * Returns 0 with msg = a description of the data, or 1 with msg = "line <n>: <what>". */
int uc_set_current_text(UCCable* c, int mode, const char* text, size_t length, char* msg, size_t msgSize);

/* The seabed given as a grid (seabed.file, a deck's SeafloorFile that is not a plane; docs/model.md "A seabed
 * given as a grid"): the text of the file in MoorDyn's SeafloorFile or MoorPy's bathymetry format, read and
 * given to every line of c in place of its seabed. Call it after uc_create or uc_create_system and before
 * uc_initialize or uc_state_restore (the grid is not in the saved state). Returns 0 with msg = a description
 * of the grid, or 1 with msg = "line <n>: <what>". */
int uc_set_seabed_text(UCCable* c, const char* text, size_t length, char* msg, size_t msgSize);

/* Defaults: the Hopland 1993 tow cable, free lower end, hinged top, 20 elements. */
/* The inputs' start values (zero, but currentScale 1): initialize every UCInputs with it. */
void uc_inputs_default(UCInputs* in);
void uc_params_default(UCParams* p);

/* 0 if every parameter is admissible; otherwise 1 and msg reads like
 * "length = -3 is outside (0, inf): the cable must have a positive length". */
int uc_params_check(const UCParams* p, char* msg, size_t msgSize);

/* Checks the parameters and builds the immutable model and the workspace. NULL on failure (msg says why). */
UCCable* uc_create(const UCParams* p, char* msg, size_t msgSize);
void uc_free(UCCable* c);

/* Initial state at time t0 from the inputs: initMode 0 equilibrium (steady tow included), 1 straight line at rest. */
int uc_initialize(UCCable* c, double t0, const UCInputs* in, char* msg, size_t msgSize);

/* Integrates from t to exactly t + h (h >= UC_MIN_STEP_SIZE with t + h > t in doubles, t must
 * equal the current time of the cable).
 * The tow point follows a quintic in time from the cable's current end state (position,
 * velocity, acceleration) to in->tow + v h + a h^2/2 with velocity v + a h and acceleration a
 * at t + h; when the inputs agree with the current end state this is exactly
 * tow + v (t' - t) + a (t' - t)^2 / 2.
 * a is in->towAcceleration when in->towAccelerationGiven, otherwise the difference of the
 * last two tow velocity inputs over the last step size (0 on the first step). */
int uc_do_step(UCCable* c, double t, double h, const UCInputs* in, char* msg, size_t msgSize);

/* on != 0: a mooring system's uc_do_step (or one line's, with failure.line = 1) that holds a line failure's break
 * strictly inside it ends there (FMI 3.0's early return): uc_time is then the break's time, short of t + h, the state
 * the state at the break, and the next uc_do_step goes on from there. 0 (the default): every step reaches t + h. */
void uc_set_stop_at_breaks(UCCable* c, int on);

/* The water pushed by the importer (water.source 1, docs/waves.md "Water pushed by the importer"): the number of
 * the lines' load points (3 per element from the tow end, the lines one after the other; 0 with water.source 0),
 * where they stand at uc_time (that many values into each of x, y, z), and their water from time t on (velocity u
 * and local acceleration a, one array per component, the first uc_water_points values of each, copied). Not in
 * the saved state: call uc_set_water before uc_initialize and before every uc_do_step. */
size_t uc_water_points(const UCCable* c);
void uc_water_positions(const UCCable* c, double* x, double* y, double* z);
void uc_set_water(UCCable* c, double t, const double* const u[3], const double* const a[3]);

/* The interface derivatives over the next communication step (taken as long as the last one) in the
 * direction seed: out[i] = sum_j d output_i(t + h) / d input_j(t) seed[j] for the outputs towForce x, y, z,
 * endForce x, y, z (i = 0..5) and the inputs tow x, y, z, vx, vy, vz (j = 0..5), end x, y, z, vx, vy, vz
 * (6..11), tow ax, ay, az (12..14), end ax, ay, az (15..17) (the end inputs act only when bottomEnd = 3 or 4).
 * Only the requested direction is computed. Available after the first step; docs/cosimulation.md says
 * exactly what they are. */
int uc_interface_derivative(UCCable* c, const double seed[18], double out[6], char* msg, size_t msgSize);

/* The same for coupled body `body` (1-based) of a mooring system: d[UC_BODY_DERIVATIVE_INPUTS i + j] =
 * d output_i(t + h) / d input_j(t) for the outputs body[k].force.x/y/z, body[k].moment.x/y/z (i = 0..5) and
 * the inputs body[k].x, y, z, roll, pitch, yaw, vx, vy, vz, wx, wy, wz, q0, q1, q2, q3 (j = 0..15; the
 * orientation inputs that bodyOrientation does not read have 0; docs/systems_mooring.md). Available after
 * the first step. */
int uc_body_derivatives(UCCable* c, int body, double d[6 * UC_BODY_DERIVATIVE_INPUTS], char* msg, size_t msgSize);

/* Where the tow point stands now: the end of the last step's trajectory (the previous inputs
 * extrapolated), or the initial tow position. A position input far from it is a displacement. */
void uc_tow_position(const UCCable* c, double p[3]);

/* The same for the other driven inputs: kind UC_DRIVEN_END, the far end of bottomEnd 3 (end.*);
 * UC_DRIVEN_BODY, coupled body `index`'s reference point (body[index].*, 1-based); UC_DRIVEN_POINT, coupled
 * point `index` (point[index].*). Returns 1 with p set, or 0 (p untouched) where the model has no such input
 * (another far end, a single line's body or point, a point no line reaches). */
int uc_driven_position(const UCCable* c, int kind, int index, double p[3]);

/* Which end.* inputs the model reads, as it decided the far end once from bottomEnd: UC_END_INPUTS_EXTERNAL
 * where an external body is at the far end (bottomEnd 3 or 4: its position, velocity and acceleration),
 * plus UC_END_INPUTS_DRIVEN where the far end moves with them (bottomEnd 3); 0 for another far end, a mooring
 * system, or c NULL. */
#define UC_END_INPUTS_EXTERNAL 1
#define UC_END_INPUTS_DRIVEN 2
int uc_end_inputs(const UCCable* c);

/* How far two acceleration inputs disagree with the velocity inputs between them [m/s2 or rad/s2]: a0 at the
 * previous communication point, a1 at this one, dv the change of the velocity input over the step h between
 * them. The mean acceleration dv / h of any acceleration that moves monotonically from a0 to a1 lies between
 * them; the distance of dv / h from that interval is returned when it exceeds UC_ACCELERATION_FLOOR +
 * UC_ACCELERATION_MARGIN times the largest of |dv / h|, |a0|, |a1| (a smooth motion sampled three times per
 * period stays within it), else 0. Accelerations held at 0 while the velocity changes disagree by all of
 * dv / h; an acceleration in the wrong unit or frame by most of it. */
double uc_acceleration_disagreement(double a0, double a1, double dv, double h);

double uc_time(const UCCable* c);
void uc_get_outputs(const UCCable* c, UCOutputs* out);
/* A mooring system's body[k].stiffness (docs/systems_mooring.md, "Mooring stiffness") into out: computed at the
 * first call after an initialization, a step or a restore, copied at the next; nothing for a single line. A
 * body whose stiffness is not computed gets 0 and an event (uc_take_event) says why; 1 (msg) only on an
 * internal error. */
int uc_update_stiffness(UCCable* c, UCOutputs* out, char* msg, size_t msgSize);

/* Exact state save/restore: a plain byte copy of everything that determines the future.
 * The state holds the integrator's history (step size, order, divided differences), so the run
 * continues without a restart; after uc_state_save and after uc_state_restore the next step
 * evaluates a new Jacobian, so a saved-and-continued run and a restored-and-continued run are
 * bit-identical. The buffer is only valid for a cable created with identical parameters. */
/* The events since the last call worth a log line (a winch limit reached), one a line; a line starting
 * "warning: " is a warning (a strain beyond the tension-strain curve): 1 and the text, or 0. */
int uc_take_event(UCCable* c, char* text, size_t size);

size_t uc_state_size(const UCCable* c);
int uc_state_save(UCCable* c, void* buffer, size_t size);
/* 0: restored; 1: refused (msg) before anything changed (a state of another size, version or deck);
 * 2: failed (msg) after the core had started taking the state: the core is no longer usable. */
int uc_state_restore(UCCable* c, const void* buffer, size_t size, char* msg, size_t msgSize);

#ifdef __cplusplus
}
#endif

#endif /* UNDERWATERCABLE_CABLE_API_H */
