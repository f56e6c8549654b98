// fuzz_fmi.cpp - seeded random-sequence driver of the FMI API.
//
// Loads UnderwaterCable.so like the adapter tests (dlopen RTLD_NOW) and calls the fmi2 functions in
// random order on up to three instances with random and hostile arguments: NaN, +-inf, huge, negative
// and denormal values, NULL pointers, unknown and wrong-type value references, random step sizes and
// communication points, FMU states saved, restored, serialized, corrupted and deserialized. The
// arguments are "mostly plausible" so that the sequences get deep into the state machine.
//
// Checked on every call (an invariant violation is printed with the call and counted; exit code 1):
//   - the status is OK, Warning, Discard or Error (never Fatal, never garbage);
//   - every non-OK status is logged;
//   - after an fmi2Error the instance refuses fmi2DoStep until reset or a state restore;
//   - outputs read after a successful fmi2DoStep are finite.
// Crashes, leaks and undefined behaviour are the sanitizers' job (build with -DUC_SANITIZE=ON, see
// scripts/fuzz_fmi). --trace prints each call before it is made, so the last line before a crash is
// the culprit; the sequence depends only on --seed (and the FMU's return values).
//
// --decks: deck mode. Most instances are given a lineFile, a private copy of one of the project's decks
// (mooring systems with coupled bodies and points, free points and free bodies, OC4; single lines), some
// of them with one number of a data row changed; the body[k].* and point[k].* inputs get plausible
// poses and velocities, and the fuzzer also edits an instance's deck copy between calls (a state saved
// before is then refused by fmi2SetFMUstate where the edit changed a value the system was built from;
// the run counts those refusals).
//
// --fmi3: the FMI 3.0 variant of the FMU instead (tests/fmu/fuzz_fmi3.cpp, which says what it checks).
//
//   uc_fmi_fuzz [--calls N] [--seed S] [--seconds T] [--trace] [--decks [FILE,FILE,...]] [--fmi3 [--regressions]]
#include <unistd.h>

#include "fuzz_common.h"

using namespace uc_fuzz;

int run_fmi3_fuzz(const Options& options);  // fuzz_fmi3.cpp

namespace {

struct Slot {
    fmi2Component c = nullptr;
    LogCapture log;
    double time = 0.0;            // the FMU's time as far as the driver knows
    bool inError = false;         // the last call returned fmi2Error
    int phase = 0;                // 0 instantiated, 1 initialization mode, 2 stepping, 3 other (terminated, error)
    bool steppedOk = false;       // the last call was a successful fmi2DoStep
    std::vector<fmi2FMUstate> states;
    // deck mode: the instance's private deck file, its text now, and per state the text it was saved with
    std::string deckPath, deckText;
    std::vector<std::string> stateDecks;
};

class Fuzzer : public FuzzBase {
public:
    explicit Fuzzer(const Options& o) : FuzzBase(o) {
        size_t n = 0;
        const UCVariable* table = uc_variables(&n);
        vars_.assign(table, table + n);
        for (const UCVariable& v : vars_) {
            if (v.causality == UC_CAUSALITY_OUTPUT) outputs_.push_back(v.vr);
            if (std::strcmp(v.name, "lineFile") == 0) lineFileVr_ = v.vr;
            if (v.causality == UC_CAUSALITY_INPUT) inputs_.push_back(&v - vars_.data());
        }
        for (int k = 0; k < 3; ++k) {
            slots_[k].deckPath = "/tmp/uc_fmi_fuzz_" + std::to_string(getpid()) + "_" + std::to_string(k) + ".dat";
        }
    }
    ~Fuzzer() {
        for (Slot& s : slots_) std::remove(s.deckPath.c_str());
    }

private:
    void free_all() override {
        for (Slot& s : slots_) free_slot(s);
    }

    void print_extra() override {
        if (!opt_.decks.empty()) {
            std::printf("decks: %lld instances given a deck (%lld of them edited), %lld deck edits between calls, "
                        "%lld restores of a state whose deck was edited since refused, %lld accepted (restored into the "
                        "instance still built from the deck it was saved with, a single line's state, which keeps its "
                        "line, a state without a core, or an edit that changed no value)\n",
                        deckInstances_, deckMutated_, deckEdits_, editedRefused_, editedRestored_);
        }
    }

    const UCVariable& any_variable() { return vars_[integer(0, (int)vars_.size() - 1)]; }

    fmi2ValueReference vr_for(UCVarType type, const UCVariable** chosen) {
        *chosen = nullptr;
        if (chance(0.08)) return chance(0.5) ? (fmi2ValueReference)integer(0, 5000) : 0xFFFFFFFFu;
        for (int tries = 0; tries < 20; ++tries) {
            // deck mode: mostly the inputs (the deck, not random parameters, makes the system)
            const bool input = !opt_.decks.empty() && !inputs_.empty() && chance(0.8);
            const UCVariable& v = input ? vars_[inputs_[integer(0, (int)inputs_.size() - 1)]] : any_variable();
            if (v.type == type || chance(0.05)) {
                *chosen = &v;
                return v.vr;
            }
        }
        return 123456;
    }

    // ---- deck mode -----------------------------------------------------------------------------------
    void write_deck(Slot& s, const std::string& text) {
        std::ofstream out(s.deckPath, std::ios::binary | std::ios::trunc);
        out << text;
        s.deckText = text;
    }

    // Gives a new instance a deck (most of the time): a private copy, maybe with one number changed.
    void give_deck(Slot& s) {
        if (opt_.decks.empty() || s.c == nullptr || !chance(0.9)) return;
        const std::string& text = deckTexts_[integer(0, (int)deckTexts_.size() - 1)];
        const bool mutate = chance(0.25);
        write_deck(s, mutate ? mutated_deck(text) : text);
        ++deckInstances_;
        if (mutate) ++deckMutated_;
        trace("fmi2SetString(lineFile " + s.deckPath + ")");
        const fmi2ValueReference vr = lineFileVr_;
        const fmi2String value = s.deckPath.c_str();
        after(s, "fmi2SetString", fmi().SetString(s.c, &vr, 1, &value));
    }

    // ---- bookkeeping ---------------------------------------------------------------------------------
    Slot& slot() { return slots_[integer(0, 2)]; }

    void violation(const char* what, const Slot& s, const std::string& call) { FuzzBase::violation(what, s.log, call); }

    // Applies the checks that hold for every call on an instance.
    void after(Slot& s, const char* function, fmi2Status status) {
        const int k = tally(function, (int)status);
        if (k == 4) violation("status is not OK/Warning/Discard/Error", s, last_);
        if (status != fmi2OK && s.c != nullptr && s.log.lines.empty()) {
            violation("a non-OK status without a log message", s, last_);
        }
        s.log.lines.clear();
        s.steppedOk = false;
        if (status == fmi2Error) s.inError = true;
        phase_after(s, function, status);
    }

    // A refused fmi2SetFMUstate or fmi2DeSerializeFMUstate changes nothing, the machine state included: the
    // instance is where it was (one whose core failed part-way is in the error state, which the next call
    // finds out, since no check here expects an fmi2OK).
    void after_refusable(Slot& s, const char* function, fmi2Status status) {
        const bool wasError = s.inError;
        const int phase = s.phase;
        after(s, function, status);
        if (status == fmi2Error) {
            s.inError = wasError;
            s.phase = phase;
        }
    }

    void free_states(Slot& s) {
        for (fmi2FMUstate& st : s.states) {
            if (st != nullptr) fmi().FreeFMUstate(s.c, &st);
        }
        s.states.clear();
        s.stateDecks.clear();
    }

    void free_slot(Slot& s) {
        if (s.c == nullptr) return;
        trace("fmi2FreeInstance");
        free_states(s);
        fmi().FreeInstance(s.c);
        ++calls_;
        ++perFunction_["fmi2FreeInstance"];
        s.c = nullptr;
    }

    void instantiate(Slot& s) {
        free_slot(s);
        s.log.lines.clear();
        const fmi2CallbackFunctions callbacks = {capture_logger, nullptr, nullptr, nullptr, &s.log};
        const bool bad = chance(0.05);
        const char* guid = bad && chance(0.5) ? "{wrong}" : fmu_guid();
        const fmi2Type type = bad && chance(0.5) ? fmi2ModelExchange : fmi2CoSimulation;
        trace("fmi2Instantiate");
        s.c = fmi().Instantiate("fuzz %s #1#", type, guid, chance(0.5) ? "file:///tmp/x%20y" : nullptr, &callbacks,
                                fmi2False, chance(0.5) ? fmi2True : fmi2False);
        ++calls_;
        ++perFunction_["fmi2Instantiate"];
        if (!bad && s.c == nullptr) violation("fmi2Instantiate failed with valid arguments", s, last_);
        if (bad && type != fmi2CoSimulation && s.c != nullptr) violation("fmi2Instantiate accepted ME", s, last_);
        s.log.lines.clear();
        s.time = 0.0;
        s.inError = false;
        s.steppedOk = false;
        s.deckText.clear();
        give_deck(s);
    }

    // A call that moves the instance along the normal life cycle (so that random sequences also reach
    // long runs): setup and initialization, steps at the right time, reset after an error. False if
    // nothing applies.
    bool progress(Slot& s) {
        if (s.inError || s.phase == 3) {
            if (!chance(0.3)) return false;
            trace("fmi2Reset (progress)");
            const fmi2Status st = fmi().Reset(s.c);
            after(s, "fmi2Reset", st);
            if (st == fmi2OK) {
                s.inError = false;
                s.time = 0.0;
                s.phase = 0;
            }
            return true;
        }
        if (s.phase == 0) {
            trace("fmi2SetupExperiment (progress)");
            const fmi2Status st = fmi().SetupExperiment(s.c, fmi2False, 0.0, 0.0, fmi2False, 0.0);
            after(s, "fmi2SetupExperiment", st);
            if (st != fmi2OK) return true;
            s.time = 0.0;
            trace("fmi2EnterInitializationMode (progress)");
            const fmi2Status en = fmi().EnterInitializationMode(s.c);
            after(s, "fmi2EnterInitializationMode", en);
            if (en == fmi2OK) s.phase = 1;
            return true;
        }
        if (s.phase == 1) {
            trace("fmi2ExitInitializationMode (progress)");
            const fmi2Status st = fmi().ExitInitializationMode(s.c);
            after(s, "fmi2ExitInitializationMode", st);
            if (st == fmi2OK) s.phase = 2;
            return true;
        }
        const double h = chance(0.8) ? 0.5 : std::pow(10.0, uniform(-3.0, 0.7));
        char buf[128];
        std::snprintf(buf, sizeof buf, "fmi2DoStep(tc %.17g, h %.17g) (progress)", s.time, h);
        trace(buf);
        const fmi2Status st = fmi().DoStep(s.c, s.time, h, fmi2True);
        const bool ok = st == fmi2OK;
        if (ok) {
            double t = 0.0;
            if (fmi().GetRealStatus(s.c, fmi2LastSuccessfulTime, &t) == fmi2OK) s.time = t;
            ++okSteps_;
        }
        after(s, "fmi2DoStep", st);
        s.steppedOk = ok;
        return true;
    }

    // Machine phase after a successful call that changes it (the random actions below).
    void phase_after(Slot& s, const char* function, fmi2Status st) {
        if (st == fmi2Error) {
            s.phase = 3;
            return;
        }
        if (st != fmi2OK) return;
        const std::string f = function;
        if (f == "fmi2EnterInitializationMode") s.phase = 1;
        if (f == "fmi2ExitInitializationMode") s.phase = 2;
        if (f == "fmi2Terminate") s.phase = 3;
        if (f == "fmi2Reset") s.phase = 0;
    }

    // ---- one random call -----------------------------------------------------------------------------
    void one_call() override {
        Slot& s = slot();
        if (s.c == nullptr || chance(0.002)) {
            instantiate(s);
            return;
        }
        char buf[256];
        if (chance(0.5) && progress(s)) return;
        if (!s.deckText.empty() && chance(0.01)) {  // deck mode: the instance's deck file edited
            write_deck(s, mutated_deck(s.deckText));
            ++deckEdits_;
            return;
        }
        const int action = integer(0, 99);
        if (action < 4) {  // setup experiment
            const double start = chance(0.9) ? uniform(0.0, 10.0) : hostile_double();
            const double stop = chance(0.8) ? start + uniform(0.0, 1e4) : hostile_double();
            const fmi2Boolean stopDefined = chance(0.7);
            std::snprintf(buf, sizeof buf, "fmi2SetupExperiment(start %g, stop %g defined %d)", start, stop,
                          stopDefined);
            trace(buf);
            const fmi2Status st = fmi().SetupExperiment(s.c, chance(0.5), uniform(-1, 1), start, stopDefined, stop);
            if (st == fmi2OK) s.time = start;
            after(s, "fmi2SetupExperiment", st);
        } else if (action < 8) {
            trace("fmi2EnterInitializationMode");
            after(s, "fmi2EnterInitializationMode", fmi().EnterInitializationMode(s.c));
        } else if (action < 12) {
            trace("fmi2ExitInitializationMode");
            after(s, "fmi2ExitInitializationMode", fmi().ExitInitializationMode(s.c));
        } else if (action < 32) {  // set values, one to four at a time
            const int n = integer(1, 4);
            const int typeChoice = integer(0, 9);
            const UCVarType type = typeChoice < 7 ? UC_TYPE_REAL : typeChoice < 9 ? UC_TYPE_INTEGER : UC_TYPE_BOOLEAN;
            std::vector<fmi2ValueReference> vrs(n);
            std::vector<double> reals(n);
            std::vector<fmi2Integer> ints(n);
            std::string call = std::string("fmi2Set") + uc_type_name(type) + "(";
            for (int k = 0; k < n; ++k) {
                const UCVariable* v = nullptr;
                vrs[k] = vr_for(type, &v);
                if (type == UC_TYPE_REAL) reals[k] = v ? real_value(*v) : hostile_double();
                if (type == UC_TYPE_INTEGER) ints[k] = v ? integer_value(*v) : integer(-5, 5);
                if (type == UC_TYPE_BOOLEAN) ints[k] = chance(0.8) ? integer(0, 1) : integer(-3, 1000);
                std::snprintf(buf, sizeof buf, "%u=%.17g ", vrs[k], type == UC_TYPE_REAL ? reals[k] : (double)ints[k]);
                call += buf;
            }
            const bool nullValues = chance(0.02);
            trace(call + (nullValues ? "NULL values)" : ")"));
            fmi2Status st;
            if (type == UC_TYPE_REAL) {
                st = fmi().SetReal(s.c, vrs.data(), n, nullValues ? nullptr : reals.data());
            } else if (type == UC_TYPE_INTEGER) {
                st = fmi().SetInteger(s.c, vrs.data(), n, nullValues ? nullptr : ints.data());
            } else {
                st = fmi().SetBoolean(s.c, vrs.data(), n, nullValues ? nullptr : ints.data());
            }
            after(s, "fmi2Set*", st);
        } else if (action < 42) {  // get values: the outputs, or random references
            const bool wasStepped = s.steppedOk;
            if (chance(0.6)) {
                std::vector<double> values(outputs_.size());
                trace("fmi2GetReal(all outputs)");
                const fmi2Status st = fmi().GetReal(s.c, outputs_.data(), outputs_.size(), values.data());
                if (wasStepped && st == fmi2OK) {
                    for (size_t k = 0; k < values.size(); ++k) {
                        if (!std::isfinite(values[k])) {
                            std::snprintf(buf, sizeof buf, "output vr %u = %g after a successful step", outputs_[k],
                                          values[k]);
                            violation(buf, s, last_);
                            break;
                        }
                    }
                }
                after(s, "fmi2GetReal", st);
            } else {
                const UCVarType type = (UCVarType)integer(0, 2);
                const UCVariable* v = nullptr;
                const fmi2ValueReference vr = vr_for(type, &v);
                double r = 0.0;
                fmi2Integer i = 0;
                std::snprintf(buf, sizeof buf, "fmi2Get%s(%u)", uc_type_name(type), vr);
                trace(buf);
                fmi2Status st = type == UC_TYPE_REAL      ? fmi().GetReal(s.c, &vr, 1, chance(0.02) ? nullptr : &r)
                                : type == UC_TYPE_INTEGER ? fmi().GetInteger(s.c, &vr, 1, &i)
                                                          : fmi().GetBoolean(s.c, &vr, 1, &i);
                after(s, "fmi2Get*", st);
            }
        } else if (action < 62) {  // step
            const double h = step_size();
            const double tc = chance(0.93) ? s.time : (chance(0.5) ? s.time + uniform(-2.0, 2.0) : hostile_double());
            std::snprintf(buf, sizeof buf, "fmi2DoStep(tc %.17g, h %.17g)", tc, h);
            trace(buf);
            const bool wasError = s.inError;
            const fmi2Status st = fmi().DoStep(s.c, tc, h, chance(0.5));
            if (wasError && st != fmi2Error) violation("fmi2DoStep accepted in the error state", s, last_);
            if (st == fmi2OK) {
                double t = 0.0;
                if (fmi().GetRealStatus(s.c, fmi2LastSuccessfulTime, &t) == fmi2OK) s.time = t;
                ++okSteps_;
            }
            after(s, "fmi2DoStep", st);
            s.steppedOk = st == fmi2OK;
        } else if (action < 66) {  // input derivatives
            const UCVariable* v = nullptr;
            const fmi2ValueReference vr = vr_for(UC_TYPE_REAL, &v);
            const fmi2Integer order = chance(0.8) ? integer(1, 2) : integer(-2, 5);
            const double value = chance(0.85) ? uniform(-5.0, 5.0) : hostile_double();
            std::snprintf(buf, sizeof buf, "fmi2SetRealInputDerivatives(%u, order %d, %g)", vr, order, value);
            trace(buf);
            after(s, "fmi2SetRealInputDerivatives", fmi().SetRealInputDerivatives(s.c, &vr, 1, &order, &value));
        } else if (action < 72) {  // save a state
            trace("fmi2GetFMUstate");
            fmi2FMUstate st = nullptr;
            const bool reuse = !s.states.empty() && chance(0.3);
            fmi2FMUstate* target = reuse ? &s.states[integer(0, (int)s.states.size() - 1)] : &st;
            const size_t reused = reuse ? (size_t)(target - s.states.data()) : 0;
            const fmi2Status status = fmi().GetFMUstate(s.c, target);
            if (reuse && status == fmi2OK) s.stateDecks[reused] = s.deckText;
            if (!reuse && st != nullptr) {
                if (s.states.size() >= 4) {
                    fmi().FreeFMUstate(s.c, &s.states.front());
                    s.states.erase(s.states.begin());
                    s.stateDecks.erase(s.stateDecks.begin());
                }
                s.states.push_back(st);
                s.stateDecks.push_back(s.deckText);
            }
            after(s, "fmi2GetFMUstate", status);
        } else if (action < 78) {  // restore a state
            if (s.states.empty()) return;
            trace("fmi2SetFMUstate");
            const int which = integer(0, (int)s.states.size() - 1);
            const fmi2Status st = fmi().SetFMUstate(s.c, s.states[which]);
            if (s.stateDecks[which] != s.deckText) ++(st == fmi2OK ? editedRestored_ : editedRefused_);
            if (st == fmi2OK) {
                s.inError = false;
                double t = 0.0;
                // lastSuccessfulTime of the restored state (the query is illegal before initialization)
                const bool stepping = fmi().GetRealStatus(s.c, fmi2LastSuccessfulTime, &t) == fmi2OK;
                if (stepping) s.time = t;
                s.phase = stepping ? 2 : 0;
                s.log.lines.clear();
            }
            after_refusable(s, "fmi2SetFMUstate", st);
            if (st == fmi2OK) s.inError = false;
        } else if (action < 80) {  // free a state
            if (s.states.empty()) return;
            const int k = integer(0, (int)s.states.size() - 1);
            trace("fmi2FreeFMUstate");
            after(s, "fmi2FreeFMUstate", fmi().FreeFMUstate(s.c, &s.states[k]));
            if (s.states[k] == nullptr) {
                s.states.erase(s.states.begin() + k);
                s.stateDecks.erase(s.stateDecks.begin() + k);
            }
        } else if (action < 86) {  // serialize, corrupt, deserialize
            if (s.states.empty()) return;
            const int which = integer(0, (int)s.states.size() - 1);
            fmi2FMUstate st = s.states[which];
            const bool editedSince = s.stateDecks[which] != s.deckText;  // its deck file changed since
            size_t size = 0;
            trace("fmi2SerializedFMUstateSize");
            const fmi2Status sizeStatus = fmi().SerializedFMUstateSize(s.c, st, &size);
            after(s, "fmi2SerializedFMUstateSize", sizeStatus);
            if (sizeStatus != fmi2OK || size > (1u << 26)) return;
            std::vector<char> bytes(size);
            const size_t given = chance(0.05) ? size / 2 : size;
            trace("fmi2SerializeFMUstate");
            const fmi2Status serStatus = fmi().SerializeFMUstate(s.c, st, bytes.data(), given);
            after(s, "fmi2SerializeFMUstate", serStatus);
            if (serStatus != fmi2OK) return;
            const double r = uniform(0.0, 1.0);
            std::string what = "intact";
            if (r < 0.3) {  // flip random bytes
                const int flips = integer(1, 8);
                for (int k = 0; k < flips; ++k) bytes[integer(0, (int)bytes.size() - 1)] ^= (char)integer(1, 255);
                what = "bytes flipped";
            } else if (r < 0.4) {
                bytes.resize(integer(0, (int)bytes.size()));
                what = "truncated";
            } else if (r < 0.45) {
                bytes.resize(bytes.size() + integer(1, 64), (char)integer(0, 255));
                what = "extended";
            } else if (r < 0.55) {  // overwrite a random double with a hostile value
                if (bytes.size() >= 16) {
                    const double h = hostile_double();
                    std::memcpy(&bytes[integer(0, (int)bytes.size() - 8)], &h, sizeof h);
                }
                what = "hostile double";
            }
            Slot& target = slot();  // possibly another instance (states are self-contained)
            if (target.c == nullptr) return;
            fmi2FMUstate restored = nullptr;
            trace("fmi2DeSerializeFMUstate (" + what + ")");
            const fmi2Status ds = fmi().DeSerializeFMUstate(target.c, bytes.empty() ? nullptr : bytes.data(),
                                                            bytes.size(), &restored);
            after_refusable(target, "fmi2DeSerializeFMUstate", ds);
            if (ds != fmi2OK || restored == nullptr) return;
            if (chance(0.7)) {
                trace("fmi2SetFMUstate (deserialized, " + what + ")");
                const fmi2Status set = fmi().SetFMUstate(target.c, restored);
                if (editedSince && what == "intact") ++(set == fmi2OK ? editedRestored_ : editedRefused_);
                if (set == fmi2OK) {
                    target.inError = false;
                    double t = 0.0;
                    const bool stepping = fmi().GetRealStatus(target.c, fmi2LastSuccessfulTime, &t) == fmi2OK;
                    if (stepping) target.time = t;
                    target.phase = stepping ? 2 : 0;
                    target.log.lines.clear();
                }
                after_refusable(target, "fmi2SetFMUstate", set);
                if (set == fmi2OK) target.inError = false;
            }
            trace("fmi2FreeFMUstate (deserialized)");
            after(target, "fmi2FreeFMUstate", fmi().FreeFMUstate(target.c, &restored));
        } else if (action < 89) {
            trace("fmi2Terminate");
            after(s, "fmi2Terminate", fmi().Terminate(s.c));
        } else if (action < 93) {
            trace("fmi2Reset");
            const fmi2Status st = fmi().Reset(s.c);
            after(s, "fmi2Reset", st);
            if (st == fmi2OK) {
                s.inError = false;
                s.time = 0.0;
            }
        } else if (action < 95) {
            static const fmi2String kCategories[] = {"logEvents", "logStatusError", "logSolver", "logAll", "bogus%s"};
            const size_t n = (size_t)integer(0, 5);
            trace("fmi2SetDebugLogging");
            after(s, "fmi2SetDebugLogging", fmi().SetDebugLogging(s.c, chance(0.5), n, n ? kCategories : nullptr));
        } else if (action < 98) {
            const fmi2StatusKind kind = (fmi2StatusKind)integer(0, 4);
            double r = 0.0;
            fmi2Boolean b = 0;
            fmi2Status st2 = fmi2OK;
            fmi2String str = nullptr;
            trace("fmi2Get*Status");
            switch (integer(0, 4)) {
                case 0: after(s, "fmi2GetRealStatus", fmi().GetRealStatus(s.c, kind, &r)); break;
                case 1: after(s, "fmi2GetBooleanStatus", fmi().GetBooleanStatus(s.c, kind, &b)); break;
                case 2: after(s, "fmi2GetStatus", fmi().GetStatus(s.c, kind, &st2)); break;
                case 3: after(s, "fmi2GetStringStatus", fmi().GetStringStatus(s.c, kind, &str)); break;
                default: after(s, "fmi2CancelStep", fmi().CancelStep(s.c)); break;
            }
        } else {
            free_slot(s);
        }
    }

    std::vector<UCVariable> vars_;
    std::vector<fmi2ValueReference> outputs_;
    Slot slots_[3];
    // deck mode
    fmi2ValueReference lineFileVr_ = 0;
    std::vector<size_t> inputs_;  // indices into vars_
    long long deckInstances_ = 0, deckMutated_ = 0, deckEdits_ = 0, editedRefused_ = 0, editedRestored_ = 0;
};

void usage() {
    std::printf(
        "usage: uc_fmi_fuzz [--calls N] [--seed S] [--seconds T] [--trace] [--decks [FILE,FILE,...]] [--fmi3 [--regressions]]\n"
        "  Random FMI call sequences with hostile arguments against UnderwaterCable.so.\n"
        "  --calls N    stop after N random actions (default 100000)\n"
        "  --seed S     PRNG seed (default 1): the same seed gives the same sequence\n"
        "  --seconds T  also stop after T seconds of wall time\n"
        "  --trace      print every call to stderr before making it\n"
        "  --decks      deck mode: instances read lineFile, a private copy of one of the decks (default: the\n"
        "               project's mooring systems and lines, OC4), some edited; body/point inputs fuzzed\n"
        "  --fmi3       the FMI 3.0 variant (its own .so, fuzz_fmi3.cpp): arrays, wrong counts and call\n"
        "               sequences, fmi3 states; most instances read a deck (--decks' list, else the default)\n"
        "  --regressions with --fmi3: the fuzzer's findings as fixed call sequences, instead of random ones\n");
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--trace") {
            o.trace = true;
        } else if (a == "--fmi3") {
            o.fmi3 = true;
        } else if (a == "--regressions") {
            o.regressions = true;
        } else if (a == "--decks") {
            o.decks = default_decks();
            if (i + 1 < argc && argv[i + 1][0] != '-') {  // a comma-separated list of its own
                o.decks.clear();
                std::stringstream list(argv[++i]);
                for (std::string path; std::getline(list, path, ',');)
                    if (!path.empty()) o.decks.push_back(path);
            }
        } else if ((a == "--calls" || a == "--seed" || a == "--seconds") && i + 1 < argc) {
            const char* v = argv[++i];
            if (a == "--calls") o.calls = std::atoll(v);
            if (a == "--seed") o.seed = std::strtoull(v, nullptr, 10);
            if (a == "--seconds") o.seconds = std::atof(v);
        } else {
            usage();
            return a == "--help" || a == "-h" ? 0 : 2;
        }
    }
    if (o.fmi3) {
        if (o.decks.empty()) o.decks = default_decks();
        return run_fmi3_fuzz(o);
    }
    try {
        fmi();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_fmi: %s\n", e.what());
        return 2;
    }
    return Fuzzer(o).run();
}
