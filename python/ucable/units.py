"""Units and constants the package, its studies and its tests share: each defined here once.

GRAVITY and WATER_DENSITY are the FMU's defaults of `gravity` and `waterDensity` (schema/variables.toml);
STANDARD_GRAVITY is what MoorDyn (and so the FMU's deck reader, `lineFile`) takes when a deck sets no g.
"""

NAUTICAL_MILE = 1852.0            # [m]
HOUR = 3600.0                     # [s]
KNOT = NAUTICAL_MILE / HOUR       # [m/s]
GRAVITY = 9.81                    # [m/s2]
STANDARD_GRAVITY = 9.80665        # [m/s2]
WATER_DENSITY = 1025.0            # [kg/m3]
