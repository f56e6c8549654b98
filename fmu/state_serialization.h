/*
 * state_serialization.h - FMU states (fmi2GetFMUstate/SetFMUstate/FreeFMUstate) and their serialized
 * form (FMI 2.0 section 2.1.8). A state is the adapter state (machine state, times,
 * parameters, inputs, outputs, flags) plus the core bytes of uc_state_save. Restoring into an instance
 * that was never initialized creates the core from the saved parameters first (those the core was created
 * with: a line file is not read again).
 *
 * Serialized layout (native byte order, this platform only):
 *   header: magic "UCFMUST\0", u32 format version, char guid[64], u32 K (UC_NUM_STATIONS),
 *           u32 sizeof(UCParams), u32 sizeof(UCInputs), u32 sizeof(UCOutputs), u64 core size
 *   body:   i32 machine state, f64 startTime, i32 stopTimeDefined, f64 stopTime, f64 time,
 *           f64 lastSuccessfulTime, i32 terminateRequested, UCParams (as set), UCParams (of the core:
 *           lineFile applied), UCInputs, UCOutputs, core bytes; each of these five blocks as runs of its
 *           8-byte words (u32 zero words, u32 data words, the data words, ... up to its size), so that the
 *           maxima a deck does not use (lines, bodies, points, wave components) take no room
 * Any mismatch of the header with this binary is rejected with fmi2Error.
 */
#ifndef UNDERWATERCABLE_FMU_STATE_SERIALIZATION_H
#define UNDERWATERCABLE_FMU_STATE_SERIALIZATION_H

#include "instance.h"

#define UC_STATE_FORMAT_VERSION 3u  /* 3: the blocks as runs of words */

fmi2Status uc_state_get(UCInstance* inst, fmi2FMUstate* state);
fmi2Status uc_state_set(UCInstance* inst, fmi2FMUstate state);
fmi2Status uc_state_free(UCInstance* inst, fmi2FMUstate* state);

fmi2Status uc_state_serialized_size(UCInstance* inst, fmi2FMUstate state, size_t* size);
fmi2Status uc_state_serialize(UCInstance* inst, fmi2FMUstate state, fmi2Byte buffer[], size_t size);
fmi2Status uc_state_deserialize(UCInstance* inst, const fmi2Byte buffer[], size_t size, fmi2FMUstate* state);

#endif /* UNDERWATERCABLE_FMU_STATE_SERIALIZATION_H */
