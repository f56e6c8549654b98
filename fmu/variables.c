/* variables.c - the value-reference table (see variables.h). Keep it in the order of modelDescription.xml. */
#include "variables.h"

#include <stdlib.h>

#define PAR(vr, name, type, field) {vr, name, UC_TYPE_##type, UC_CAUSALITY_PARAMETER, offsetof(UCParams, field)}
#define INP(vr, name, field) {vr, name, UC_TYPE_REAL, UC_CAUSALITY_INPUT, offsetof(UCInputs, field)}
#define OUT(vr, name, field) {vr, name, UC_TYPE_REAL, UC_CAUSALITY_OUTPUT, offsetof(UCOutputs, field)}

/* One output per station k = 1..UC_NUM_STATIONS with consecutive value references from vr0. */
#define STATION(vr0, prefix, field, k) OUT((vr0) + (k)-1, prefix "[" #k "]", field[(k)-1])
#define STATIONS(vr0, prefix, field)                                                                         \
    STATION(vr0, prefix, field, 1), STATION(vr0, prefix, field, 2), STATION(vr0, prefix, field, 3),          \
        STATION(vr0, prefix, field, 4), STATION(vr0, prefix, field, 5), STATION(vr0, prefix, field, 6),      \
        STATION(vr0, prefix, field, 7), STATION(vr0, prefix, field, 8), STATION(vr0, prefix, field, 9),      \
        STATION(vr0, prefix, field, 10), STATION(vr0, prefix, field, 11), STATION(vr0, prefix, field, 12),   \
        STATION(vr0, prefix, field, 13), STATION(vr0, prefix, field, 14), STATION(vr0, prefix, field, 15),   \
        STATION(vr0, prefix, field, 16), STATION(vr0, prefix, field, 17), STATION(vr0, prefix, field, 18),   \
        STATION(vr0, prefix, field, 19), STATION(vr0, prefix, field, 20), STATION(vr0, prefix, field, 21)

#if UC_NUM_STATIONS != 21
#error "STATIONS() and modelDescription.xml are written for UC_NUM_STATIONS == 21"
#endif

static const UCVariable kVariables[] = {
    PAR(1, "length", REAL, length),
    PAR(2, "diameter", REAL, diameter),
    PAR(3, "massPerLength", REAL, massPerLength),
    PAR(4, "EA", REAL, EA),
    PAR(5, "EI", REAL, EI),
    PAR(6, "axialDamping", REAL, axialDamping),
    PAR(7, "Cdn", REAL, Cdn),
    PAR(8, "Cdt", REAL, Cdt),
    PAR(9, "Can", REAL, Can),
    PAR(10, "Cat", REAL, Cat),
    PAR(11, "waterDensity", REAL, waterDensity),
    PAR(12, "gravity", REAL, gravity),
    PAR(13, "nElements", INTEGER, nElements),
    PAR(14, "relTol", REAL, relTol),
    PAR(15, "absTol", REAL, absTol),
    PAR(16, "bottomEnd", INTEGER, bottomEnd),
    PAR(17, "topEnd", INTEGER, topEnd),
    PAR(18, "topTangent.x", REAL, topTangent[0]),
    PAR(19, "topTangent.y", REAL, topTangent[1]),
    PAR(20, "topTangent.z", REAL, topTangent[2]),
    PAR(21, "anchor.x", REAL, anchor[0]),
    PAR(22, "anchor.y", REAL, anchor[1]),
    PAR(23, "anchor.z", REAL, anchor[2]),
    PAR(24, "body.mass", REAL, bodyMass),
    PAR(25, "body.volume", REAL, bodyVolume),
    PAR(26, "body.addedMass", REAL, bodyAddedMass),
    PAR(27, "body.CdA", REAL, bodyCdA),
    PAR(28, "initMode", INTEGER, initMode),
    PAR(29, "initialDirection.x", REAL, initialDirection[0]),
    PAR(30, "initialDirection.y", REAL, initialDirection[1]),
    PAR(31, "initialDirection.z", REAL, initialDirection[2]),
    PAR(32, "enableBending", BOOLEAN, enableBending),
    PAR(33, "enableAddedMass", BOOLEAN, enableAddedMass),

    INP(101, "tow.x", tow[0]),
    INP(102, "tow.y", tow[1]),
    INP(103, "tow.z", tow[2]),
    INP(104, "tow.vx", towVelocity[0]),
    INP(105, "tow.vy", towVelocity[1]),
    INP(106, "tow.vz", towVelocity[2]),
    INP(107, "endLoad.x", endLoad[0]),
    INP(108, "endLoad.y", endLoad[1]),
    INP(109, "endLoad.z", endLoad[2]),
    INP(110, "current.x", current[0]),
    INP(111, "current.y", current[1]),

    OUT(201, "towForce.x", towForce[0]),
    OUT(202, "towForce.y", towForce[1]),
    OUT(203, "towForce.z", towForce[2]),
    OUT(204, "towTension", towTension),
    OUT(205, "endForce.x", endForce[0]),
    OUT(206, "endForce.y", endForce[1]),
    OUT(207, "endForce.z", endForce[2]),
    OUT(208, "endTension", endTension),
    OUT(209, "endPosition.x", endPosition[0]),
    OUT(210, "endPosition.y", endPosition[1]),
    OUT(211, "endPosition.z", endPosition[2]),
    OUT(212, "endVelocity.x", endVelocity[0]),
    OUT(213, "endVelocity.y", endVelocity[1]),
    OUT(214, "endVelocity.z", endVelocity[2]),
    STATIONS(301, "shape.x", shapeX),
    STATIONS(401, "shape.y", shapeY),
    STATIONS(501, "shape.z", shapeZ),
    STATIONS(601, "tension", tension),
    OUT(701, "minTension", minTension),
    OUT(702, "maxCurvature", maxCurvature),
    OUT(703, "maxBendingMoment", maxBendingMoment),
    OUT(801, "solver.nSteps", nSteps),
    OUT(802, "solver.nResidualEvals", nResidualEvals),
    OUT(803, "solver.nJacobianEvals", nJacobianEvals),
    OUT(804, "solver.nNonlinearFailures", nNonlinearFailures),
    OUT(805, "solver.nErrorTestFailures", nErrorTestFailures),

    /* Added later: appended (value references 901 on) so that existing indices and references stay. */
    INP(901, "endCouple.x", endCouple[0]),
    INP(902, "endCouple.y", endCouple[1]),
    INP(903, "endCouple.z", endCouple[2]),
    PAR(904, "enableSeabed", BOOLEAN, enableSeabed),
    PAR(905, "waterDepth", REAL, waterDepth),
    PAR(906, "seabedStiffness", REAL, seabedStiffness),
    PAR(907, "seabedDamping", REAL, seabedDamping),
    PAR(908, "seabedFriction", REAL, seabedFriction),
    PAR(909, "currentProfileRows", INTEGER, currentProfileRows),
    PAR(910, "currentProfile.depth[1]", REAL, currentProfileDepth[0]),
    PAR(911, "currentProfile.depth[2]", REAL, currentProfileDepth[1]),
    PAR(912, "currentProfile.depth[3]", REAL, currentProfileDepth[2]),
    PAR(913, "currentProfile.depth[4]", REAL, currentProfileDepth[3]),
    PAR(914, "currentProfile.depth[5]", REAL, currentProfileDepth[4]),
    PAR(915, "currentProfile.depth[6]", REAL, currentProfileDepth[5]),
    PAR(916, "currentProfile.depth[7]", REAL, currentProfileDepth[6]),
    PAR(917, "currentProfile.depth[8]", REAL, currentProfileDepth[7]),
    PAR(918, "currentProfile.depth[9]", REAL, currentProfileDepth[8]),
    PAR(919, "currentProfile.depth[10]", REAL, currentProfileDepth[9]),
    PAR(920, "currentProfile.x[1]", REAL, currentProfileX[0]),
    PAR(921, "currentProfile.x[2]", REAL, currentProfileX[1]),
    PAR(922, "currentProfile.x[3]", REAL, currentProfileX[2]),
    PAR(923, "currentProfile.x[4]", REAL, currentProfileX[3]),
    PAR(924, "currentProfile.x[5]", REAL, currentProfileX[4]),
    PAR(925, "currentProfile.x[6]", REAL, currentProfileX[5]),
    PAR(926, "currentProfile.x[7]", REAL, currentProfileX[6]),
    PAR(927, "currentProfile.x[8]", REAL, currentProfileX[7]),
    PAR(928, "currentProfile.x[9]", REAL, currentProfileX[8]),
    PAR(929, "currentProfile.x[10]", REAL, currentProfileX[9]),
    PAR(930, "currentProfile.y[1]", REAL, currentProfileY[0]),
    PAR(931, "currentProfile.y[2]", REAL, currentProfileY[1]),
    PAR(932, "currentProfile.y[3]", REAL, currentProfileY[2]),
    PAR(933, "currentProfile.y[4]", REAL, currentProfileY[3]),
    PAR(934, "currentProfile.y[5]", REAL, currentProfileY[4]),
    PAR(935, "currentProfile.y[6]", REAL, currentProfileY[5]),
    PAR(936, "currentProfile.y[7]", REAL, currentProfileY[6]),
    PAR(937, "currentProfile.y[8]", REAL, currentProfileY[7]),
    PAR(938, "currentProfile.y[9]", REAL, currentProfileY[8]),
    PAR(939, "currentProfile.y[10]", REAL, currentProfileY[9]),
    INP(940, "end.x", end[0]),
    INP(941, "end.y", end[1]),
    INP(942, "end.z", end[2]),
    INP(943, "end.vx", endVelocity[0]),
    INP(944, "end.vy", endVelocity[1]),
    INP(945, "end.vz", endVelocity[2]),
    OUT(946, "touchdownArcLength", touchdownArcLength),
    OUT(947, "minSeabedClearance", minSeabedClearance),
    PAR(948, "enableTorsion", BOOLEAN, enableTorsion),
    PAR(949, "GJ", REAL, GJ),
    PAR(950, "torqueMode", INTEGER, torqueMode),
    INP(951, "torque", torque),
    INP(952, "twist", twist),
    OUT(953, "cableTorque", cableTorque),
    OUT(954, "twist[1]", twistAngle[0]),
    OUT(955, "twist[2]", twistAngle[1]),
    OUT(956, "twist[3]", twistAngle[2]),
    OUT(957, "twist[4]", twistAngle[3]),
    OUT(958, "twist[5]", twistAngle[4]),
    OUT(959, "twist[6]", twistAngle[5]),
    OUT(960, "twist[7]", twistAngle[6]),
    OUT(961, "twist[8]", twistAngle[7]),
    OUT(962, "twist[9]", twistAngle[8]),
    OUT(963, "twist[10]", twistAngle[9]),
    OUT(964, "twist[11]", twistAngle[10]),
    OUT(965, "twist[12]", twistAngle[11]),
    OUT(966, "twist[13]", twistAngle[12]),
    OUT(967, "twist[14]", twistAngle[13]),
    OUT(968, "twist[15]", twistAngle[14]),
    OUT(969, "twist[16]", twistAngle[15]),
    OUT(970, "twist[17]", twistAngle[16]),
    OUT(971, "twist[18]", twistAngle[17]),
    OUT(972, "twist[19]", twistAngle[18]),
    OUT(973, "twist[20]", twistAngle[19]),
    OUT(974, "twist[21]", twistAngle[20]),
    OUT(975, "towMoment.x", towMoment[0]),
    OUT(976, "towMoment.y", towMoment[1]),
    OUT(977, "towMoment.z", towMoment[2]),
    OUT(978, "endMoment.x", endMoment[0]),
    OUT(979, "endMoment.y", endMoment[1]),
    OUT(980, "endMoment.z", endMoment[2]),
    PAR(981, "enableCompression", BOOLEAN, enableCompression),
    OUT(982, "curvature[1]", curvature[0]),
    OUT(983, "curvature[2]", curvature[1]),
    OUT(984, "curvature[3]", curvature[2]),
    OUT(985, "curvature[4]", curvature[3]),
    OUT(986, "curvature[5]", curvature[4]),
    OUT(987, "curvature[6]", curvature[5]),
    OUT(988, "curvature[7]", curvature[6]),
    OUT(989, "curvature[8]", curvature[7]),
    OUT(990, "curvature[9]", curvature[8]),
    OUT(991, "curvature[10]", curvature[9]),
    OUT(992, "curvature[11]", curvature[10]),
    OUT(993, "curvature[12]", curvature[11]),
    OUT(994, "curvature[13]", curvature[12]),
    OUT(995, "curvature[14]", curvature[13]),
    OUT(996, "curvature[15]", curvature[14]),
    OUT(997, "curvature[16]", curvature[15]),
    OUT(998, "curvature[17]", curvature[16]),
    OUT(999, "curvature[18]", curvature[17]),
    OUT(1000, "curvature[19]", curvature[18]),
    OUT(1001, "curvature[20]", curvature[19]),
    OUT(1002, "curvature[21]", curvature[20]),
};

#define N_VARIABLES (sizeof(kVariables) / sizeof(kVariables[0]))

const UCVariable* uc_variables(size_t* count) {
    *count = N_VARIABLES;
    return kVariables;
}

static int compare_vr(const void* key, const void* element) {
    unsigned int vr = *(const unsigned int*)key;
    unsigned int other = ((const UCVariable*)element)->vr;
    return (vr > other) - (vr < other);
}

/* Value references are unique over all types (a stricter rule than FMI's per-type uniqueness). */
const UCVariable* uc_variable_find(unsigned int vr, UCVarType type) {
    const UCVariable* v = bsearch(&vr, kVariables, N_VARIABLES, sizeof(kVariables[0]), compare_vr);
    return (v != NULL && v->type == type) ? v : NULL;
}

void* uc_variable_address(const UCVariable* v, UCParams* p, UCInputs* in, UCOutputs* out) {
    return (void*)uc_variable_address_const(v, p, in, out);
}

const void* uc_variable_address_const(const UCVariable* v, const UCParams* p, const UCInputs* in,
                                      const UCOutputs* out) {
    switch (v->causality) {
        case UC_CAUSALITY_PARAMETER: return (const char*)p + v->offset;
        case UC_CAUSALITY_INPUT: return (const char*)in + v->offset;
        default: return (const char*)out + v->offset;
    }
}

const char* uc_type_name(UCVarType t) {
    switch (t) {
        case UC_TYPE_REAL: return "Real";
        case UC_TYPE_INTEGER: return "Integer";
        default: return "Boolean";
    }
}

const char* uc_causality_name(UCCausality c) {
    switch (c) {
        case UC_CAUSALITY_PARAMETER: return "parameter";
        case UC_CAUSALITY_INPUT: return "input";
        default: return "output";
    }
}

const char* uc_variability_name(UCCausality c) { return c == UC_CAUSALITY_PARAMETER ? "fixed" : "continuous"; }
