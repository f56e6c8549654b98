/* heave_waves_driver.c - the heave case of heave_driver.c in an irregular sea: JONSWAP Hs 3 m, Tp 10 s,
 * 200 components, seed 1, acting on the umbilical through the water (the top heave as in calm water),
 * for scripts/profile_callgrind --scenes heave_waves: the share of the wave kinematics in the residual. */
#define UC_PROFILE_WAVES 200
#include "heave_driver.c"
