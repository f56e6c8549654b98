// fuzz_common.h - what the FMI 2.0 and the FMI 3.0 fuzzers share (tests/fmu/fuzz_fmi.cpp,
// tests/fmu/fuzz_fmi3.cpp): the options, the seeded random values (hostile and plausible, by the FMI 2.0
// variable they go to), the decks of deck mode and their mutation, the tally of statuses and violations,
// and the run loop.
#ifndef UNDERWATERCABLE_TESTS_FMU_FUZZ_COMMON_H
#define UNDERWATERCABLE_TESTS_FMU_FUZZ_COMMON_H

#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "fmu_harness.h"
#include "variables.h"

namespace uc_fuzz {

struct Options {
    long long calls = 100000;
    uint64_t seed = 1;
    double seconds = 1e30;
    bool trace = false;
    bool fmi3 = false;               // the FMI 3.0 variant (fuzz_fmi3.cpp)
    bool regressions = false;        // --fmi3 --regressions: the fixed sequences of past findings instead
    std::vector<std::string> decks;  // deck mode when not empty
};

// The decks of deck mode by default: the project's mooring-system and line decks and the OC4 scene.
inline std::vector<std::string> default_decks() {
    const std::string data = UC_TEST_DATA_DIR "/decks/";
    return {data + "platform_buoy_leg.dat", data + "subsurface_buoy_body.dat", data + "subsurface_buoy.dat",
            data + "clump_weight.dat",      data + "chain_wire_chain.dat",     data + "clump_on_seabed.dat",
            data + "chain.dat",             UC_SCENES_DIR "/oc4_semi.dat"};
}

inline std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

class FuzzBase {
public:
    explicit FuzzBase(const Options& o) : opt_(o), rng_(o.seed) {
        for (const std::string& path : opt_.decks) {
            deckTexts_.push_back(read_text(path));
            if (deckTexts_.back().empty()) std::fprintf(stderr, "fuzz_fmi: deck %s is empty or unreadable\n", path.c_str());
        }
    }
    virtual ~FuzzBase() = default;

    // Random actions until --calls FMI calls or --seconds; a summary on stdout; 0 without a violation.
    int run() {
        const auto start = std::chrono::steady_clock::now();
        long long i = 0;
        for (; calls_ < opt_.calls; ++i) {
            if ((i & 255) == 0) {
                const double elapsed =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                if (elapsed > opt_.seconds) break;
                if ((i & 16383) == 0 && i > 0) {
                    std::fprintf(stderr, "fuzz_fmi: %lld FMI calls (%lld random actions), %.1f s, %d violations\n",
                                 calls_, i, elapsed, violations_);
                }
            }
            one_call();
        }
        free_all();
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("fuzz_fmi: seed %" PRIu64 ": %lld FMI calls in %.1f s, %d invariant violations\n", opt_.seed,
                    calls_, elapsed, violations_);
        std::printf("status counts: OK %lld, Warning %lld, Discard %lld, Error %lld, other %lld; "
                    "successful steps %lld\n",
                    status_[0], status_[1], status_[2], status_[3], status_[4], okSteps_);
        for (const auto& [name, count] : perFunction_) std::printf("  %-30s %lld\n", name.c_str(), count);
        print_extra();
        return violations_ == 0 ? 0 : 1;
    }

protected:
    virtual void one_call() = 0;
    virtual void free_all() = 0;
    virtual void print_extra() {}

    // ---- random values ------------------------------------------------------------------------------
    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
    int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng_); }
    bool chance(double p) { return uniform(0.0, 1.0) < p; }

    double hostile_double() {
        static const double kSpecial[] = {std::nan(""),
                                          -std::nan(""),
                                          std::numeric_limits<double>::infinity(),
                                          -std::numeric_limits<double>::infinity(),
                                          std::numeric_limits<double>::max(),
                                          -std::numeric_limits<double>::max(),
                                          std::numeric_limits<double>::denorm_min(),
                                          std::numeric_limits<double>::min(),
                                          0.0,
                                          -0.0,
                                          1e300,
                                          -1e300,
                                          1e-300,
                                          -1.0,
                                          1e12};
        return kSpecial[integer(0, sizeof kSpecial / sizeof kSpecial[0] - 1)];
    }

    // A plausible value for a variable: around its default, within physical magnitudes.
    double plausible(const UCVariable& v) {
        const std::string name = v.name;
        if (v.causality == UC_CAUSALITY_INPUT) {
            if (name.rfind("tow.v", 0) == 0) return uniform(-3.0, 3.0);
            if (name.rfind("tow.", 0) == 0) return uniform(-50.0, 50.0);
            if (name.rfind("current", 0) == 0) return uniform(-1.5, 1.5);
            if (name == "winch.rate") return uniform(-3.0, 3.0);
            if (name == "winch.tension") return uniform(0.0, 3e4);
            if (name.rfind("body[", 0) == 0 || name.rfind("point[", 0) == 0) {
                const std::string member = name.substr(name.find("].") + 2);
                if (member == "x" || member == "y" || member == "z") return uniform(-10.0, 10.0);
                if (member == "roll" || member == "pitch" || member == "yaw") return uniform(-0.2, 0.2);
                if (member[0] == 'q') return member == "q0" ? uniform(0.98, 1.0) : uniform(-0.1, 0.1);
                if (member[0] == 'w') return uniform(-0.1, 0.1);
                return uniform(-2.0, 2.0);  // velocities
            }
            return uniform(-2e3, 2e3);  // endLoad, endCouple, ...
        }
        // A section's or an attachment's member: the same magnitudes as the line's own.
        const size_t dot = name.find("].");
        const std::string member = dot == std::string::npos ? name : name.substr(dot + 2);
        if (name.rfind("attachment[", 0) == 0) {
            if (member == "s") return uniform(0.0, 400.0);
            if (member == "mass" || member == "addedMass") return uniform(0.0, 2000.0);
            return uniform(0.0, 2.0);
        }
        if (name.rfind("section[", 0) == 0) {
            if (member == "length") return uniform(5.0, 200.0);
            if (member == "diameter") return uniform(0.005, 0.1);
            if (member == "EA") return std::pow(10.0, uniform(4.0, 10.0));
            if (member == "EI" || member == "GJ") return std::pow(10.0, uniform(-2.0, 5.0));
            if (member == "massPerLength") return uniform(0.1, 20.0);
            if (member == "axialDamping") return std::pow(10.0, uniform(2.0, 7.0));
            return uniform(0.0, 3.0);
        }
        if (name == "waves.period") return uniform(2.0, 15.0);
        if (name == "waves.height") return uniform(0.0, 5.0);
        if (name == "waves.direction") return uniform(-4.0, 4.0);
        if (name == "waves.rampTime") return uniform(0.0, 20.0);
        if (name == "waves.gamma") return uniform(1.0, 7.0);
        if (name == "waterDepth") return uniform(10.0, 1000.0);
        if (name == "winch.minLength") return uniform(1.0, 100.0);
        if (name == "winch.maxLength") return uniform(100.0, 800.0);
        if (name == "winch.timeConstant") return std::pow(10.0, uniform(-3.0, 0.5));
        if (name == "length") return uniform(5.0, 400.0);
        if (name == "diameter") return uniform(0.005, 0.1);
        if (name == "EA") return std::pow(10.0, uniform(4.0, 10.0));
        if (name == "EI") return std::pow(10.0, uniform(-2.0, 5.0));
        if (name == "relTol") return std::pow(10.0, uniform(-10.0, -3.0));
        if (name == "absTol") return std::pow(10.0, uniform(-9.0, -3.0));
        if (name == "massPerLength") return uniform(0.1, 20.0);
        if (name.find("Direction") != std::string::npos || name.find("Tangent") != std::string::npos) {
            return uniform(-1.0, 1.0);
        }
        if (name.rfind("anchor", 0) == 0) return uniform(-300.0, 300.0);
        if (name.rfind("body.", 0) == 0) return uniform(0.0, 2000.0);
        if (name == "axialDamping") return std::pow(10.0, uniform(2.0, 7.0));
        return uniform(0.0, 3.0);  // coefficients, densities scaled down still positive
    }

    double real_value(const UCVariable& v) {
        const double r = uniform(0.0, 1.0);
        if (r < 0.15) return hostile_double();
        if (r < 0.25) return -plausible(v);
        return plausible(v);
    }

    int integer_value(const UCVariable& v) {
        const std::string name = v.name;
        const double r = uniform(0.0, 1.0);
        if (r < 0.1) {
            static const int kSpecial[] = {std::numeric_limits<int>::min(), std::numeric_limits<int>::max(), -1, 0,
                                           1001, 1 << 20};
            return kSpecial[integer(0, 5)];
        }
        if (name == "nElements") return integer(1, 24);
        if (name == "nSections") return integer(1, 4);
        if (name == "nAttachments") return integer(0, 3);
        if (name == "waves.mode") return integer(0, 2);
        if (name == "waves.nComponents") return integer(1, 300);
        if (name == "waves.seed") return integer(0, 1 << 30);
        if (name.rfind("section[", 0) == 0 && name.find(".nElements") != std::string::npos) return integer(1, 12);
        return integer(0, 3);
    }

    double step_size() {
        const double r = uniform(0.0, 1.0);
        if (r < 0.05) return hostile_double();
        if (r < 0.6) return 0.5;
        if (r < 0.9) return std::pow(10.0, uniform(-6.0, 0.7));
        return uniform(-1.0, 20.0);
    }

    // ---- deck mode -----------------------------------------------------------------------------------
    // text with one number of a data row (a row starting with a digit) scaled, negated or zeroed.
    std::string mutated_deck(const std::string& text) {
        std::vector<size_t> starts;  // of the numbers after a row's first field
        size_t row = 0;
        while (row < text.size()) {
            const size_t end = std::min(text.find('\n', row), text.size());
            if (std::isdigit(static_cast<unsigned char>(text[row]))) {
                for (size_t i = row + 1; i < end; ++i) {
                    const unsigned char c = static_cast<unsigned char>(text[i]);
                    const unsigned char before = static_cast<unsigned char>(text[i - 1]);
                    if ((std::isdigit(c) || c == '-') && (before == ' ' || before == '\t' || before == '|')) starts.push_back(i);
                }
            }
            row = end + 1;
        }
        if (starts.empty()) return text;
        const size_t at = starts[integer(0, (int)starts.size() - 1)];
        size_t end = at;
        while (end < text.size() && std::strchr("0123456789.eE+-", text[end]) != nullptr) ++end;
        const double value = std::atof(text.substr(at, end - at).c_str());
        static const double kFactors[] = {0.0, -1.0, 0.5, 2.0, 1.01, 1e-6, 1e6};
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.9g", value * kFactors[integer(0, 6)] + (chance(0.2) ? 10.0 : 0.0));
        return text.substr(0, at) + buf + text.substr(end);
    }


    // ---- bookkeeping ---------------------------------------------------------------------------------
    void trace(const std::string& call) {
        last_ = call;
        if (opt_.trace) {
            std::fprintf(stderr, "%lld %s\n", calls_, call.c_str());
            std::fflush(stderr);
        }
    }

    void violation(const char* what, const LogCapture& log, const std::string& call) {
        ++violations_;
        std::printf("VIOLATION after call %lld (%s): %s\n%s", calls_, call.c_str(), what, log.all().c_str());
    }

    // Counts a call of `function` and its status (0..3 OK, Warning, Discard, Error; anything else: 4).
    int tally(const char* function, int status) {
        ++calls_;
        ++perFunction_[function];
        const int k = (status >= 0 && status <= 3) ? status : 4;
        ++status_[k];
        return k;
    }

    Options opt_;
    std::mt19937_64 rng_;
    std::string last_;
    long long calls_ = 0, okSteps_ = 0;
    long long status_[5] = {0, 0, 0, 0, 0};
    int violations_ = 0;
    std::map<std::string, long long> perFunction_;
    std::vector<std::string> deckTexts_;  // deck mode
};

}  // namespace uc_fuzz

#endif  // UNDERWATERCABLE_TESTS_FMU_FUZZ_COMMON_H
