// manoeuvre_driver.cpp - flies a tow manoeuvre from a table through the FMI API, for valgrind memcheck
// (scripts/memcheck). The table (written by scripts/memcheck from studies.cases.manoeuvre) has one row per
// communication point: t tow.x tow.y tow.z tow.vx tow.vy tow.vz ax ay az (whitespace separated).
// Besides stepping, the run saves, serializes, deserializes and restores an FMU state halfway, resets
// and re-initializes a second instance, so those code paths are checked as well.
//
//   uc_manoeuvre_driver table.txt
// Exit code 0 when every call returned fmi2OK; prints the final tow tension.
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "fmu_harness.h"

namespace {

struct Row {
    double t, p[3], v[3], a[3];
};

std::vector<Row> read_table(const char* path) {
    std::vector<Row> rows;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream s(line);
        Row r{};
        s >> r.t >> r.p[0] >> r.p[1] >> r.p[2] >> r.v[0] >> r.v[1] >> r.v[2] >> r.a[0] >> r.a[1] >> r.a[2];
        if (s) rows.push_back(r);
    }
    return rows;
}

int fail(Instance& inst, const char* what) {
    std::fprintf(stderr, "manoeuvre_driver: %s failed\n%s", what, inst.log.all().c_str());
    return 1;
}

int set_row(Instance& inst, const Row& r) {
    static const char* names[] = {"tow.x", "tow.y", "tow.z", "tow.vx", "tow.vy", "tow.vz"};
    for (int k = 0; k < 3; ++k) {
        if (inst.setReal(names[k], r.p[k]) != fmi2OK || inst.setReal(names[3 + k], r.v[k]) != fmi2OK) return 1;
    }
    const fmi2ValueReference vrs[3] = {vr_of("tow.vx"), vr_of("tow.vy"), vr_of("tow.vz")};
    const fmi2Integer order[3] = {1, 1, 1};
    return fmi().SetRealInputDerivatives(inst.c, vrs, 3, order, r.a) == fmi2OK ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: uc_manoeuvre_driver table.txt\n");
        return 2;
    }
    const std::vector<Row> rows = read_table(argv[1]);
    if (rows.size() < 2) {
        std::fprintf(stderr, "manoeuvre_driver: no rows in %s\n", argv[1]);
        return 2;
    }
    Instance inst("memcheck", false);
    if (inst.c == nullptr) return 1;
    if (set_row(inst, rows[0]) != 0) return fail(inst, "inputs at t0");
    if (inst.initialize(rows.front().t, rows.back().t) != fmi2OK) return fail(inst, "initialization");
    fmi2FMUstate half = nullptr;
    std::vector<char> bytes;
    const size_t middle = rows.size() / 2;
    for (size_t k = 0; k + 1 < rows.size(); ++k) {
        if (set_row(inst, rows[k]) != 0) return fail(inst, "inputs");
        if (fmi().DoStep(inst.c, rows[k].t, rows[k + 1].t - rows[k].t, fmi2True) != fmi2OK) return fail(inst, "doStep");
        inst.outputs();
        if (k == middle) {
            size_t size = 0;
            if (fmi().GetFMUstate(inst.c, &half) != fmi2OK || fmi().SerializedFMUstateSize(inst.c, half, &size) != fmi2OK)
                return fail(inst, "state");
            bytes.resize(size);
            if (fmi().SerializeFMUstate(inst.c, half, bytes.data(), size) != fmi2OK) return fail(inst, "serialize");
        }
    }
    const double tension = inst.getReal("towTension");
    // Restore the halfway state from its serialized bytes and fly the second half again.
    fmi2FMUstate restored = nullptr;
    if (fmi().DeSerializeFMUstate(inst.c, bytes.data(), bytes.size(), &restored) != fmi2OK ||
        fmi().SetFMUstate(inst.c, restored) != fmi2OK)
        return fail(inst, "restore");
    for (size_t k = middle + 1; k + 1 < rows.size(); ++k) {
        if (set_row(inst, rows[k]) != 0) return fail(inst, "inputs (rerun)");
        if (fmi().DoStep(inst.c, rows[k].t, rows[k + 1].t - rows[k].t, fmi2True) != fmi2OK) return fail(inst, "doStep (rerun)");
    }
    const double again = inst.getReal("towTension");
    if (fmi().FreeFMUstate(inst.c, &half) != fmi2OK || fmi().FreeFMUstate(inst.c, &restored) != fmi2OK)
        return fail(inst, "free states");
    if (fmi().Terminate(inst.c) != fmi2OK) return fail(inst, "terminate");
    if (fmi().Reset(inst.c) != fmi2OK || inst.initialize(rows.front().t, rows.back().t) != fmi2OK)
        return fail(inst, "reset and initialize");
    std::printf("manoeuvre_driver: %zu steps to t = %g s, towTension %.6f N (rerun from the serialized halfway "
                "state: %.6f N)\n", rows.size() - 1, rows.back().t, tension, again);
    return tension == again ? 0 : 1;
}
