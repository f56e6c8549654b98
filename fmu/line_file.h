/*
 * line_file.h - the parameter lineFile: the path of a MoorDyn v2 input file. A relative path is looked up
 * in the FMU's resources directory (fmuResourceLocation of fmi2Instantiate, a file: URI) first, then in
 * the working directory. The adapter reads the file; the core (uc_line_file_apply) reads its text.
 */
#ifndef UNDERWATERCABLE_FMU_LINE_FILE_H
#define UNDERWATERCABLE_FMU_LINE_FILE_H

#include <stddef.h>

#include "instance.h"

/* Largest line file read (a deck of a few lines is a few kB). */
#define UC_LINE_FILE_MAX_BYTES ((size_t)16 << 20)

/* Reads inst->params.lineFile and writes its line into *p (the parameters the core is created with).
 * Logs the file used and the reader's notes (logEvents); an unreadable file (naming every path tried) or
 * a refused deck (naming the file and its line) is fmi2Error, logged naming `function`. */
fmi2Status uc_line_file_load(UCInstance* inst, UCParams* p, const char* function);

/* A deck that is a mooring system (p->mooringSystem set by uc_line_file_load): reads lineFile again and
 * creates the system with the parameters *p for its lines (uc_create_system). Errors as above. */
fmi2Status uc_line_file_create_system(UCInstance* inst, const UCParams* p, UCCable** cable, const char* function);

/* Reads p->wavesFile (looked up as lineFile) and writes its wave components into *p (waves.mode 3;
 * docs/waves.md, "Given components"). Logs the file used (logEvents); an unreadable file (naming every path
 * tried) or a refused row (naming the file and its line) is fmi2Error, logged naming `function`. */
fmi2Status uc_wave_file_load(UCInstance* inst, UCParams* p, const char* function);

/* currents.mode 2 or 5 (docs/waves.md, "A current given as data"): reads p->currentsFile (looked up as lineFile;
 * for a deck's Currents 2 or 5 the path the deck's companion was read from) and gives its data to the core
 * (uc_set_current_text); nothing with currents.mode 0. Logs the file used (logEvents); an unreadable file
 * (naming every path tried: a state restored where the file is gone) or refused data (naming the file and
 * its line) is fmi2Error, logged naming `function`. */
fmi2Status uc_current_file_load(UCInstance* inst, const UCParams* p, UCCable* cable, const char* function);

/* seabed.file (docs/model.md, "A seabed given as a grid"): reads p->seabedFile (looked up as lineFile; for a
 * deck's SeafloorFile that is not a plane the path the deck's companion was read from) and gives its grid to
 * the core (uc_set_seabed_text); nothing where it is empty. Logs the file used (logEvents); an unreadable
 * file (naming every path tried) or a refused grid (naming the file and its line) is fmi2Error, logged
 * naming `function`. */
fmi2Status uc_seabed_file_load(UCInstance* inst, const UCParams* p, UCCable* cable, const char* function);

#endif /* UNDERWATERCABLE_FMU_LINE_FILE_H */
