// rainflow.h - streaming four-point rainflow counting with Miner's sum (docs/model.md, "Fatigue").
//
// Samples arrive one at a time (the tow tension after every integrator step). Turning points are
// kept on a small stack; whenever the last four turning points x1 x2 x3 x4 enclose an inner range
// |x3 - x2| no larger than both neighbouring ranges, that inner range is a closed cycle: it is
// counted and x2, x3 are removed (the four-point method, equivalent to ASTM E1049 rainflow for the
// closed cycles). What stays on the stack is the residue; its adjacent ranges count as half cycles,
// so the reported damage equals that of an offline rainflow count of the history so far.
//
// The state is a plain struct of fixed size (exact save/restore by copying it). A residue longer
// than its capacity (only for a history whose amplitude keeps growing for hundreds of reversals)
// counts its oldest range as a half cycle and drops it; the stack never reallocates.
//
// The struct is copied byte for byte into saved FMU states, which one platform may write and another
// read (docs/platforms.md): its fields are fixed-width types (no `long`, 8 bytes on Linux and 4 on
// Windows) in an order that leaves no padding, so its bytes are the same on every 64-bit platform.
#pragma once

#include <cstdint>

namespace uc {

// S-N curve N(S) = K S^-m with S the stress range in MPa (the convention of the offshore mooring
// T-N / S-N curves), S = tension range / area.
struct SNCurve {
    double m = 3.0;        // slope
    double logK = 11.0;    // log10 K
    double area = 0.0;     // [m2] area the tension range is divided by; 0: no fatigue counting
    // Damage of one full cycle of tension range dT [N].
    double cycle_damage(double tensionRange) const;
};

struct RainflowCounter {
    static constexpr int kCapacity = 128;
    double stack[kCapacity] = {};  // turning points, oldest first (the last one may still move)
    double last = 0.0;             // previous sample, and whether the signal was rising into it
    double closedDamage = 0.0;     // Miner's sum of the closed cycles
    double closedCycles = 0.0;
    std::int64_t samples = 0;
    std::int32_t size = 0;
    std::int32_t direction = 0;    // +1 rising, -1 falling, 0 no direction yet

    void add(double value, const SNCurve& curve);
    // Closed cycles plus the residue's half cycles: the offline count of the history so far.
    double damage(const SNCurve& curve) const;
    void reset() { *this = RainflowCounter{}; }

private:
    void push_turning_point(double value, const SNCurve& curve);
};

}  // namespace uc
