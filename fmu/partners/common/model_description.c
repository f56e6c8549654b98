/*
 * model_description.c - build tool: writes the modelDescription.xml of a partner FMU from the same
 * variable table the FMU's adapter uses (kPartnerModel), so that the XML and the binary cannot drift.
 *
 *   <identifier>_model_description OUTPUT_FILE GUID VERSION
 *
 * Value references are the table positions (1-based). Parameters are fixed with min/max (Strings start
 * empty), inputs continuous with start 0, outputs continuous and calculated; an output without direct feedthrough
 * gets dependencies="" (it depends on the states only), one with feedthrough no dependencies attribute
 * (it may depend on every input).
 */
#include <stdio.h>
#include <string.h>

#include "partner.h"

typedef struct Unit {
    const char* name;
    int kg, m, s, rad;
    const char* displayName; /* NULL: none */
    double displayFactor;
} Unit;

static const Unit kUnits[] = {
    {"m", 0, 1, 0, 0, NULL, 0.0},
    {"m/s", 0, 1, -1, 0, "kn", 1.9438444924406048},
    {"m/s2", 0, 1, -2, 0, NULL, 0.0},
    {"m2", 0, 2, 0, 0, NULL, 0.0},
    {"m3", 0, 3, 0, 0, NULL, 0.0},
    {"kg", 1, 0, 0, 0, NULL, 0.0},
    {"kg/m3", 1, -3, 0, 0, NULL, 0.0},
    {"kg.m2", 1, 2, 0, 0, NULL, 0.0},
    {"N", 1, 1, -2, 0, "kN", 0.001},
    {"N.m", 1, 2, -2, 0, "kN.m", 0.001},
    {"N.s/m", 1, 0, -1, 0, NULL, 0.0},
    {"N.s2/m2", 1, -1, 0, 0, NULL, 0.0},
    {"N.m.s", 1, 2, -1, 0, NULL, 0.0},
    {"N.m.s2", 1, 2, 0, 0, NULL, 0.0},
    {"s", 0, 0, 1, 0, NULL, 0.0},
    {"1/s", 0, 0, -1, 0, NULL, 0.0},
    {"rad", 0, 0, 0, 1, "deg", 57.29577951308232},
    {"rad/s", 0, 0, -1, 1, "deg/s", 57.29577951308232},
    {"rad/s2", 0, 0, -2, 1, "deg/s2", 57.29577951308232},
};
#define N_UNITS (sizeof kUnits / sizeof kUnits[0])

static const char* const kLogCategories[][2] = {
    {"logEvents", "Life-cycle events: instantiation, initialization, state save/restore"},
    {"logSolver", "Integrator messages (none at present)"},
    {"logStatusWarning", "Messages of calls that return fmi2Warning"},
    {"logStatusDiscard", "Messages of calls that return fmi2Discard"},
    {"logStatusError", "Messages of calls that return fmi2Error (always logged)"},
    {"logStatusFatal", "Messages of calls that return fmi2Fatal (always logged)"},
    {"logAll", "All of the above"},
};

static void put_escaped(FILE* f, const char* text) {
    for (const char* c = text; *c != '\0'; ++c) {
        switch (*c) {
            case '&': fputs("&amp;", f); break;
            case '<': fputs("&lt;", f); break;
            case '>': fputs("&gt;", f); break;
            case '"': fputs("&quot;", f); break;
            default: fputc(*c, f);
        }
    }
}

static const Unit* find_unit(const char* name) {
    for (size_t i = 0; i < N_UNITS; ++i)
        if (strcmp(kUnits[i].name, name) == 0) return &kUnits[i];
    return NULL;
}

static int unit_used(const PMModel* m, const char* name) {
    for (size_t i = 0; i < m->nVariables; ++i)
        if (m->variables[i].unit != NULL && strcmp(m->variables[i].unit, name) == 0) return 1;
    return 0;
}

static void write_units(FILE* f, const PMModel* m) {
    fputs("  <UnitDefinitions>\n", f);
    for (size_t i = 0; i < N_UNITS; ++i) {
        const Unit* u = &kUnits[i];
        if (!unit_used(m, u->name)) continue;
        fprintf(f, "    <Unit name=\"%s\">\n      <BaseUnit", u->name);
        if (u->kg) fprintf(f, " kg=\"%d\"", u->kg);
        if (u->m) fprintf(f, " m=\"%d\"", u->m);
        if (u->s) fprintf(f, " s=\"%d\"", u->s);
        if (u->rad) fprintf(f, " rad=\"%d\"", u->rad);
        fputs("/>\n", f);
        if (u->displayName) fprintf(f, "      <DisplayUnit name=\"%s\" factor=\"%.17g\"/>\n", u->displayName, u->displayFactor);
        fputs("    </Unit>\n", f);
    }
    fputs("  </UnitDefinitions>\n", f);
}

static void write_variable(FILE* f, const PMVariable* v, size_t vr) {
    static const char* const kCausality[] = {"parameter", "input", "output"};
    fprintf(f, "    <!-- %zu --><ScalarVariable name=\"%s\" valueReference=\"%zu\" description=\"", vr, v->name, vr);
    put_escaped(f, v->description);
    fprintf(f, "\" causality=\"%s\"", kCausality[v->causality]);
    if (v->causality == PM_PARAMETER) {
        fputs(" variability=\"fixed\" initial=\"exact\">\n", f);
    } else if (v->causality == PM_INPUT) {
        fputs(" variability=\"continuous\">\n", f);
    } else {
        fputs(" variability=\"continuous\" initial=\"calculated\">\n", f);
    }
    if (v->type == PM_STRING) {
        fputs("      <String start=\"\"/>\n", f);
    } else if (v->type == PM_BOOLEAN) {
        fprintf(f, "      <Boolean start=\"%s\"/>\n", v->start != 0.0 ? "true" : "false");
    } else if (v->type == PM_INTEGER) {
        fprintf(f, "      <Integer min=\"%.0f\" max=\"%.0f\" start=\"%.0f\"/>\n", v->min, v->max, v->start);
    } else {
        fputs("      <Real", f);
        if (v->unit) fprintf(f, " unit=\"%s\"", v->unit);
        if (v->causality == PM_PARAMETER) fprintf(f, " min=\"%.17g\" max=\"%.17g\"", v->min, v->max);
        if (v->causality != PM_OUTPUT) fprintf(f, " start=\"%.17g\"", v->start);
        fputs("/>\n", f);
    }
    fputs("    </ScalarVariable>\n", f);
}

static void write_structure(FILE* f, const PMModel* m) {
    fputs("  <ModelStructure>\n    <Outputs>\n", f);
    for (size_t i = 0; i < m->nVariables; ++i) {
        const PMVariable* v = &m->variables[i];
        if (v->causality != PM_OUTPUT) continue;
        fprintf(f, "      <Unknown index=\"%zu\"%s/>\n", i + 1, v->feedthrough ? "" : " dependencies=\"\"");
    }
    fputs("    </Outputs>\n    <InitialUnknowns>\n", f);
    for (size_t i = 0; i < m->nVariables; ++i)
        if (m->variables[i].causality == PM_OUTPUT) fprintf(f, "      <Unknown index=\"%zu\"/>\n", i + 1);
    fputs("    </InitialUnknowns>\n  </ModelStructure>\n", f);
}

static int check_table(const PMModel* m) {
    for (size_t i = 0; i < m->nVariables; ++i) {
        const PMVariable* v = &m->variables[i];
        if (v->unit != NULL && find_unit(v->unit) == NULL) {
            fprintf(stderr, "%s: unit \"%s\" of %s is not in the unit table\n", m->identifier, v->unit, v->name);
            return 1;
        }
        for (size_t j = 0; j < i; ++j)
            if (strcmp(m->variables[j].name, v->name) == 0) {
                fprintf(stderr, "%s: variable %s declared twice\n", m->identifier, v->name);
                return 1;
            }
        if (v->type == PM_INTEGER && (v->causality != PM_PARAMETER || v->min != (int)v->min || v->max != (int)v->max ||
                                      v->start != (int)v->start)) {
            fprintf(stderr, "%s: Integer %s must be a parameter with integer start, min and max\n", m->identifier,
                    v->name);
            return 1;
        }
        if (v->type == PM_STRING && v->causality != PM_PARAMETER) {
            fprintf(stderr, "%s: String %s must be a parameter\n", m->identifier, v->name);
            return 1;
        }
        if (v->causality == PM_PARAMETER && !(v->start >= v->min && v->start <= v->max)) {
            fprintf(stderr, "%s: start of %s outside [min, max]\n", m->identifier, v->name);
            return 1;
        }
    }
    return 0;
}

int main(int argc, char** argv) {
    const PMModel* m = &kPartnerModel;
    if (argc != 4) {
        fprintf(stderr, "usage: %s OUTPUT_FILE GUID VERSION\n", argv[0]);
        return 2;
    }
    if (check_table(m) != 0) return 1;
    FILE* f = fopen(argv[1], "w");
    if (f == NULL) {
        perror(argv[1]);
        return 1;
    }
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    fprintf(f, "<!-- Generated by fmu/partners/common/model_description.c from the variable table of %s. -->\n",
            m->identifier);
    fprintf(f, "<fmiModelDescription fmiVersion=\"2.0\" modelName=\"%s\" guid=\"%s\" description=\"", m->identifier,
            argv[2]);
    put_escaped(f, m->description);
    fprintf(f, "\" author=\"UnderwaterCable developers\" version=\"%s\" generationTool=\"UnderwaterCable "
               "partner model description writer\" variableNamingConvention=\"structured\" "
               "numberOfEventIndicators=\"0\">\n", argv[3]);
    fprintf(f, "  <CoSimulation modelIdentifier=\"%s\" needsExecutionTool=\"false\" "
               "canHandleVariableCommunicationStepSize=\"true\" canInterpolateInputs=\"false\" "
               "maxOutputDerivativeOrder=\"0\" canRunAsynchronuously=\"false\" "
               "canBeInstantiatedOnlyOncePerProcess=\"false\" canNotUseMemoryManagementFunctions=\"true\" "
               "canGetAndSetFMUstate=\"true\" canSerializeFMUstate=\"true\" "
               "providesDirectionalDerivative=\"false\"/>\n", m->identifier);
    write_units(f, m);
    fputs("  <LogCategories>\n", f);
    for (size_t i = 0; i < sizeof kLogCategories / sizeof kLogCategories[0]; ++i)
        fprintf(f, "    <Category name=\"%s\" description=\"%s\"/>\n", kLogCategories[i][0], kLogCategories[i][1]);
    fputs("  </LogCategories>\n", f);
    fputs("  <DefaultExperiment startTime=\"0\" stopTime=\"660\" stepSize=\"0.5\"/>\n", f);
    fputs("  <ModelVariables>\n", f);
    for (size_t i = 0; i < m->nVariables; ++i) write_variable(f, &m->variables[i], i + 1);
    fputs("  </ModelVariables>\n", f);
    write_structure(f, m);
    fputs("</fmiModelDescription>\n", f);
    return fclose(f) == 0 ? 0 : 1;
}
