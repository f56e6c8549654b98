// fuzz_fmi3.cpp - the FMI 3.0 mode of uc_fmi_fuzz (--fmi3): seeded random call sequences against the FMI 3.0
// variant of the FMU (its own UnderwaterCable.so, fmu/fmi3), loaded with dlopen(RTLD_NOW | RTLD_LOCAL) as an
// importer does, on up to three instances. Most instances read a deck (a mooring system with coupled and free
// bodies and points, OC4, a single line; some with one number changed, some edited under their saved states,
// as in deck mode), so the system's arrays (body.x ... body.q3, point.x ... point.vz as inputs; body.force.*,
// body.stiffness [4, 6, 6], point.force.*, line.* as outputs) carry values. The calls: fmi3SetFloat64 and
// fmi3GetFloat64 over arrays and scalars, with nValues that does not match the value references' elements,
// NULL arrays, NaN and infinities, time, outputs and fixed parameters after initialization, element value
// references of arrays (FMI 2.0 scalars the FMI 3.0 description does not list), unknown ones and ones of
// another type; Int32, Boolean and String likewise (one value each, too long strings); the life cycle in any
// order (fmi3EnterInitializationMode with hostile times, fmi3DoStep with NULL result pointers, terminate,
// reset); FMU states saved, restored, freed, serialized, truncated, extended, corrupted and deserialized
// into another instance; directional derivatives of scalars and of the body arrays with wrong counts and
// mixed shapes; the FMI 3.0 functions this co-simulation FMU does not provide; instantiation as model
// exchange, with event mode or a wrong token.
//
// Checked on every call (a violation is printed with the call and counted; exit code 1):
//   - the status is OK, Warning, Discard or Error, and every non-OK status is logged;
//   - a call that is wrong whatever the model does returns fmi3Error: a count that does not match the
//     elements, a NULL array, a value that is not finite, time, an output or an unknown value reference
//     set, a fixed parameter set after initialization, a call out of sequence (the machine state is tracked
//     where it is known: after an error, a DoStep, a terminate or a restore of a state saved in a known
//     one), a truncated or extended serialized state, a buffer smaller than the state, a NULL state, a
//     function the FMU does not provide; a failed instantiation returns NULL and logs why; fmi3Reset of a
//     live instance succeeds;
//   - a refused fmi3SetFloat64 leaves every value it was given as it was (read back after the refusal);
//   - arrays (arrays(): arrays mixed with scalars, elements and time, right and wrong counts): a refused
//     fmi3SetFloat64 leaves every element bit for bit as it was, an accepted one reads back as set, a get
//     refused for its count writes nothing into the importer's array;
//   - fmi3DoStep reports no event, no early return and a finite lastSuccessfulTime; the Float64 outputs
//     (every array element) read after a successful step are finite.
// Crashes, leaks and undefined behaviour are the sanitizers' job (scripts/fuzz_fmi --sanitize --fmi3).
#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <memory>
#include <set>
#include <stdexcept>

#include "fmi3Types.h"
#include "fuzz_common.h"
#include "uc_fmi3_arrays.h"

using namespace uc_fuzz;

namespace {

// The FMI 3.0 functions the fuzzer calls: X(name, return type, (parameter types)). The first block is what
// the FMU provides, the second what it must refuse (no event mode, clocks, model exchange, other types).
#define UC_FMI3_FUZZED(X)                                                                                      \
    X(InstantiateCoSimulation, fmi3Instance,                                                                   \
      (fmi3String, fmi3String, fmi3String, fmi3Boolean, fmi3Boolean, fmi3Boolean, fmi3Boolean,                 \
       const fmi3ValueReference*, size_t, fmi3InstanceEnvironment, fmi3LogMessageCallback,                    \
       fmi3IntermediateUpdateCallback))                                                                        \
    X(InstantiateModelExchange, fmi3Instance,                                                                  \
      (fmi3String, fmi3String, fmi3String, fmi3Boolean, fmi3Boolean, fmi3InstanceEnvironment,                  \
       fmi3LogMessageCallback))                                                                                \
    X(FreeInstance, void, (fmi3Instance))                                                                      \
    X(SetDebugLogging, fmi3Status, (fmi3Instance, fmi3Boolean, size_t, const fmi3String*))                    \
    X(EnterInitializationMode, fmi3Status, (fmi3Instance, fmi3Boolean, fmi3Float64, fmi3Float64, fmi3Boolean,  \
                                           fmi3Float64))                                                       \
    X(ExitInitializationMode, fmi3Status, (fmi3Instance))                                                      \
    X(Terminate, fmi3Status, (fmi3Instance))                                                                   \
    X(Reset, fmi3Status, (fmi3Instance))                                                                       \
    X(DoStep, fmi3Status, (fmi3Instance, fmi3Float64, fmi3Float64, fmi3Boolean, fmi3Boolean*, fmi3Boolean*,    \
                           fmi3Boolean*, fmi3Float64*))                                                        \
    X(GetFloat64, fmi3Status, (fmi3Instance, const fmi3ValueReference*, size_t, fmi3Float64*, size_t))         \
    X(SetFloat64, fmi3Status, (fmi3Instance, const fmi3ValueReference*, size_t, const fmi3Float64*, size_t))   \
    X(GetInt32, fmi3Status, (fmi3Instance, const fmi3ValueReference*, size_t, fmi3Int32*, size_t))             \
    X(SetInt32, fmi3Status, (fmi3Instance, const fmi3ValueReference*, size_t, const fmi3Int32*, size_t))       \
    X(GetBoolean, fmi3Status, (fmi3Instance, const fmi3ValueReference*, size_t, fmi3Boolean*, size_t))         \
    X(SetBoolean, fmi3Status, (fmi3Instance, const fmi3ValueReference*, size_t, const fmi3Boolean*, size_t))   \
    X(GetString, fmi3Status, (fmi3Instance, const fmi3ValueReference*, size_t, fmi3String*, size_t))           \
    X(SetString, fmi3Status, (fmi3Instance, const fmi3ValueReference*, size_t, const fmi3String*, size_t))     \
    X(GetFMUState, fmi3Status, (fmi3Instance, fmi3FMUState*))                                                  \
    X(SetFMUState, fmi3Status, (fmi3Instance, fmi3FMUState))                                                   \
    X(FreeFMUState, fmi3Status, (fmi3Instance, fmi3FMUState*))                                                 \
    X(SerializedFMUStateSize, fmi3Status, (fmi3Instance, fmi3FMUState, size_t*))                               \
    X(SerializeFMUState, fmi3Status, (fmi3Instance, fmi3FMUState, fmi3Byte*, size_t))                          \
    X(DeserializeFMUState, fmi3Status, (fmi3Instance, const fmi3Byte*, size_t, fmi3FMUState*))                 \
    X(GetDirectionalDerivative, fmi3Status,                                                                    \
      (fmi3Instance, const fmi3ValueReference*, size_t, const fmi3ValueReference*, size_t, const fmi3Float64*, \
       size_t, fmi3Float64*, size_t))                                                                          \
    X(EnterEventMode, fmi3Status, (fmi3Instance))                                                              \
    X(EnterStepMode, fmi3Status, (fmi3Instance))                                                               \
    X(EnterConfigurationMode, fmi3Status, (fmi3Instance))                                                      \
    X(ExitConfigurationMode, fmi3Status, (fmi3Instance))                                                       \
    X(GetFloat32, fmi3Status, (fmi3Instance, const fmi3ValueReference*, size_t, fmi3Float32*, size_t))         \
    X(SetInt64, fmi3Status, (fmi3Instance, const fmi3ValueReference*, size_t, const fmi3Int64*, size_t))       \
    X(GetUInt8, fmi3Status, (fmi3Instance, const fmi3ValueReference*, size_t, fmi3UInt8*, size_t))             \
    X(GetBinary, fmi3Status, (fmi3Instance, const fmi3ValueReference*, size_t, size_t*, fmi3Binary*, size_t))  \
    X(GetClock, fmi3Status, (fmi3Instance, const fmi3ValueReference*, size_t, fmi3Clock*))                     \
    X(GetNumberOfContinuousStates, fmi3Status, (fmi3Instance, size_t*))                                        \
    X(GetOutputDerivatives, fmi3Status,                                                                        \
      (fmi3Instance, const fmi3ValueReference*, size_t, const fmi3Int32*, fmi3Float64*, size_t))              \
    X(GetAdjointDerivative, fmi3Status,                                                                        \
      (fmi3Instance, const fmi3ValueReference*, size_t, const fmi3ValueReference*, size_t, const fmi3Float64*, \
       size_t, fmi3Float64*, size_t))                                                                          \
    X(SetTime, fmi3Status, (fmi3Instance, fmi3Float64))                                                        \
    X(UpdateDiscreteStates, fmi3Status, (fmi3Instance, fmi3Boolean*, fmi3Boolean*, fmi3Boolean*, fmi3Boolean*, \
                                         fmi3Boolean*, fmi3Float64*))

struct Fmi3Api {
#define UC_DECLARE_FMI3(name, ret, args) ret(*name) args = nullptr;
    UC_FMI3_FUZZED(UC_DECLARE_FMI3)
#undef UC_DECLARE_FMI3
    void* handle = nullptr;
    std::vector<std::string> missing;
};

const Fmi3Api& fmi3() {
    static const Fmi3Api api = [] {
        Fmi3Api a;
        a.handle = dlopen(UC_FMI3_SO, RTLD_NOW | RTLD_LOCAL);
        if (a.handle == nullptr) return a;
#define UC_RESOLVE_FMI3(name, ret, args)                                               \
    a.name = reinterpret_cast<ret(*) args>(dlsym(a.handle, "fmi3" #name));             \
    if (a.name == nullptr) a.missing.push_back("fmi3" #name);
        UC_FMI3_FUZZED(UC_RESOLVE_FMI3)
#undef UC_RESOLVE_FMI3
        return a;
    }();
    if (api.handle == nullptr || !api.missing.empty()) {
        throw std::runtime_error("cannot load " UC_FMI3_SO " or a function of it" +
                                 (api.missing.empty() ? std::string() : ": " + api.missing.front()));
    }
    return api;
}

// The instantiation token of the FMI 3.0 model description the library was built with.
std::string fmi3_token() {
    const std::string xml = read_text(UC_FMI3_MODEL_DESCRIPTION);
    const std::string key = "instantiationToken=\"";
    const size_t at = xml.find(key);
    if (at == std::string::npos) throw std::runtime_error("no instantiationToken in " UC_FMI3_MODEL_DESCRIPTION);
    return xml.substr(at + key.size(), xml.find('"', at + key.size()) - at - key.size());
}

void capture3(fmi3InstanceEnvironment env, fmi3Status, fmi3String category, fmi3String message) {
    static_cast<LogCapture*>(env)->lines.push_back(std::string(category ? category : "(NULL category)") + ": " +
                                                   (message ? message : "(NULL message)"));
}

const char* status_name(fmi3Status s) {
    static const char* kNames[] = {"fmi3OK", "fmi3Warning", "fmi3Discard", "fmi3Error", "fmi3Fatal"};
    return (s >= fmi3OK && s <= fmi3Fatal) ? kNames[s] : "not a status";
}

// The machine state as far as the fuzzer knows it; Unknown where a call's effect depends on what it found.
enum class Phase { Unknown, Instantiated, Init, Stepping, Terminated, Error };

// What an fmi3Error does to the machine state: the FMI 2.0 adapter's checked calls and the FMI 3.0 setters go
// to the error state; the FMI 3.0 layer's own refusals of a getter's arguments, a DoStep's NULL results, a
// state to restore and the functions not provided change nothing.
enum class OnError { ErrorState, Unchanged, Unknown };

// A variable of the FMI 3.0 model description: a scalar, an array (its first FMI 2.0 element's value reference
// and its elements at a stride) or time.
struct Var3 {
    fmi3ValueReference vr = 0;
    size_t count = 1;
    fmi3ValueReference stride = 1;
    const UCVariable* first = nullptr;  // the FMI 2.0 scalar of element 1 (nullptr: time)
    std::string name;
    size_t kept = 1;                    // elements from vr at the stride; the others from extension
    fmi3ValueReference extension = 0;
    fmi3ValueReference element(size_t i) const {
        return i < kept ? vr + (fmi3ValueReference)i * stride : extension + (fmi3ValueReference)(i - kept) * stride;
    }
};

// A value reference drawn for a call, with what it is.
enum class Kind { Variable, Element, OtherType, Unknown, Time };
struct Pick {
    fmi3ValueReference vr = 0;
    size_t count = 1;
    Kind kind = Kind::Unknown;
    const UCVariable* v = nullptr;  // the FMI 2.0 scalar it stands for (its first element), if any
};

struct Slot3 {
    fmi3Instance c = nullptr;
    LogCapture log;
    double time = 0.0;
    Phase phase = Phase::Unknown;
    bool steppedOk = false;  // the last call was a successful fmi3DoStep
    std::vector<fmi3FMUState> states;
    std::vector<Phase> statePhases;  // the phase each state was saved in
    std::vector<std::string> stateDecks;
    std::string deckPath, deckText;
};

class Fmi3Fuzzer : public FuzzBase {
public:
    explicit Fmi3Fuzzer(const Options& o) : FuzzBase(o), token_(fmi3_token()) {
        size_t n = 0;
        const UCVariable* table = uc_variables(&n);
        std::set<unsigned int> elementVrs;
        std::map<unsigned int, Var3> arrays;
#define UC_FMI3_ARRAY_ENTRY(firstVr, elements, step, arrayName, keep, ext, sizedBy, perIndex)                            \
    arrays[firstVr] = Var3{firstVr, elements, step, uc_variable_find(firstVr, UC_TYPE_REAL), arrayName, keep, ext}; \
    for (unsigned int i = 1; i < (elements); ++i) elementVrs.insert(arrays[firstVr].element(i));
        UC_FMI3_ARRAYS(UC_FMI3_ARRAY_ENTRY)
#undef UC_FMI3_ARRAY_ENTRY
        vars_.push_back(Var3{UC_FMI3_TIME_VR, 1, 1, nullptr, "time"});
        for (size_t k = 0; k < n; ++k) {
            const UCVariable& v = table[k];
            if (v.type == UC_TYPE_REAL && elementVrs.count(v.vr)) {
                elements_.push_back(&v);
                continue;
            }
            const auto array = arrays.find(v.vr);
            vars_.push_back(v.type == UC_TYPE_REAL && array != arrays.end() ? array->second
                                                                            : Var3{v.vr, 1, 1, &v, v.name});
            if (std::strcmp(v.name, "lineFile") == 0) lineFileVr_ = v.vr;
        }
        for (size_t k = 0; k < vars_.size(); ++k) {
            const Var3& v = vars_[k];
            if (v.first == nullptr) continue;
            byType_[v.first->type].push_back(k);
            if (v.first->causality == UC_CAUSALITY_INPUT) inputsByType_[v.first->type].push_back(k);
            if (v.first->type == UC_TYPE_REAL && v.first->causality == UC_CAUSALITY_OUTPUT) {
                outputVrs_.push_back(v.vr);
                outputElements_ += v.count;
            }
            if (v.name == "towForce.x" || v.name == "towForce.y" || v.name == "towForce.z" ||
                v.name == "endForce.x" || v.name == "endForce.y" || v.name == "endForce.z") {
                scalarUnknowns_.push_back(v.vr);
            }
            if (v.name.rfind("tow.", 0) == 0 && v.count == 1 && v.first->causality == UC_CAUSALITY_INPUT &&
                v.name.find(".a") == std::string::npos) {
                scalarKnowns_.push_back(v.vr);
            }
            if (v.count == UC_MAX_BODIES && (v.name.rfind("body.force.", 0) == 0 || v.name.rfind("body.moment.", 0) == 0)) {
                arrayUnknowns_.push_back(v.vr);
            }
            if (v.count == UC_MAX_BODIES && v.first->causality == UC_CAUSALITY_INPUT && v.name.rfind("body.", 0) == 0) {
                arrayKnowns_.push_back(v.vr);
            }
            if (v.first->type == UC_TYPE_REAL) {
                (v.count == 1 ? realScalars_ : v.first->causality == UC_CAUSALITY_INPUT ? arrayInputs_ : arrayOutputs_)
                    .push_back(k);
            }
        }
        for (int k = 0; k < 3; ++k) {
            slots_[k].deckPath = "/tmp/uc_fmi3_fuzz_" + std::to_string(getpid()) + "_" + std::to_string(k) + ".dat";
        }
    }
    ~Fmi3Fuzzer() override {
        for (Slot3& s : slots_) std::remove(s.deckPath.c_str());
    }

private:
    const Fmi3Api& api() { return fmi3(); }

    void free_all() override {
        for (Slot3& s : slots_) free_slot(s);
    }

    void print_extra() override {
        std::printf("fmi3: %zu variables (%zu arrays), %zu element value references of arrays; %lld calls wrong "
                    "whatever the model does, all to return fmi3Error; %lld refused fmi3SetFloat64 read back "
                    "unchanged; decks: %lld instances given one (%lld of them edited), %lld edits under saved states\n",
                    vars_.size(), arrayCount(), elements_.size(), wrongCalls_, readBacks_, deckInstances_, deckMutated_,
                    deckEdits_);
        std::printf("fmi3 arrays: %lld calls of arrays mixed with scalars; %lld refused fmi3SetFloat64 read back "
                    "unchanged (every value given), %lld accepted read back as set, %lld refused fmi3GetFloat64 left "
                    "the importer's array untouched\n",
                    arrayCalls_, arrayRefusedReadBacks_, arrayAcceptedReadBacks_, arrayRefusedGets_);
    }

    size_t arrayCount() const {
        return (size_t)std::count_if(vars_.begin(), vars_.end(), [](const Var3& v) { return v.count > 1; });
    }

    // ---- value references ----------------------------------------------------------------------------
    Pick pick(UCVarType type) {
        Pick p;
        const double r = uniform(0.0, 1.0);
        if (r < 0.03) {
            p.vr = chance(0.5) ? 0xFFFFFFFFu : 4000000u;
            p.kind = Kind::Unknown;
            return p;
        }
        if (r < 0.06) {  // a variable of another type
            UCVarType other = type;
            while (other == type) other = (UCVarType)integer(0, 3);
            const Var3& v = vars_[byType_[other][integer(0, (int)byType_[other].size() - 1)]];
            p.vr = v.vr;
            p.v = v.first;
            p.kind = Kind::OtherType;
            return p;
        }
        if (type == UC_TYPE_REAL && r < 0.09) {  // an array's element, an FMI 2.0 scalar FMI 3.0 does not list
            p.v = elements_[integer(0, (int)elements_.size() - 1)];
            p.vr = p.v->vr;
            p.kind = Kind::Element;
            return p;
        }
        if (type == UC_TYPE_REAL && r < 0.11) {
            p.vr = UC_FMI3_TIME_VR;
            p.kind = Kind::Time;
            return p;
        }
        // deck mode: mostly the inputs (the deck, not random parameters, makes the system)
        const std::vector<size_t>& from =
            !inputsByType_[type].empty() && chance(0.7) ? inputsByType_[type] : byType_[type];
        const Var3& v = vars_[from[integer(0, (int)from.size() - 1)]];
        p.vr = v.vr;
        p.count = v.count;
        p.v = v.first;
        p.kind = Kind::Variable;
        return p;
    }

    // A count that differs from `expected`: one fewer or more, none, or a few more.
    size_t wrong_count(size_t expected) {
        switch (integer(0, 3)) {
            case 0: return expected > 0 ? expected - 1 : 1;
            case 1: return expected + 1;
            case 2: return expected > 0 ? 0 : 2;
            default: return expected + (size_t)integer(2, 40);
        }
    }

    // Whether setting p is refused whatever the values (given the machine state where it is known).
    bool set_refused(const Pick& p, const Slot3& s) const {
        if (p.kind == Kind::Unknown || p.kind == Kind::OtherType || p.kind == Kind::Time) return true;
        if (p.v->causality == UC_CAUSALITY_OUTPUT) return true;
        if (p.v->causality == UC_CAUSALITY_PARAMETER && s.phase == Phase::Stepping) return true;
        return s.phase == Phase::Terminated || s.phase == Phase::Error;
    }

    // Whether getting p is refused (time reads in any state; the others not before initialization).
    bool get_refused(const Pick& p, const Slot3& s) const {
        if (p.kind == Kind::Unknown || p.kind == Kind::OtherType) return true;
        return p.kind != Kind::Time && s.phase == Phase::Instantiated;
    }

    // ---- bookkeeping ---------------------------------------------------------------------------------
    Slot3& slot() { return slots_[integer(0, 2)]; }

    void violation(const std::string& what, const Slot3& s) { FuzzBase::violation(what.c_str(), s.log, last_); }

    // The checks of every call; `wrong`: the call is wrong whatever the model does and must return fmi3Error.
    void after(Slot3& s, const char* function, fmi3Status status, OnError onError, bool wrong = false) {
        const int k = tally(function, (int)status);
        if (k == 4 || status == fmi3Fatal) violation("status is not OK/Warning/Discard/Error", s);
        if (status != fmi3OK && s.c != nullptr && s.log.lines.empty()) violation("a non-OK status without a log message", s);
        if (wrong) {
            ++wrongCalls_;
            if (status != fmi3Error) violation(std::string("a wrong call returned ") + status_name(status), s);
        }
        s.log.lines.clear();
        s.steppedOk = false;
        if (status == fmi3Error) {
            if (onError == OnError::ErrorState) s.phase = Phase::Error;
            if (onError == OnError::Unknown && s.phase != Phase::Error) s.phase = Phase::Unknown;
        } else if (status != fmi3OK) {
            s.phase = Phase::Unknown;
        }
    }

    void free_states(Slot3& s) {
        for (fmi3FMUState& st : s.states) {
            if (st != nullptr) api().FreeFMUState(s.c, &st);
        }
        s.states.clear();
        s.statePhases.clear();
        s.stateDecks.clear();
    }

    void free_slot(Slot3& s) {
        if (s.c == nullptr) return;
        trace("fmi3FreeInstance");
        free_states(s);
        api().FreeInstance(s.c);
        tally("fmi3FreeInstance", 0);
        s.c = nullptr;
    }

    void write_deck(Slot3& s, const std::string& text) {
        std::ofstream out(s.deckPath, std::ios::binary | std::ios::trunc);
        out << text;
        s.deckText = text;
    }

    void give_deck(Slot3& s) {
        if (deckTexts_.empty() || s.c == nullptr || !chance(0.75)) return;
        const bool mutate = chance(0.25);
        const std::string& text = deckTexts_[integer(0, (int)deckTexts_.size() - 1)];
        write_deck(s, mutate ? mutated_deck(text) : text);
        ++deckInstances_;
        if (mutate) ++deckMutated_;
        trace("fmi3SetString(lineFile " + s.deckPath + ")");
        const fmi3String value = s.deckPath.c_str();
        after(s, "fmi3SetString", api().SetString(s.c, &lineFileVr_, 1, &value, 1), OnError::ErrorState);
    }

    // ---- life cycle ----------------------------------------------------------------------------------
    void instantiate(Slot3& s) {
        free_slot(s);
        s.log.lines.clear();
        s.time = 0.0;
        s.steppedOk = false;
        s.deckText.clear();
        const int bad = chance(0.06) ? integer(1, 4) : 0;  // a wrong token, event mode, model exchange, no token
        const std::string wrongToken = "{00000000-0000-0000-0000-000000000000}";
        const char* token = bad == 1 ? wrongToken.c_str() : bad == 4 ? nullptr : token_.c_str();
        const char* resources = chance(0.5) ? "/tmp/x y%20#" : nullptr;
        static const char* kBad[] = {"", "a wrong token", "eventModeUsed", "model exchange", "a NULL token"};
        trace(std::string("fmi3Instantiate") + (bad ? std::string(" with ") + kBad[bad] : ""));
        if (bad == 3) {
            s.c = api().InstantiateModelExchange("fuzz3 %s #1#", token, resources, false, true, &s.log, capture3);
        } else {
            s.c = api().InstantiateCoSimulation("fuzz3 %s #1#", token, resources, false, chance(0.5), bad == 2,
                                                chance(0.5), nullptr, 0, &s.log, capture3, nullptr);
        }
        tally(bad ? "fmi3Instantiate (wrong)" : "fmi3Instantiate", s.c == nullptr ? 3 : 0);
        if (bad) {
            ++wrongCalls_;
            if (s.c != nullptr) violation(std::string("instantiation with ") + kBad[bad] + " did not fail", s);
            if (s.c == nullptr && s.log.lines.empty()) violation("a failed instantiation without a log message", s);
            free_slot(s);
            s.log.lines.clear();
            return;
        }
        if (s.c == nullptr) {
            violation("fmi3InstantiateCoSimulation failed with valid arguments", s);
            return;
        }
        s.log.lines.clear();
        s.phase = Phase::Instantiated;
        give_deck(s);
    }

    // A call that moves the instance along the normal life cycle (so that random sequences reach long runs).
    bool progress(Slot3& s) {
        if (s.phase == Phase::Error || s.phase == Phase::Terminated || s.phase == Phase::Unknown) {
            if (!chance(0.3)) return false;
            reset(s, "fmi3Reset (progress)");
            return true;
        }
        if (s.phase == Phase::Instantiated) {
            trace("fmi3EnterInitializationMode (progress)");
            after(s, "fmi3EnterInitializationMode", api().EnterInitializationMode(s.c, false, 0.0, 0.0, false, 0.0),
                  OnError::ErrorState);
            if (s.phase == Phase::Instantiated) s.phase = Phase::Init;  // not changed by an error: OK
            s.time = 0.0;
            return true;
        }
        if (s.phase == Phase::Init) {
            trace("fmi3ExitInitializationMode (progress)");
            const fmi3Status st = api().ExitInitializationMode(s.c);
            after(s, "fmi3ExitInitializationMode", st, OnError::ErrorState);
            if (st == fmi3OK) s.phase = Phase::Stepping;
            return true;
        }
        do_step(s, s.time, chance(0.8) ? 0.5 : std::pow(10.0, uniform(-3.0, 0.7)), false, "(progress)");
        return true;
    }

    void reset(Slot3& s, const char* call) {
        trace(call);
        const fmi3Status st = api().Reset(s.c);
        if (st != fmi3OK) violation(std::string("fmi3Reset of a live instance returned ") + status_name(st), s);
        after(s, "fmi3Reset", st, OnError::ErrorState);
        if (st == fmi3OK) {
            s.phase = Phase::Instantiated;
            s.time = 0.0;
        }
    }

    void do_step(Slot3& s, double tc, double h, bool nullResult, const char* note) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "fmi3DoStep(tc %.17g, h %.17g%s) %s", tc, h, nullResult ? ", a NULL result" : "",
                      note);
        trace(buf);
        fmi3Boolean event = true, terminate = true, early = true;
        fmi3Float64 last = std::nan("");
        const int which = nullResult ? integer(0, 3) : -1;
        const fmi3Status st = api().DoStep(s.c, tc, h, chance(0.5), which == 0 ? nullptr : &event,
                                           which == 1 ? nullptr : &terminate, which == 2 ? nullptr : &early,
                                           which == 3 ? nullptr : &last);
        const bool outOfSequence = s.phase == Phase::Instantiated || s.phase == Phase::Init ||
                                   s.phase == Phase::Terminated || s.phase == Phase::Error;
        if (st == fmi3OK && (event || early || !std::isfinite(last))) {
            violation("fmi3DoStep: an event, an early return or a lastSuccessfulTime that is not finite", s);
        }
        after(s, "fmi3DoStep", st, nullResult ? OnError::Unchanged : OnError::ErrorState, nullResult || outOfSequence);
        if (st == fmi3OK) {
            s.time = last;
            s.phase = Phase::Stepping;
            ++okSteps_;
            s.steppedOk = true;
        }
    }

    // ---- values --------------------------------------------------------------------------------------
    double value_for(const UCVariable* v) { return v != nullptr ? real_value(*v) : hostile_double(); }

    // Float64 values of the picks' elements, read now (for the read-back of a refused set); false if unreadable.
    bool read_float64(Slot3& s, const std::vector<fmi3ValueReference>& vrs, size_t count, std::vector<double>* out) {
        out->assign(count, 0.0);
        trace("fmi3GetFloat64 (before a set)");
        const fmi3Status st = api().GetFloat64(s.c, vrs.data(), vrs.size(), out->data(), count);
        after(s, "fmi3GetFloat64", st, OnError::ErrorState);
        return st == fmi3OK || st == fmi3Warning;
    }

    void set_float64(Slot3& s) {
        const int n = integer(1, 3);
        std::vector<Pick> picks(n);
        std::vector<fmi3ValueReference> vrs(n);
        size_t expected = 0;
        bool refused = false;
        std::string call = "fmi3SetFloat64(";
        for (int k = 0; k < n; ++k) {
            picks[k] = pick(UC_TYPE_REAL);
            vrs[k] = picks[k].vr;
            expected += picks[k].count;
            refused = refused || set_refused(picks[k], s);
            call += std::to_string(vrs[k]) + (picks[k].count > 1 ? "[" + std::to_string(picks[k].count) + "] " : " ");
        }
        const bool mismatch = chance(0.12);
        const size_t nValues = mismatch ? wrong_count(expected) : expected;
        std::vector<double> values(nValues);
        bool finite = true;
        for (size_t at = 0, k = 0; k < (size_t)n; ++k) {
            for (size_t i = 0; i < picks[k].count && at < nValues; ++i, ++at) {
                values[at] = value_for(picks[k].v);
                finite = finite && std::isfinite(values[at]);
            }
        }
        for (size_t at = std::min(expected, nValues); at < nValues; ++at) values[at] = uniform(-1.0, 1.0);
        const int nulls = chance(0.03) ? integer(1, 2) : 0;  // 1: vr NULL, 2: values NULL
        call += "= " + std::to_string(nValues) + " values" + (finite ? "" : " not all finite") +
                (nulls == 1 ? ", vr NULL" : nulls == 2 ? ", values NULL" : "") + ")";
        const bool wrong = mismatch || nulls != 0 || refused || !finite;
        // The read-back: variables whose refusal is down to one value (every one settable now, a NaN among them).
        std::vector<double> before;
        const bool readBack = wrong && !mismatch && nulls == 0 && finite == false && !refused &&
                              (s.phase == Phase::Init || s.phase == Phase::Stepping) && chance(0.5) &&
                              std::all_of(picks.begin(), picks.end(), [](const Pick& p) { return p.kind == Kind::Variable; }) &&
                              read_float64(s, vrs, expected, &before);
        trace(call);
        const fmi3Status st = api().SetFloat64(s.c, nulls == 1 ? nullptr : vrs.data(), vrs.size(),
                                               nulls == 2 ? nullptr : values.data(), nValues);
        after(s, "fmi3SetFloat64", st, OnError::ErrorState, wrong);
        if (readBack && st == fmi3Error) {
            std::vector<double> now(expected, 0.0);
            trace("fmi3GetFloat64 (after the refused set)");
            const fmi3Status got = api().GetFloat64(s.c, vrs.data(), vrs.size(), now.data(), expected);
            const bool same = std::memcmp(before.data(), now.data(), expected * sizeof(double)) == 0;
            if ((got == fmi3OK || got == fmi3Warning) && !same) {
                violation("a refused fmi3SetFloat64 changed a value: " + call, s);
            }
            ++readBacks_;
            after(s, "fmi3GetFloat64", got, OnError::ErrorState);
        }
    }

    void get_float64(Slot3& s) {
        const bool wasStepped = s.steppedOk;
        if (chance(0.5)) {  // every Float64 output, the arrays' elements included
            std::vector<double> values(outputElements_);
            trace("fmi3GetFloat64(all outputs)");
            const fmi3Status st = api().GetFloat64(s.c, outputVrs_.data(), outputVrs_.size(), values.data(),
                                                   values.size());
            if (wasStepped && st == fmi3OK) {
                for (size_t k = 0; k < values.size(); ++k) {
                    if (!std::isfinite(values[k])) {
                        violation("output element " + std::to_string(k) + " = " + std::to_string(values[k]) +
                                      " after a successful step", s);
                        break;
                    }
                }
            }
            after(s, "fmi3GetFloat64", st, OnError::ErrorState, s.phase == Phase::Instantiated);
            return;
        }
        const int n = integer(1, 3);
        std::vector<fmi3ValueReference> vrs(n);
        size_t expected = 0;
        bool refused = false;
        for (int k = 0; k < n; ++k) {
            const Pick p = pick(UC_TYPE_REAL);
            vrs[k] = p.vr;
            expected += p.count;
            refused = refused || get_refused(p, s);
        }
        const bool mismatch = chance(0.15);
        const size_t nValues = mismatch ? wrong_count(expected) : expected;
        std::vector<double> values(nValues);
        const int nulls = chance(0.03) ? integer(1, 2) : 0;
        trace("fmi3GetFloat64(" + std::to_string(n) + " value references, " + std::to_string(expected) + " elements, " +
              std::to_string(nValues) + " values" + (nulls ? ", a NULL array)" : ")"));
        const fmi3Status st = api().GetFloat64(s.c, nulls == 1 ? nullptr : vrs.data(), vrs.size(),
                                               nulls == 2 ? nullptr : values.data(), nValues);
        after(s, "fmi3GetFloat64", st, mismatch || nulls ? OnError::Unchanged : OnError::ErrorState,
              mismatch || nulls || refused);
    }

    // ---- arrays --------------------------------------------------------------------------------------
    // A variable of an arrays call and its elements' FMI 2.0 scalars, in order (nullptr: time).
    struct Part {
        Pick pick;
        std::vector<const UCVariable*> scalars;
    };

    Part array_part(const std::vector<size_t>& from) {
        const Var3& v = vars_[from[integer(0, (int)from.size() - 1)]];
        Part part{Pick{v.vr, v.count, Kind::Variable, v.first}, {}};
        for (size_t i = 0; i < v.count; ++i) {
            part.scalars.push_back(uc_variable_find(v.element(i), UC_TYPE_REAL));
        }
        return part;
    }

    // One to four Float64 variables, an array among them (an input mostly, or an output), the others arrays,
    // scalars, elements of arrays or time, in random order.
    std::vector<Part> array_parts() {
        std::vector<Part> parts;
        const int n = integer(1, 4);
        for (int k = 0; k < n; ++k) {
            const double r = uniform(0.0, 1.0);
            if (k == 0 || r < 0.5) {
                parts.push_back(array_part(chance(0.8) || arrayOutputs_.empty() ? arrayInputs_ : arrayOutputs_));
            } else if (r < 0.88) {
                const Var3& v = vars_[realScalars_[integer(0, (int)realScalars_.size() - 1)]];
                parts.push_back(Part{Pick{v.vr, 1, Kind::Variable, v.first}, {v.first}});
            } else if (r < 0.97) {
                const UCVariable* e = elements_[integer(0, (int)elements_.size() - 1)];
                parts.push_back(Part{Pick{e->vr, 1, Kind::Element, e}, {e}});
            } else {
                parts.push_back(Part{Pick{UC_FMI3_TIME_VR, 1, Kind::Time, nullptr}, {nullptr}});
            }
        }
        std::shuffle(parts.begin(), parts.end(), rng_);
        return parts;
    }

    // A count for `expected` elements whose last array is `lastArray` elements long: right, or wrong (a part of
    // an array, one short, one over, none, a few over).
    size_t array_count(size_t expected, size_t lastArray, bool* mismatch) {
        *mismatch = chance(0.3);
        if (!*mismatch) return expected;
        if (chance(0.4) && lastArray > 1) return expected - (size_t)integer(1, (int)lastArray - 1);
        return wrong_count(expected);
    }

    // The machine states in which every Float64 variable reads.
    static bool readable(const Slot3& s) {
        return s.phase == Phase::Init || s.phase == Phase::Stepping || s.phase == Phase::Terminated ||
               s.phase == Phase::Error;
    }

    // fmi3SetFloat64 and fmi3GetFloat64 of arrays mixed with scalars, with the right and wrong counts. Checked,
    // besides after(): a refused set leaves every value of every variable given as it was (read back before and
    // after, element by element); an accepted set of inputs and parameters reads back as set; a refused get for
    // a count that does not match writes nothing into the importer's array.
    void arrays(Slot3& s) {
        ++arrayCalls_;
        const std::vector<Part> parts = array_parts();
        std::vector<fmi3ValueReference> vrs;
        std::vector<const UCVariable*> scalars;
        size_t lastArray = 0;
        bool refused = false;
        std::string call;
        for (const Part& part : parts) {
            vrs.push_back(part.pick.vr);
            scalars.insert(scalars.end(), part.scalars.begin(), part.scalars.end());
            if (part.pick.count > 1) lastArray = part.pick.count;
            call += (call.empty() ? "" : " ") + std::to_string(part.pick.vr) +
                    (part.pick.count > 1 ? "[" + std::to_string(part.pick.count) + "]" : "");
        }
        const size_t expected = scalars.size();
        bool mismatch = false;
        const size_t nValues = array_count(expected, lastArray, &mismatch);
        if (chance(0.35)) {
            array_get(s, vrs, expected, nValues, mismatch, call);
            return;
        }
        for (const Part& part : parts) refused = refused || set_refused(part.pick, s);
        std::vector<double> values(nValues);
        bool finite = true;
        for (size_t at = 0; at < nValues; ++at) {
            const UCVariable* v = at < expected ? scalars[at] : nullptr;
            values[at] = v != nullptr ? plausible(*v) : uniform(0.0, 10.0);
        }
        if (nValues > 0 && chance(0.25)) values[integer(0, (int)nValues - 1)] = hostile_double();
        for (const double x : values) finite = finite && std::isfinite(x);
        call = "fmi3SetFloat64(" + call + " = " + std::to_string(nValues) + " values for " + std::to_string(expected) +
               " elements" + (finite ? "" : ", not all finite") + ")";
        const bool wrong = mismatch || refused || !finite;
        std::vector<double> before, now;
        const bool haveBefore = readable(s) && chance(0.7) && read_all(s, vrs, expected, &before, "before a set");
        trace(call);
        const fmi3Status st = api().SetFloat64(s.c, vrs.data(), vrs.size(), values.data(), nValues);
        after(s, "fmi3SetFloat64", st, OnError::ErrorState, wrong);
        if (st == fmi3Error && haveBefore && read_all(s, vrs, expected, &now, "after the refused set")) {
            ++arrayRefusedReadBacks_;
            const size_t at = first_difference(before, now);
            if (at < expected) violation("a refused " + call + " changed element " + std::to_string(at) + element_name(scalars[at]) + ": " + std::to_string(before[at]) + " -> " + std::to_string(now[at]), s);
        }
        if (st == fmi3OK && !wrong && readable(s) && read_all(s, vrs, expected, &now, "after the set")) {
            ++arrayAcceptedReadBacks_;
            // What each FMI 2.0 scalar holds now: the last value given for it (a variable may be given twice).
            std::map<const UCVariable*, double> set;
            for (size_t at = 0; at < expected; ++at) set[scalars[at]] = values[at];
            for (size_t at = 0; at < expected; ++at) {
                const UCVariable* v = scalars[at];
                if (v == nullptr || v->causality == UC_CAUSALITY_OUTPUT) continue;
                if (std::memcmp(&set[v], &now[at], sizeof(double)) != 0) {
                    violation("after an accepted " + call + ", element " + std::to_string(at) + element_name(v) +
                                  " reads " + std::to_string(now[at]) + ", set " + std::to_string(set[v]), s);
                    break;
                }
            }
        }
    }

    void array_get(Slot3& s, const std::vector<fmi3ValueReference>& vrs, size_t expected, size_t nValues,
                   bool mismatch, const std::string& variables) {
        static const uint64_t kUntouched = 0x7ff4dead0000beefULL;  // a signalling NaN no getter writes
        std::vector<double> values(nValues);
        for (double& x : values) std::memcpy(&x, &kUntouched, sizeof x);
        const bool wrong = mismatch || get_refused_at(s);
        trace("fmi3GetFloat64(" + variables + " = " + std::to_string(nValues) + " values for " +
              std::to_string(expected) + " elements)");
        const fmi3Status st = api().GetFloat64(s.c, vrs.data(), vrs.size(), values.data(), nValues);
        after(s, "fmi3GetFloat64", st, mismatch ? OnError::Unchanged : OnError::ErrorState, wrong);
        if (mismatch && st == fmi3Error) {
            ++arrayRefusedGets_;
            for (size_t at = 0; at < nValues; ++at) {
                if (std::memcmp(&values[at], &kUntouched, sizeof(double)) != 0) {
                    violation("fmi3GetFloat64 refused for its count wrote values[" + std::to_string(at) + "]", s);
                    break;
                }
            }
        }
    }

    // Whether any get is refused in the machine state (before initialization).
    static bool get_refused_at(const Slot3& s) { return s.phase == Phase::Instantiated; }

    // Every element of the variables vrs, read with the right count; false if the get is not OK or Warning.
    bool read_all(Slot3& s, const std::vector<fmi3ValueReference>& vrs, size_t count, std::vector<double>* out,
                  const char* when) {
        out->assign(count, 0.0);
        trace(std::string("fmi3GetFloat64 (") + when + ")");
        const fmi3Status st = api().GetFloat64(s.c, vrs.data(), vrs.size(), out->data(), count);
        after(s, "fmi3GetFloat64", st, OnError::ErrorState);
        return st == fmi3OK || st == fmi3Warning;
    }

    static size_t first_difference(const std::vector<double>& a, const std::vector<double>& b) {
        for (size_t k = 0; k < a.size() && k < b.size(); ++k) {
            if (std::memcmp(&a[k], &b[k], sizeof(double)) != 0) return k;
        }
        return std::max(a.size(), b.size());
    }

    static std::string element_name(const UCVariable* v) { return v != nullptr ? std::string(" (") + v->name + ")" : " (time)"; }

    // Int32, Boolean and String: one value per value reference.
    void scalars(Slot3& s) {
        const UCVarType type = (UCVarType)integer(1, 3);
        const bool set = chance(0.6);
        const int n = integer(1, 3);
        std::vector<fmi3ValueReference> vrs(n);
        bool refused = false;
        std::vector<Pick> picks(n);
        for (int k = 0; k < n; ++k) {
            picks[k] = pick(type);
            picks[k].count = 1;
            vrs[k] = picks[k].vr;
            refused = refused || (set ? set_refused(picks[k], s) : get_refused(picks[k], s));
        }
        const bool mismatch = chance(0.12);
        const size_t nValues = mismatch ? wrong_count((size_t)n) : (size_t)n;
        const bool nullValues = chance(0.03);
        std::vector<fmi3Int32> ints(nValues);
        std::unique_ptr<fmi3Boolean[]> bools(new fmi3Boolean[nValues + 1]());
        std::vector<fmi3String> strings(nValues, nullptr);
        std::vector<std::string> texts(nValues);
        static const char* kNames[] = {"Float64", "Int32", "Boolean", "String"};
        const std::string function = std::string(set ? "fmi3Set" : "fmi3Get") + kNames[type];
        for (size_t k = 0; set && k < nValues; ++k) {
            const UCVariable* v = k < (size_t)n ? picks[k].v : nullptr;
            ints[k] = v != nullptr && v->type == UC_TYPE_INTEGER ? integer_value(*v) : integer(-3, 30);
            bools[k] = chance(0.5);
            const double r = uniform(0.0, 1.0);
            texts[k] = r < 0.4 ? s.deckPath : r < 0.6 ? "" : r < 0.8 ? "/nonexistent/deck.dat" : std::string(5000, 'x');
            strings[k] = texts[k].c_str();
        }
        trace(function + "(" + std::to_string(n) + " value references, " + std::to_string(nValues) + " values" +
              (nullValues ? ", values NULL)" : ")"));
        fmi3Status st;
        const fmi3ValueReference* vr = vrs.data();
        if (type == UC_TYPE_INTEGER) {
            st = set ? api().SetInt32(s.c, vr, n, nullValues ? nullptr : ints.data(), nValues)
                     : api().GetInt32(s.c, vr, n, nullValues ? nullptr : ints.data(), nValues);
        } else if (type == UC_TYPE_BOOLEAN) {
            st = set ? api().SetBoolean(s.c, vr, n, nullValues ? nullptr : bools.get(), nValues)
                     : api().GetBoolean(s.c, vr, n, nullValues ? nullptr : bools.get(), nValues);
        } else {
            st = set ? api().SetString(s.c, vr, n, nullValues ? nullptr : strings.data(), nValues)
                     : api().GetString(s.c, vr, n, nullValues ? nullptr : strings.data(), nValues);
        }
        // A string longer than its String variable holds is refused.
        bool tooLong = false;
        for (size_t k = 0; k < (size_t)n && k < nValues; ++k) {
            const UCVariable* v = picks[k].v;
            tooLong = tooLong || (picks[k].kind == Kind::Variable && v->type == UC_TYPE_STRING && texts[k].size() >= v->size);
        }
        const OnError onError = set ? OnError::ErrorState : mismatch ? OnError::Unchanged : OnError::Unknown;
        after(s, function.c_str(), st, onError, mismatch || nullValues || refused || (set && type == UC_TYPE_STRING && tooLong));
    }

    // ---- directional derivatives ---------------------------------------------------------------------
    void derivative(Slot3& s) {
        const int shape = integer(0, 2);  // scalars, body arrays, or both mixed (wrong)
        const std::vector<fmi3ValueReference>& unknownsFrom = shape == 0 ? scalarUnknowns_ : arrayUnknowns_;
        const std::vector<fmi3ValueReference>& knownsFrom = shape == 1 ? arrayKnowns_ : scalarKnowns_;
        if (unknownsFrom.empty() || knownsFrom.empty()) return;
        const size_t n = shape == 1 ? 4 : 1;
        std::vector<fmi3ValueReference> unknowns(integer(1, 3)), knowns(integer(1, 4));
        for (auto& u : unknowns) u = unknownsFrom[integer(0, (int)unknownsFrom.size() - 1)];
        for (auto& k : knowns) k = knownsFrom[integer(0, (int)knownsFrom.size() - 1)];
        const bool wrongCounts = chance(0.25);
        const size_t nSeed = wrongCounts && chance(0.5) ? wrong_count(knowns.size() * n) : knowns.size() * n;
        const size_t nSensitivity = wrongCounts && nSeed == knowns.size() * n ? wrong_count(unknowns.size() * n)
                                                                               : unknowns.size() * n;
        std::vector<double> seed(nSeed), sensitivity(nSensitivity);
        for (double& x : seed) x = chance(0.1) ? hostile_double() : (chance(0.5) ? 1.0 : 0.0);
        const bool nullArray = chance(0.02);
        trace("fmi3GetDirectionalDerivative(" + std::to_string(unknowns.size()) + " unknowns, " +
              std::to_string(knowns.size()) + " knowns, " + std::to_string(nSeed) + " seeds, " +
              std::to_string(nSensitivity) + " sensitivities" + (shape == 2 ? ", scalars and arrays mixed" : "") +
              (nullArray ? ", seed NULL)" : ")"));
        const fmi3Status st = api().GetDirectionalDerivative(s.c, unknowns.data(), unknowns.size(), knowns.data(),
                                                             knowns.size(), nullArray ? nullptr : seed.data(), nSeed,
                                                             sensitivity.data(), nSensitivity);
        const bool wrong = wrongCounts || shape == 2 || nullArray;
        after(s, "fmi3GetDirectionalDerivative", st, wrong ? OnError::Unchanged : OnError::Unknown, wrong);
    }

    // ---- FMU states ----------------------------------------------------------------------------------
    void restored(Slot3& s, fmi3Status st, Phase phase) {
        if (st != fmi3OK) return;
        s.phase = phase;
        double t = 0.0;
        const fmi3ValueReference timeVr = UC_FMI3_TIME_VR;
        trace("fmi3GetFloat64(time)");
        const fmi3Status got = api().GetFloat64(s.c, &timeVr, 1, &t, 1);
        if (got != fmi3OK) violation("time cannot be read after a restore", s);
        after(s, "fmi3GetFloat64(time)", got, OnError::Unknown);
        s.time = t;
    }

    void get_state(Slot3& s) {
        trace("fmi3GetFMUState");
        fmi3FMUState st = nullptr;
        const bool reuse = !s.states.empty() && chance(0.3);
        const size_t which = reuse ? (size_t)integer(0, (int)s.states.size() - 1) : 0;
        const Phase phase = s.phase;
        const fmi3Status status = api().GetFMUState(s.c, reuse ? &s.states[which] : &st);
        if (reuse && status == fmi3OK) {
            s.stateDecks[which] = s.deckText;
            s.statePhases[which] = phase;
        }
        if (!reuse && st != nullptr) {
            if (s.states.size() >= 4) {
                api().FreeFMUState(s.c, &s.states.front());
                s.states.erase(s.states.begin());
                s.statePhases.erase(s.statePhases.begin());
                s.stateDecks.erase(s.stateDecks.begin());
            }
            s.states.push_back(st);
            s.statePhases.push_back(phase);
            s.stateDecks.push_back(s.deckText);
        }
        after(s, "fmi3GetFMUState", status, OnError::ErrorState);
    }

    void set_state(Slot3& s) {
        const bool null = s.states.empty() || chance(0.03);
        const int which = null ? -1 : integer(0, (int)s.states.size() - 1);
        trace(null ? "fmi3SetFMUState(NULL)" : "fmi3SetFMUState");
        const fmi3Status st = api().SetFMUState(s.c, null ? nullptr : s.states[which]);
        after(s, "fmi3SetFMUState", st, null ? OnError::Unchanged : OnError::Unknown, null);
        if (!null) restored(s, st, s.statePhases[which]);
    }

    void free_state(Slot3& s) {
        if (s.states.empty()) return;
        const int k = integer(0, (int)s.states.size() - 1);
        trace("fmi3FreeFMUState");
        after(s, "fmi3FreeFMUState", api().FreeFMUState(s.c, &s.states[k]), OnError::ErrorState);
        if (s.states[k] == nullptr) {
            s.states.erase(s.states.begin() + k);
            s.statePhases.erase(s.statePhases.begin() + k);
            s.stateDecks.erase(s.stateDecks.begin() + k);
        }
    }

    void serialize(Slot3& s) {
        if (s.states.empty()) return;
        const int which = integer(0, (int)s.states.size() - 1);
        const fmi3FMUState st = s.states[which];
        size_t size = 0;
        trace("fmi3SerializedFMUStateSize");
        const fmi3Status sizeStatus = api().SerializedFMUStateSize(s.c, st, &size);
        after(s, "fmi3SerializedFMUStateSize", sizeStatus, OnError::ErrorState);
        if (sizeStatus != fmi3OK || size > (1u << 26)) return;
        std::vector<fmi3Byte> bytes(size);
        const bool small = chance(0.05) && size > 0;
        trace(small ? "fmi3SerializeFMUState (a buffer half the size)" : "fmi3SerializeFMUState");
        const fmi3Status serStatus = api().SerializeFMUState(s.c, st, bytes.data(), small ? size / 2 : size);
        after(s, "fmi3SerializeFMUState", serStatus, OnError::ErrorState, small);
        if (serStatus != fmi3OK) return;
        const double r = uniform(0.0, 1.0);
        std::string what = "intact";
        bool mustFail = false;
        if (r < 0.25) {
            const int flips = integer(1, 8);
            for (int k = 0; k < flips; ++k) bytes[integer(0, (int)bytes.size() - 1)] ^= (fmi3Byte)integer(1, 255);
            what = "bytes flipped";
        } else if (r < 0.37) {
            bytes.resize(integer(0, (int)bytes.size() - 1));
            what = "truncated";
            mustFail = true;
        } else if (r < 0.42) {
            bytes.resize(bytes.size() + integer(1, 64), (fmi3Byte)integer(0, 255));
            what = "extended";
            mustFail = true;
        } else if (r < 0.52) {
            if (bytes.size() >= 16) {
                const double h = hostile_double();
                std::memcpy(&bytes[integer(0, (int)bytes.size() - 8)], &h, sizeof h);
            }
            what = "hostile double";
        }
        Slot3& target = slot();  // possibly another instance (states are self-contained)
        if (target.c == nullptr) return;
        fmi3FMUState state = nullptr;
        trace("fmi3DeserializeFMUState (" + what + ")");
        const fmi3Status ds = api().DeserializeFMUState(target.c, bytes.empty() ? nullptr : bytes.data(), bytes.size(),
                                                        &state);
        after(target, "fmi3DeserializeFMUState", ds, OnError::Unchanged, mustFail);
        if (ds != fmi3OK || state == nullptr) return;
        if (chance(0.7)) {
            trace("fmi3SetFMUState (deserialized, " + what + ")");
            const fmi3Status set = api().SetFMUState(target.c, state);
            after(target, "fmi3SetFMUState", set, OnError::Unknown);
            restored(target, set, what == "intact" ? s.statePhases[which] : Phase::Unknown);
        }
        trace("fmi3FreeFMUState (deserialized)");
        after(target, "fmi3FreeFMUState", api().FreeFMUState(target.c, &state), OnError::ErrorState);
    }

    // ---- what the FMU does not provide ---------------------------------------------------------------
    void not_provided(Slot3& s) {
        const fmi3ValueReference vr[2] = {1, 2};
        double d[8] = {0};
        float f[2] = {0};
        fmi3Int64 i64[2] = {1, 2};
        fmi3UInt8 u8[2] = {0};
        fmi3Int32 orders[2] = {1, 1};
        fmi3Boolean b[6] = {false};
        fmi3Clock clocks[2] = {false};
        size_t sizes[2] = {0}, count = 0;
        fmi3Binary binaries[2] = {nullptr};
        const int which = integer(0, 12);
        static const char* kNames[] = {"fmi3EnterEventMode",    "fmi3EnterStepMode",   "fmi3EnterConfigurationMode",
                                       "fmi3GetFloat32",        "fmi3SetInt64",        "fmi3GetUInt8",
                                       "fmi3GetBinary",         "fmi3GetClock",        "fmi3GetNumberOfContinuousStates",
                                       "fmi3GetOutputDerivatives", "fmi3GetAdjointDerivative", "fmi3SetTime",
                                       "fmi3UpdateDiscreteStates"};
        trace(std::string(kNames[which]) + " (not provided)");
        fmi3Status st = fmi3OK;
        switch (which) {
            case 0: st = api().EnterEventMode(s.c); break;
            case 1: st = api().EnterStepMode(s.c); break;
            case 2: {  // provided where the structural parameters are set: legal in the instantiated state only
                const bool legal = s.phase == Phase::Instantiated;
                st = api().EnterConfigurationMode(s.c);
                if (!legal && s.phase != Phase::Unknown) break;  // a wrong call: checked below
                after(s, kNames[which], st, OnError::Unchanged);
                if (legal && st != fmi3OK) violation("fmi3EnterConfigurationMode refused in the instantiated state", s);
                if (st == fmi3OK) {
                    trace("fmi3ExitConfigurationMode");
                    const fmi3Status out = api().ExitConfigurationMode(s.c);
                    after(s, "fmi3ExitConfigurationMode", out, OnError::ErrorState);
                    if (out != fmi3OK) violation("fmi3ExitConfigurationMode refused after fmi3EnterConfigurationMode", s);
                }
                return;
            }
            case 3: st = api().GetFloat32(s.c, vr, 2, f, 2); break;
            case 4: st = api().SetInt64(s.c, vr, 2, i64, 2); break;
            case 5: st = api().GetUInt8(s.c, vr, 2, u8, 2); break;
            case 6: st = api().GetBinary(s.c, vr, 2, sizes, binaries, 2); break;
            case 7: st = api().GetClock(s.c, vr, 2, clocks); break;
            case 8: st = api().GetNumberOfContinuousStates(s.c, &count); break;
            case 9: st = api().GetOutputDerivatives(s.c, vr, 2, orders, d, 2); break;
            case 10: st = api().GetAdjointDerivative(s.c, vr, 1, vr + 1, 1, d, 1, d + 1, 1); break;
            case 11: st = api().SetTime(s.c, uniform(0.0, 10.0)); break;
            default: st = api().UpdateDiscreteStates(s.c, b, b + 1, b + 2, b + 3, b + 4, d); break;
        }
        after(s, kNames[which], st, OnError::Unchanged, true);
    }

    // ---- one random call -----------------------------------------------------------------------------
    void one_call() override {
        Slot3& s = slot();
        if (s.c == nullptr || chance(0.002)) {
            instantiate(s);
            return;
        }
        if (chance(0.5) && progress(s)) return;
        if (!s.deckText.empty() && chance(0.01)) {  // the instance's deck file edited under its states
            write_deck(s, mutated_deck(s.deckText));
            ++deckEdits_;
            return;
        }
        const int action = integer(0, 99);
        char buf[200];
        if (action < 4) {
            const double start = chance(0.9) ? uniform(0.0, 10.0) : hostile_double();
            const double stop = chance(0.8) ? start + uniform(0.0, 1e4) : hostile_double();
            const bool stopDefined = chance(0.7);
            std::snprintf(buf, sizeof buf, "fmi3EnterInitializationMode(start %g, stop %g defined %d)", start, stop,
                          (int)stopDefined);
            trace(buf);
            const Phase phase = s.phase;
            const fmi3Status st =
                api().EnterInitializationMode(s.c, chance(0.5), uniform(-1.0, 1.0), start, stopDefined, stop);
            after(s, "fmi3EnterInitializationMode", st, OnError::ErrorState,
                  phase == Phase::Init || phase == Phase::Stepping || phase == Phase::Terminated || phase == Phase::Error);
            if (st == fmi3OK) {
                s.phase = Phase::Init;
                s.time = start;
            }
        } else if (action < 8) {
            trace("fmi3ExitInitializationMode");
            const Phase phase = s.phase;
            const fmi3Status st = api().ExitInitializationMode(s.c);
            after(s, "fmi3ExitInitializationMode", st, OnError::ErrorState,
                  phase == Phase::Instantiated || phase == Phase::Stepping || phase == Phase::Terminated ||
                      phase == Phase::Error);
            if (st == fmi3OK) s.phase = Phase::Stepping;
        } else if (action < 20) {
            set_float64(s);
        } else if (action < 28) {
            arrays(s);
        } else if (action < 38) {
            get_float64(s);
        } else if (action < 44) {
            scalars(s);
        } else if (action < 60) {
            const double h = step_size();
            const double tc = chance(0.93) ? s.time : (chance(0.5) ? s.time + uniform(-2.0, 2.0) : hostile_double());
            do_step(s, tc, h, chance(0.03), "");
        } else if (action < 64) {
            derivative(s);
        } else if (action < 70) {
            get_state(s);
        } else if (action < 76) {
            set_state(s);
        } else if (action < 78) {
            free_state(s);
        } else if (action < 84) {
            serialize(s);
        } else if (action < 87) {
            not_provided(s);
        } else if (action < 90) {
            trace("fmi3Terminate");
            const Phase phase = s.phase;
            const fmi3Status st = api().Terminate(s.c);
            after(s, "fmi3Terminate", st, OnError::ErrorState,
                  phase == Phase::Instantiated || phase == Phase::Init || phase == Phase::Terminated ||
                      phase == Phase::Error);
            if (st == fmi3OK) s.phase = Phase::Terminated;
        } else if (action < 93) {
            reset(s, "fmi3Reset");
        } else if (action < 95) {
            static const fmi3String kCategories[] = {"logEvents", "logStatusError", "logSolver", "logAll", "bogus%s"};
            const size_t n = (size_t)integer(0, 5);
            trace("fmi3SetDebugLogging");
            after(s, "fmi3SetDebugLogging", api().SetDebugLogging(s.c, chance(0.5), n, n ? kCategories : nullptr),
                  OnError::ErrorState);
        } else {
            free_slot(s);
        }
    }

    std::string token_;
    std::vector<Var3> vars_;
    std::vector<const UCVariable*> elements_;  // FMI 2.0 scalars of arrays beyond their first element
    std::map<int, std::vector<size_t>> byType_, inputsByType_;  // indices into vars_
    std::vector<fmi3ValueReference> outputVrs_;
    size_t outputElements_ = 0;
    std::vector<fmi3ValueReference> scalarUnknowns_, scalarKnowns_, arrayUnknowns_, arrayKnowns_;
    std::vector<size_t> arrayInputs_, arrayOutputs_, realScalars_;  // indices into vars_ (Float64 only)
    fmi3ValueReference lineFileVr_ = 0;
    Slot3 slots_[3];
    long long wrongCalls_ = 0, readBacks_ = 0, deckInstances_ = 0, deckMutated_ = 0, deckEdits_ = 0;
    long long arrayCalls_ = 0, arrayRefusedReadBacks_ = 0, arrayAcceptedReadBacks_ = 0, arrayRefusedGets_ = 0;
};

// ---- regressions: the fuzzer's findings, minimised to fixed call sequences ------------------------------

// One fresh instance in initialization mode (the single line of the default parameters), its log captured.
struct Regression {
    LogCapture log;
    fmi3Instance c = nullptr;
    Regression() {
        const std::string token = fmi3_token();
        c = fmi3().InstantiateCoSimulation("regression", token.c_str(), nullptr, false, true, false, false, nullptr, 0,
                                           &log, capture3, nullptr);
        if (c != nullptr) fmi3().EnterInitializationMode(c, false, 0.0, 0.0, false, 0.0);
        log.lines.clear();
    }
    ~Regression() {
        if (c != nullptr) fmi3().FreeInstance(c);
    }
    Regression(const Regression&) = delete;
    Regression& operator=(const Regression&) = delete;
};

// ---- arrays: fixed call sequences of the arrays checks (the fuzzer's arrays() draws them at random) ----------

// The FMI 3.0 arrays body.q0 (stride 4), point.vz (UC_MAX_POINTS, stride 3) and the scalar tow.x, in one call, with the
// FMI 2.0 value reference of each element by its name (body[k].q0, point[k].vz): independent of the stride
// table the adapter expands arrays with (the elements after the first read as scalars, as the FMI 2.0
// adapter knows them).
struct ArraysCall {
    std::vector<fmi3ValueReference> vrs = {vr_of("body[1].q0"), vr_of("tow.x"), vr_of("point[1].vz")};
    std::vector<fmi3ValueReference> elements;
    std::vector<double> values;
    ArraysCall() {
        for (int k = 1; k <= UC_MAX_BODIES; ++k) elements.push_back(vr_of("body[" + std::to_string(k) + "].q0"));
        elements.push_back(vr_of("tow.x"));
        for (int k = 1; k <= UC_MAX_POINTS; ++k) elements.push_back(vr_of("point[" + std::to_string(k) + "].vz"));
        for (size_t k = 0; k < elements.size(); ++k) values.push_back(0.25 + 0.125 * (double)k);
    }
};

// "" if every element reads (as an array and by its element's value reference) bit for bit as `expected`.
std::string arrays_read_as(const Regression& r, const ArraysCall& a, const std::vector<double>& expected) {
    std::vector<double> got(expected.size(), 0.0), each(expected.size(), 0.0);
    const fmi3Status st = fmi3().GetFloat64(r.c, a.vrs.data(), a.vrs.size(), got.data(), got.size());
    if (st != fmi3OK) return std::string("reading the arrays returned ") + status_name(st);
    for (size_t k = 0; k < expected.size(); ++k) {
        // An array's first element has the array's value reference: it reads as the array, above.
        const bool first = std::find(a.vrs.begin(), a.vrs.end(), a.elements[k]) != a.vrs.end();
        if (first) {
            each[k] = got[k];
        } else if (fmi3().GetFloat64(r.c, &a.elements[k], 1, &each[k], 1) != fmi3OK) {
            return "element " + std::to_string(k) + " does not read by its value reference";
        }
        if (std::memcmp(&got[k], &expected[k], sizeof(double)) != 0 ||
            std::memcmp(&each[k], &expected[k], sizeof(double)) != 0) {
            return "element " + std::to_string(k) + " reads " + std::to_string(got[k]) + " as an array and " +
                   std::to_string(each[k]) + " by its value reference, " + std::to_string(expected[k]) + " expected";
        }
    }
    return "";
}

// Sets the arrays (accepted, checked), then makes `refused` if given (which must return fmi3Error with a
// message) and checks that every element still reads as set.
std::string refused_arrays_call(fmi3Status (*refused)(const Regression&, const ArraysCall&)) {
    Regression r;
    const ArraysCall a;
    if (r.c == nullptr) return "no instance";
    const fmi3Status set = fmi3().SetFloat64(r.c, a.vrs.data(), a.vrs.size(), a.values.data(), a.values.size());
    if (set != fmi3OK) return std::string("the right call returned ") + status_name(set);
    const std::string accepted = arrays_read_as(r, a, a.values);
    if (!accepted.empty()) return "after the accepted set: " + accepted;
    if (refused == nullptr) return "";
    r.log.lines.clear();
    const fmi3Status st = refused(r, a);
    if (st != fmi3Error) return std::string("the wrong call returned ") + status_name(st);
    if (r.log.lines.empty()) return "refused without a log message";
    const std::string unchanged = arrays_read_as(r, a, a.values);
    return unchanged.empty() ? "" : "after the refused set: " + unchanged;
}

// Each case: a name and a check that returns "" when the FMU behaves, else what it did.
int run_fmi3_regressions() {
    const std::vector<std::pair<const char*, std::string (*)()>> cases = {
        {"fmi3GetBoolean with values NULL is refused (it wrote through the NULL pointer)",
         []() -> std::string {
             Regression r;
             const fmi3ValueReference vr = vr_of("enableCompression");
             if (r.c == nullptr) return "no instance";
             const fmi3Status st = fmi3().GetBoolean(r.c, &vr, 1, nullptr, 1);
             if (st != fmi3Error) return std::string("returned ") + status_name(st);
             return r.log.lines.empty() ? "refused without a log message" : "";
         }},
        {"fmi3SetFloat64 of arrays mixed with a scalar lands element by element (by the elements' own value references)",
         []() -> std::string { return refused_arrays_call(nullptr); }},
        {"fmi3SetFloat64 one value short (the last array cut) is refused and changes no element",
         []() -> std::string {
             return refused_arrays_call([](const Regression& r, const ArraysCall& a) {
                 std::vector<double> v(a.values.size() - 1, 7.5);
                 return fmi3().SetFloat64(r.c, a.vrs.data(), a.vrs.size(), v.data(), v.size());
             });
         }},
        {"fmi3SetFloat64 of arrays with NaN as the last element is refused and changes no element",
         []() -> std::string {
             return refused_arrays_call([](const Regression& r, const ArraysCall& a) {
                 std::vector<double> v(a.values.size(), 7.5);
                 v.back() = std::nan("");
                 return fmi3().SetFloat64(r.c, a.vrs.data(), a.vrs.size(), v.data(), v.size());
             });
         }},
        {"fmi3SetFloat64 of arrays with an output array last is refused and changes no element",
         []() -> std::string {
             return refused_arrays_call([](const Regression& r, const ArraysCall& a) {
                 std::vector<fmi3ValueReference> vrs = a.vrs;
                 vrs.push_back(vr_of("body[1].force.x"));  // body.force.x [4], an output
                 std::vector<double> v(a.values.size() + 4, 7.5);
                 return fmi3().SetFloat64(r.c, vrs.data(), vrs.size(), v.data(), v.size());
             });
         }},
        {"fmi3GetFloat64 of arrays one value short is refused and writes nothing",
         []() -> std::string {
             Regression r;
             const ArraysCall a;
             if (r.c == nullptr) return "no instance";
             std::vector<double> v(a.values.size() - 1, 7.5);
             const fmi3Status st = fmi3().GetFloat64(r.c, a.vrs.data(), a.vrs.size(), v.data(), v.size());
             if (st != fmi3Error) return std::string("returned ") + status_name(st);
             for (const double x : v) {
                 if (x != 7.5) return "wrote into the array";
             }
             return r.log.lines.empty() ? "refused without a log message" : "";
         }},
    };
    int failures = 0;
    for (const auto& [name, check] : cases) {
        const std::string what = check();
        std::printf("%s: %s%s\n", what.empty() ? "ok" : "FAILED", name, what.empty() ? "" : (": " + what).c_str());
        failures += !what.empty();
    }
    std::printf("fuzz_fmi: %zu FMI 3.0 regressions, %d failed\n", cases.size(), failures);
    return failures == 0 ? 0 : 1;
}

}  // namespace

int run_fmi3_fuzz(const Options& options) {
    try {
        fmi3();
        if (options.regressions) return run_fmi3_regressions();
        return Fmi3Fuzzer(options).run();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_fmi: %s\n", e.what());
        return 2;
    }
}
